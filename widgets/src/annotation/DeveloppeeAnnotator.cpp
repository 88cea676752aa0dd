// The développée's annotation overlay from the document's labels, and its painting into them.
#include "stylos/widgets/annotation/DeveloppeeAnnotator.h"

#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/annotation/LegendText.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/document/SceneDocument.h"

namespace stylos::widgets {

DeveloppeeAnnotator::DeveloppeeAnnotator(SceneDocument& document, DeveloppeeView& view, QObject* parent)
    : QObject(parent), m_document(document), m_view(&view)
{
    connect(&view, &DeveloppeeView::developpeeChanged, this, &DeveloppeeAnnotator::rebuild);
    connect(&view, &DeveloppeeView::strokeStarted, this, [this] { m_stroke = m_document.beginStroke(); });
    connect(&view, &DeveloppeeView::pixelsPainted, this, &DeveloppeeAnnotator::paint);
    connect(&view, &DeveloppeeView::strokeFinished, this, [this] { m_stroke = 0; });
    connect(&document.labels(), &LabelStore::labelsChanged, this, &DeveloppeeAnnotator::labelsChanged);
    connect(&document, &SceneDocument::legendChanged, this, &DeveloppeeAnnotator::legendChanged);
    connect(&document, &SceneDocument::sceneReset, this, &DeveloppeeAnnotator::rebuild);
    setActive(AnnotationLayer::Material, 0);
}

void DeveloppeeAnnotator::setActive(AnnotationLayer layer, std::uint8_t classId)
{
    const auto& classes = m_document.legend().classes(layer);
    if (!m_document.legend().find(layer, classId)) classId = classes.empty() ? 0 : classes.front().id;
    const bool layerChanged = layer != m_layer;
    if (!layerChanged && classId == m_class) return;
    m_layer = layer;
    m_class = classId;
    if (m_view) m_view->setActiveClass(classId);
    if (layerChanged) rebuild();
    Q_EMIT activeChanged(layer, classId);
}

std::shared_ptr<const std::vector<std::uint8_t>> DeveloppeeAnnotator::shownLabels() const
{
    if (!m_view || !m_view->leafIndex()) return nullptr;
    auto labels = m_document.labels().labels(m_view->fragmentId(), m_layer);
    if (!labels || labels->size() != m_view->leafIndex()->leafCount()) return nullptr;
    return labels;
}

void DeveloppeeAnnotator::rebuild()
{
    if (!m_view) return;
    const auto labels = shownLabels();
    if (!labels) {
        m_view->overlay().clear();
        m_view->overlayChanged();
        return;
    }
    const auto& index = *m_view->leafIndex();
    recolour();
    m_view->overlay().setIds(index.width(), index.height(), index.majorityLabels(*labels));
    m_view->overlayChanged();
}

void DeveloppeeAnnotator::recolour()
{
    LabelOverlay::Colours colours{};
    for (const auto& c : m_document.legend().classes(m_layer)) colours[c.id] = qRgb(c.colour.r, c.colour.g, c.colour.b);
    m_view->overlay().setColours(colours);
}

void DeveloppeeAnnotator::labelsChanged(quint64 fragment, int layer, const std::vector<std::uint32_t>& leaves)
{
    if (!m_view || fragment != m_view->fragmentId() || AnnotationLayer(layer) != m_layer) return;
    if (leaves.empty() || m_view->overlay().isEmpty()) {
        rebuild();
        return;
    }
    const auto labels = shownLabels();
    if (!labels) return;
    const auto& index = *m_view->leafIndex();
    const std::vector<std::uint32_t> pixels = index.pixelsOf(leaves); // only the touched pixels
    std::vector<std::uint8_t> ids(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) ids[i] = index.majorityLabel(pixels[i], *labels);
    m_view->overlay().setPixels(pixels, ids);
    m_view->overlayChanged();
}

void DeveloppeeAnnotator::legendChanged()
{
    if (!m_document.legend().find(m_layer, m_class) || m_class == 0) {
        const auto& classes = m_document.legend().classes(m_layer);
        m_class = classes.empty() ? 0 : classes.front().id;
        if (m_view) m_view->setActiveClass(m_class);
        Q_EMIT activeChanged(m_layer, m_class);
    }
    if (!m_view || m_view->overlay().isEmpty()) return;
    recolour();
    m_view->overlayChanged();
}

void DeveloppeeAnnotator::paint(const std::vector<std::uint32_t>& pixels, std::uint8_t classId)
{
    if (!m_view || !shownLabels()) return;
    const std::vector<std::uint32_t> leaves = m_view->leafIndex()->leavesOf(pixels);
    const auto* cls = m_document.legend().find(m_layer, classId);
    const QString text = classId == 0 ? tr("Erase %1").arg(LegendText::layerTitle(m_layer))
                                      : tr("Paint “%1”").arg(cls ? LegendText::className(m_layer, *cls) : QString());
    m_document.setLabels(m_view->fragmentId(), m_layer, leaves, classId, text, m_stroke);
}

} // namespace stylos::widgets
