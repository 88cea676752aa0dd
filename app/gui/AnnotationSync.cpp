#include "AnnotationSync.h"

#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QTimer>

namespace stylos::app {

AnnotationSync::AnnotationSync(widgets::SceneDocument& document, widgets::ViewportWidget& viewport, QObject* parent)
    : QObject(parent), m_document(document), m_viewport(&viewport)
{
    using widgets::SceneDocument;
    connect(&document.labels(), &widgets::LabelStore::labelsChanged, this, &AnnotationSync::labelsChanged);
    connect(&document, &SceneDocument::legendChanged, this, [this] {
        m_legend = true;
        schedule();
    });
    connect(&document, &SceneDocument::sceneReset, this, &AnnotationSync::everything);
    connect(&document, &SceneDocument::fragmentRemoved, this, [this](quint64 id) {
        m_changes[core::scene::FragmentId(id)] = {true, 0, 0}; // no longer shown: its labels leave the GL
        schedule();
    });
    everything();
}

widgets::PointRenderer::ClassColours AnnotationSync::classColours(const core::annotation::Legend& legend, Layer layer)
{
    widgets::PointRenderer::ClassColours colours{};
    for (const core::annotation::LegendClass& c : legend.classes(layer))
        colours[c.id] = {c.colour.r, c.colour.g, c.colour.b, 255};
    return colours;
}

void AnnotationSync::setLayer(Layer layer)
{
    if (layer == m_layer) return;
    m_layer = layer;
    everything();
    Q_EMIT layerChanged(int(layer));
}

void AnnotationSync::everything()
{
    m_all = true;
    m_legend = true;
    m_changes.clear();
    schedule();
}

void AnnotationSync::labelsChanged(quint64 fragment, int layer, const std::vector<std::uint32_t>& leaves)
{
    if (layer != int(m_layer) || m_all) return;
    const auto id = core::scene::FragmentId(fragment);
    const auto it = m_changes.find(id);
    if (leaves.empty()) m_changes[id] = {true, 0, 0};
    else if (it == m_changes.end()) m_changes[id] = {false, leaves.front(), leaves.back()};
    else if (!it->second.whole)
        it->second = {false, std::min(it->second.first, leaves.front()), std::max(it->second.last, leaves.back())};
    schedule();
}

void AnnotationSync::schedule()
{
    if (m_scheduled) return;
    m_scheduled = true;
    QTimer::singleShot(0, this, &AnnotationSync::pushNow);
}

void AnnotationSync::pushNow()
{
    m_scheduled = false;
    if (!m_viewport) return;
    if (m_legend) m_viewport->setClassColours(classColours(m_document.legend(), m_layer));
    m_legend = false;
    const widgets::LabelStore& store = m_document.labels();
    auto pushWhole = [&](core::scene::FragmentId id) {
        const auto labels = store.labels(id, m_layer);
        if (labels && m_document.fragment(id)) m_viewport->setLabels(id, *labels);
        else m_viewport->clearLabels(id);
    };
    if (m_all) {
        m_viewport->clearAllLabels();
        for (const core::scene::Fragment& f : m_document.scene().fragments()) pushWhole(f.id);
    }
    for (const auto& [id, range] : m_changes) {
        const auto labels = store.labels(id, m_layer);
        if (range.whole || !labels || range.last >= labels->size() || !m_document.fragment(id)) {
            pushWhole(id);
            continue;
        }
        const std::span<const std::uint8_t> all(*labels);
        m_viewport->updateLabels(id, range.first, all.subspan(range.first, range.last - range.first + 1));
    }
    m_all = false;
    m_changes.clear();
}

} // namespace stylos::app
