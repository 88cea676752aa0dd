// The développée's annotation overlay from the document's labels, and its painting into them.
#include "stylos/widgets/annotation/DeveloppeeAnnotator.h"

#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/annotation/LegendText.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/document/SceneDocument.h"

#include "stylos/core/scene/SceneEigen.h"

#include <Eigen/Geometry>

namespace stylos::widgets {

DeveloppeeAnnotator::DeveloppeeAnnotator(SceneDocument& document, DeveloppeeView& view, QObject* parent)
    : QObject(parent), m_document(document), m_view(&view)
{
    connect(&view, &DeveloppeeView::developpeeChanged, this, &DeveloppeeAnnotator::rebuild);
    connect(&view, &DeveloppeeView::strokeStarted, this, [this] {
        m_stroke = m_document.beginStroke();
        m_refusedThisStroke = false;
    });
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
    if (m_view->assemblyIndex()) {
        rebuildAssembly();
        return;
    }
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
    if (!m_view || AnnotationLayer(layer) != m_layer) return;
    if (const auto& assembly = m_view->assemblyIndex()) {
        const auto piece = pieceOf(fragment);
        if (!piece) return;
        if (leaves.empty() || m_view->overlay().isEmpty()) {
            rebuild();
            return;
        }
        const auto labels = m_document.labels().labels(fragment, m_layer);
        const std::vector<std::uint32_t> pixels = assembly->pixelsOf(*piece, leaves); // only the touched pixels
        std::vector<std::uint8_t> ids(pixels.size());
        const auto labelsOf = [&](std::uint64_t) { return labels ? std::span<const std::uint8_t>(*labels) : std::span<const std::uint8_t>(); };
        for (std::size_t i = 0; i < pixels.size(); ++i) ids[i] = assembly->majorityLabel(pixels[i], labelsOf);
        m_view->overlay().setPixels(pixels, ids);
        m_view->overlayChanged();
        return;
    }
    if (fragment != m_view->fragmentId()) return;
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
    if (!m_view) return;
    const auto* cls = m_document.legend().find(m_layer, classId);
    const QString text = classId == 0 ? tr("Erase %1").arg(LegendText::layerTitle(m_layer))
                                      : tr("Paint “%1”").arg(cls ? LegendText::className(m_layer, *cls) : QString());
    if (m_view->assemblyIndex()) {
        paintAssembly(pixels, classId, text);
        return;
    }
    if (!shownLabels()) return;
    const std::vector<std::uint32_t> leaves = m_view->leafIndex()->leavesOf(pixels);
    m_document.setLabels(m_view->fragmentId(), m_layer, leaves, classId, text, m_stroke);
}

quint64 DeveloppeeAnnotator::fragmentOf(std::uint64_t piece) const { return piece == 0 ? m_view->fragmentId() : piece; }

std::optional<std::uint64_t> DeveloppeeAnnotator::pieceOf(quint64 fragment) const
{
    const auto& assembly = m_view ? m_view->assemblyIndex() : nullptr;
    if (!assembly) return std::nullopt;
    const std::uint64_t piece = fragment == m_view->fragmentId() ? 0 : fragment;
    return assembly->find(piece) ? std::optional<std::uint64_t>(piece) : std::nullopt;
}

void DeveloppeeAnnotator::rebuildAssembly()
{
    const auto& assembly = *m_view->assemblyIndex();
    // Each piece's labels (held while the overlay is made), by piece id.
    std::vector<std::pair<std::uint64_t, std::shared_ptr<const std::vector<std::uint8_t>>>> held;
    for (const auto& piece : assembly.pieces()) held.emplace_back(piece.id, m_document.labels().labels(fragmentOf(piece.id), m_layer));
    const auto labelsOf = [&held](std::uint64_t id) {
        for (const auto& [piece, labels] : held)
            if (piece == id && labels) return std::span<const std::uint8_t>(*labels);
        return std::span<const std::uint8_t>();
    };
    std::vector<std::uint8_t> ids(std::size_t(assembly.width()) * std::size_t(assembly.height()), 0);
    for (std::size_t p = 0; p < ids.size(); ++p) ids[p] = assembly.majorityLabel(std::uint32_t(p), labelsOf);
    recolour();
    m_view->overlay().setIds(assembly.width(), assembly.height(), std::move(ids));
    m_view->overlayChanged();
}

QString DeveloppeeAnnotator::staleReason() const
{
    if (!m_view || !m_view->assemblyIndex()) return {};
    const quint64 drumId = m_view->fragmentId();
    const auto outOfDate = [](const QString& why) {
        return tr("Not painted: the développée of the assembly is out of date (%1). Compute it again to paint.").arg(why);
    };
    if (!m_document.fragment(drumId)) return outOfDate(tr("its drum was removed"));
    const Eigen::Isometry3d drumWorld(core::scene::toEigen(m_document.worldPose(drumId)));
    for (const auto& piece : m_view->assemblyIndex()->pieces()) {
        const quint64 id = fragmentOf(piece.id);
        const core::scene::Fragment* f = m_document.fragment(id);
        if (!f) return outOfDate(tr("a fragment was removed"));
        const QString name = QString::fromStdString(f->name);
        if (piece.id != 0) {
            const core::scene::Assembly* assembly = m_document.assembly(f->assembly);
            if (!assembly || assembly->drum != drumId) return outOfDate(tr("“%1” is no longer in the assembly").arg(name));
            const Eigen::Isometry3d toDrum = drumWorld.inverse() * Eigen::Isometry3d(core::scene::toEigen(m_document.worldPose(id)));
            if ((toDrum.matrix() - piece.pose.matrix()).cwiseAbs().maxCoeff() > 1e-9)
                return outOfDate(tr("“%1” was moved").arg(name));
        }
        const auto octree = m_document.octree(id);
        const auto labels = m_document.labels().labels(id, m_layer);
        if (!octree || octree->path().string() != piece.source || !labels || labels->size() != piece.index.leafCount())
            return outOfDate(tr("the octree of “%1” changed").arg(name));
    }
    return {};
}

void DeveloppeeAnnotator::paintAssembly(const std::vector<std::uint32_t>& pixels, std::uint8_t classId, const QString& text)
{
    if (const QString reason = staleReason(); !reason.isEmpty()) {
        if (!m_refusedThisStroke || m_stroke == 0) Q_EMIT refused(reason);
        m_refusedThisStroke = true;
        return;
    }
    // Each piece's leaves at the pixels it shows; one stroke token: all of it is one undo step.
    const auto& assembly = *m_view->assemblyIndex();
    const quint64 stroke = m_stroke != 0 ? m_stroke : m_document.beginStroke();
    for (const auto& [piece, own] : assembly.split(pixels))
        m_document.setLabels(fragmentOf(piece), m_layer, assembly.leavesOf(piece, own), classId, text, stroke);
}

} // namespace stylos::widgets
