#pragma once
/** @file
 * @brief Joins a DeveloppeeView to the document's annotation: the view's overlay shows the active layer of the
 *        shown fragment's labels in the legend's colours, and what the view paints becomes labels.
 *
 * - Overlay: on a new développée, another layer or a loaded / reset label set, every pixel's id is made from the
 *   labels through the développée's PixelLeafIndex (the majority label of its leaves, as a label raster);
 *   on LabelStore::labelsChanged(leaves) only the pixels of those leaves are made again; on legendChanged() only
 *   the colours. Nothing is recomputed per stroke beyond the touched pixels.
 * - Painting: strokeStarted() takes a stroke token (SceneDocument::beginStroke), each pixelsPainted() sets the
 *   leaves of those pixels through SceneDocument::setLabels with that token — so one stroke is one undo step —
 *   and the overlay follows from labelsChanged like any other edit (an undo, the 3D lasso).
 * - The active layer and class: setActive(); the tool bar and the Legend dock follow activeChanged().
 * The labels must belong to the développée's octree (same leaf count); otherwise nothing is shown or painted.
 * GUI thread only.
 */
#include "stylos/core/annotation/Legend.h"

#include <QObject>
#include <QPointer>

#include <cstdint>
#include <vector>

namespace stylos::widgets {

class DeveloppeeView;
class SceneDocument;

class DeveloppeeAnnotator : public QObject {
    Q_OBJECT

public:
    using AnnotationLayer = core::annotation::AnnotationLayer;

    /** Neither owned; both must outlive the annotator (or it is the view's child). */
    DeveloppeeAnnotator(SceneDocument& document, DeveloppeeView& view, QObject* parent = nullptr);

    AnnotationLayer layer() const { return m_layer; }
    /** @brief The class painted (0: none; e.g. an empty layer). */
    std::uint8_t activeClass() const { return m_class; }
    /** @brief Chooses the layer shown and painted and its class (0 or a class the layer lacks: its first). */
    void setActive(AnnotationLayer layer, std::uint8_t classId);

Q_SIGNALS:
    void activeChanged(stylos::core::annotation::AnnotationLayer layer, std::uint8_t classId);

private:
    /** The labels of the shown fragment's active layer when they fit the view's index; else null. */
    std::shared_ptr<const std::vector<std::uint8_t>> shownLabels() const;
    void rebuild();
    void recolour();
    void labelsChanged(quint64 fragment, int layer, const std::vector<std::uint32_t>& leaves);
    void legendChanged();
    void paint(const std::vector<std::uint32_t>& pixels, std::uint8_t classId);

    SceneDocument& m_document;
    QPointer<DeveloppeeView> m_view;
    AnnotationLayer m_layer = AnnotationLayer::Material;
    std::uint8_t m_class = 0;
    quint64 m_stroke = 0;
};

} // namespace stylos::widgets
