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
 *
 * An assembly's développée (DeveloppeeView::assemblyIndex()): the overlay shows, at each pixel, the label of the
 * piece shown there (the majority of that piece's leaves at the pixel); a stroke's pixels are split by the piece
 * shown at each and each piece's leaves at its own pixels get the class — the drum's and every fragment's edits of
 * one stroke are one undo step. Before painting, the index is checked against the document: a piece removed or
 * moved out of the assembly, re-posed against the drum, or whose octree changed since the développée was made
 * makes it stale, and then nothing is painted and refused() says why (once a stroke) until it is computed again.
 * GUI thread only.
 */
#include "stylos/core/annotation/Legend.h"

#include <QObject>
#include <QPointer>

#include <cstdint>
#include <optional>
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

    /** @brief Why painting on the shown assembly's développée is refused now (translated); empty when it is not
     *         one or its index still matches the document. */
    QString staleReason() const;

Q_SIGNALS:
    void activeChanged(stylos::core::annotation::AnnotationLayer layer, std::uint8_t classId);
    /** @brief A stroke was not painted: @p message (translated) says why and what to do. */
    void refused(const QString& message);

private:
    /** The labels of the shown fragment's active layer when they fit the view's index; else null. */
    std::shared_ptr<const std::vector<std::uint8_t>> shownLabels() const;
    void rebuild();
    void recolour();
    void labelsChanged(quint64 fragment, int layer, const std::vector<std::uint32_t>& leaves);
    void legendChanged();
    void paint(const std::vector<std::uint32_t>& pixels, std::uint8_t classId);
    // An assembly's développée.
    /** The fragment of piece @p piece (0: the drum, the view's fragment). */
    quint64 fragmentOf(std::uint64_t piece) const;
    /** The piece of fragment @p fragment in the shown assembly's index; nullopt when none. */
    std::optional<std::uint64_t> pieceOf(quint64 fragment) const;
    void rebuildAssembly();
    void paintAssembly(const std::vector<std::uint32_t>& pixels, std::uint8_t classId, const QString& text);

    SceneDocument& m_document;
    QPointer<DeveloppeeView> m_view;
    AnnotationLayer m_layer = AnnotationLayer::Material;
    std::uint8_t m_class = 0;
    quint64 m_stroke = 0;
    bool m_refusedThisStroke = false;
};

} // namespace stylos::widgets
