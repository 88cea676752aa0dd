#pragma once
/** @file
 * @brief The 2D view of a développée: the shaded image with pan (drag with any button) and zoom (wheel,
 *        about the cursor; + and −), fit to the window (F, double-click, or at first show and on resize
 *        until the user pans or zooms), a readout of the point under the cursor (u and v in mm along the
 *        image, the height in mm from the unrolled heights) and a scale bar, both drawn in the corners.
 *
 * Linked to 3D both ways through the développée's core::unroll::UnrollMap, in the octree's frame (the
 * fragment's own): a left click (press and release within 4 pixels) on a pixel with a height emits
 * pointPicked(fragmentId, map.worldAtPixel(c + 0.5, r + 0.5, h)) — the centre of pixel (c, r) at its
 * height h — and marks that pixel; setMarker(point) draws a marker where map.pixelOf(point) lands.
 *
 * Annotation (docs/annotation.md): with a pixel ↔ leaf index (DeveloppeeResult::leafIndex, or an assembly's
 * DeveloppeeResult::assemblyIndex) the view paints. It
 * draws a LabelOverlay (class ids per pixel in the legend's colours, at overlayOpacity()) that someone else
 * fills (DeveloppeeAnnotator, from the document's labels), and with a paint tool (setTool(); keys B brush,
 * E eraser, L polygon / lasso, W magic wand, H fill holes, N navigate) a left press paints: it emits
 * strokeStarted(), then pixelsPainted() once per dab or fill, then strokeFinished() — one press-drag-release
 * (or one fill) is one stroke. Brush and eraser take the pixels whose centre is within brushSize() / 2 (metres
 * on the object, through the map's pixel size) of the dragged path; the polygon is made of clicks (closed by a
 * double-click, Enter or a click on its first vertex; Escape cancels it) or one freehand drag (closed on
 * release); the wand fills the 4-connected pixels whose height (or shading) is within the tolerance of the
 * clicked one; "holes" fills what the clicked region encloses with its class. With a paint tool, the middle
 * and right buttons pan and the wheel zooms as always. The view never changes labels itself.
 *
 * Coordinates: "image" positions are the UnrollMap's continuous pixel coordinates (pixel (c, r) spans
 * [c, c + 1) × [r, r + 1), row 0 at the top); "widget" positions are logical pixels of this widget;
 * widget = offset + zoom · image. GUI thread only.
 */
#include "stylos/core/annotation/AssemblyLeafIndex.h"
#include "stylos/core/annotation/PixelLeafIndex.h"
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/unroll/UnrollMap.h"
// Q_DECLARE_METATYPE(Eigen::Vector3d) is made there; pointPicked() uses the same type.
#include "stylos/widgets/developpee/LabelOverlay.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <Eigen/Core>

#include <QImage>
#include <QPixmap>
#include <QPointF>
#include <QString>
#include <QWidget>

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

namespace stylos::widgets {

struct DeveloppeeResult;
class DeveloppeePaintTool;

/** @brief What a left press does in the développée view. */
enum class PaintTool { Navigate, Brush, Eraser, Lasso, Wand, Holes };
/** @brief What the magic wand compares: the unrolled height, or the shading (skydome, light or height grey). */
enum class WandCriterion { Height, Shading };

class DeveloppeeView : public QWidget {
    Q_OBJECT

public:
    static constexpr double MinZoom = 1.0 / 256.0; ///< widget pixels per image pixel
    static constexpr double MaxZoom = 64.0;

    explicit DeveloppeeView(QWidget* parent = nullptr);
    ~DeveloppeeView() override;

    /**
     * @brief Shows @p image (any format; grey + alpha from DeveloppeeJob) of fragment @p fragmentId, with
     *        its @p heights and @p map (same size as the image; asserted) and fits it to the window. The
     *        marker is kept (placed again through the new map) for the same fragment, dropped for another.
     *        @p leafIndex (the same grid, else ignored) makes it paintable. Emits developpeeChanged().
     */
    void setDeveloppee(quint64 fragmentId, const QImage& image,
                       std::shared_ptr<const core::shading::HeightField> heights, const core::unroll::UnrollMap& map,
                       std::shared_ptr<const core::annotation::PixelLeafIndex> leafIndex = nullptr);
    /** @brief setDeveloppee() from a successful job result; a failed one is ignored (returns false). */
    bool setResult(const DeveloppeeResult& result);
    /** @brief Shows nothing (the placeholder text). */
    void clear();

    bool hasDeveloppee() const { return m_map.has_value(); }
    quint64 fragmentId() const { return m_fragmentId; }
    const std::optional<core::unroll::UnrollMap>& map() const { return m_map; }
    const QImage& image() const { return m_image; }
    const std::shared_ptr<const core::shading::HeightField>& heights() const { return m_heights; }
    /** @brief The pixel ↔ leaf index of the shown développée; null when it cannot be painted. */
    const std::shared_ptr<const core::annotation::PixelLeafIndex>& leafIndex() const { return m_leafIndex; }
    /** @brief An assembly's développée: the leaves of each piece at the pixels it shows (DeveloppeeResult::
     *         assemblyIndex); null for one fragment's. Painting there splits the pixels by the piece shown. */
    const std::shared_ptr<const core::annotation::AssemblyLeafIndex>& assemblyIndex() const { return m_assemblyIndex; }
    /** @brief Sets it after setDeveloppee() (the same grid, else ignored); makes the view paintable. */
    void setAssemblyIndex(std::shared_ptr<const core::annotation::AssemblyLeafIndex> index);
    bool canPaint() const { return m_leafIndex != nullptr || m_assemblyIndex != nullptr; }

    // Annotation overlay (filled from outside; see the file comment).
    LabelOverlay& overlay() { return m_overlay; }
    const LabelOverlay& overlay() const { return m_overlay; }
    /** @brief Redraws after the overlay changed (only the screen; the ids are the overlay's). */
    void overlayChanged() { update(); }
    /** @brief 0 (hidden) to 1 (opaque); 0.6 at first. */
    void setOverlayOpacity(double opacity);
    double overlayOpacity() const { return m_overlayOpacity; }

    // Painting tools.
    void setTool(PaintTool tool);
    PaintTool tool() const { return m_tool; }
    /** @brief The class the brush, polygon and wand paint (0: none chosen, they do nothing). */
    void setActiveClass(std::uint8_t classId) { m_activeClass = classId; }
    std::uint8_t activeClass() const { return m_activeClass; }
    /** @brief Brush and eraser diameter on the object, metres (> 0). */
    void setBrushSize(double metres) { m_brushSize = std::max(1e-6, metres); update(); }
    double brushSize() const { return m_brushSize; }
    void setWandCriterion(WandCriterion criterion) { m_wandCriterion = criterion; }
    WandCriterion wandCriterion() const { return m_wandCriterion; }
    /** @brief The wand's tolerance: metres for Height, a fraction of the grey range (0..1) for Shading. */
    void setWandTolerance(double tolerance) { m_wandTolerance = std::max(0.0, tolerance); }
    double wandTolerance() const { return m_wandTolerance; }
    /** @brief The pixels the wand takes from @p seed with the current criterion and tolerance. */
    std::vector<std::uint32_t> wandPixels(std::uint32_t seed) const;
    /** @brief The polygon being drawn (image positions); empty when none. */
    std::vector<QPointF> polygonInProgress() const;

    /** @brief The text shown when there is nothing to show. */
    void setPlaceholderText(const QString& text);

    // The view transform.
    double zoom() const { return m_zoom; }
    /** @brief Widget position of image position (0, 0), logical pixels. */
    QPointF offset() const { return m_offset; }
    /** @brief Sets zoom (clamped to [MinZoom, MaxZoom]) and offset; stops the automatic fit. */
    void setTransform(double zoom, const QPointF& offset);
    QPointF widgetToImage(const QPointF& widget) const { return (widget - m_offset) / m_zoom; }
    QPointF imageToWidget(const QPointF& image) const { return m_offset + image * m_zoom; }
    /** @brief Multiplies the zoom by @p factor (clamped), keeping the image position under @p widget fixed. */
    void zoomAbout(const QPointF& widget, double factor);
    /** @brief Centres the image at the largest zoom that shows it whole; resizing keeps fitting it. */
    void fitToWindow();

    /** @brief The 3D point (octree frame) of pixel (@p column, @p row): its centre at its height;
     *         nullopt outside the image or on an Empty pixel. */
    std::optional<Eigen::Vector3d> pointAtPixel(int column, int row) const;

    /** @brief A guide line to draw (octree frame, metres): a flute's bottom line of the drum the fragment
     *         docks against (or of the fragment itself), parallel to the axis the développée unrolls about. */
    struct GuideLine {
        Eigen::Vector3d point = Eigen::Vector3d::Zero();
        Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
    };
    /** @brief Draws @p lines over the développée, each as a thin line along its image through the map with a
     *         tick above the image; kept until replaced (an empty list hides them). */
    void setGuideLines(std::vector<GuideLine> lines);
    /** @brief Where each guide line crosses the image's middle row (continuous column), in the order given;
     *         lines the map cannot place are left out. Empty without a développée. */
    std::vector<double> guideColumns() const;

    /** @brief An assembly's développée: the fragment each pixel shows (row-major, the image's size; 0: none),
     *         outlined in yellow; a click on one emits piecePicked(). Null (or the wrong size) for none. */
    void setPieces(std::shared_ptr<const std::vector<std::uint64_t>> pieceAt);
    /** @brief The fragment pixel (@p column, @p row) shows; 0 for none. */
    std::uint64_t pieceAt(int column, int row) const;

    /** @brief Marks @p point (octree frame, metres); empty hides the marker. */
    void setMarker(const std::optional<Eigen::Vector3d>& point);
    std::optional<Eigen::Vector3d> marker() const { return m_marker; }
    /** @brief Where the marker lands (continuous image position); nullopt without a marker or a map,
     *         or when the point has no surface coordinates. */
    std::optional<QPointF> markerPixel() const;

    /** @brief The readout for image position @p image: empty outside the image. */
    QString readoutAt(const QPointF& image) const;
    /** @brief The readout under the cursor, as drawn (empty when the cursor is elsewhere). */
    QString readout() const { return m_readout; }
    /** @brief "u 12.3 mm   v 4.5 mm   h 0.12 mm", or "… (no data)" without a height (translated). */
    static QString formatReadout(double uMetres, double vMetres, std::optional<double> hMetres);

Q_SIGNALS:
    /** @brief A click on pixel (c, r) of fragment @p fragmentId: its 3D point (octree frame), see pointAtPixel(). */
    void pointPicked(quint64 fragmentId, const Eigen::Vector3d& point);
    /** @brief A click on a fragment's pixels in an assembly's développée (setPieces()). */
    void piecePicked(quint64 fragmentId);
    /** @brief The readout under the cursor changed (empty when the cursor left the image). */
    void readoutChanged(const QString& text);
    /** @brief Another développée (or none) is shown: the overlay was emptied. */
    void developpeeChanged();
    /** @brief setTool() (or its key) chose another tool. */
    void toolChanged(stylos::widgets::PaintTool tool);
    /** @brief A stroke begins: the pixelsPainted() until strokeFinished() are one undo step. */
    void strokeStarted();
    /** @brief Pixels (row-major, ascending) to give @p classId (0: erase). */
    void pixelsPainted(const std::vector<std::uint32_t>& pixels, std::uint8_t classId);
    void strokeFinished();

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    void resetPainting();
    void updateReadout(const QPointF& widget);
    void setReadout(const QString& text);
    void drawMarker(class QPainter& painter) const;
    void drawOverlays(class QPainter& painter) const;
    void drawGuideLines(class QPainter& painter) const;
    /** The image positions where guide line @p line meets the image's top and bottom rows. */
    std::optional<std::pair<QPointF, QPointF>> guideEnds(const GuideLine& line) const;

    quint64 m_fragmentId = 0;
    QImage m_image;
    QPixmap m_pixmap;
    std::shared_ptr<const core::shading::HeightField> m_heights;
    std::optional<core::unroll::UnrollMap> m_map;
    std::optional<Eigen::Vector3d> m_marker;
    std::vector<GuideLine> m_guideLines;
    std::shared_ptr<const std::vector<std::uint64_t>> m_pieceAt;
    QImage m_outline; ///< the pieces' outlines over the image, transparent elsewhere
    QString m_placeholder;
    QString m_readout;

    double m_zoom = 1.0;
    QPointF m_offset;
    bool m_autoFit = true;
    QPoint m_pressPosition;
    QPoint m_lastPosition;
    Qt::MouseButtons m_pressButtons;
    bool m_dragged = false;
    bool m_painting = false; ///< the left press went to the paint tool
    QPointF m_cursor;        ///< the last mouse position (widget)
    bool m_cursorInside = false;

    std::shared_ptr<const core::annotation::PixelLeafIndex> m_leafIndex;
    std::shared_ptr<const core::annotation::AssemblyLeafIndex> m_assemblyIndex;
    LabelOverlay m_overlay;
    double m_overlayOpacity = 0.6;
    PaintTool m_tool = PaintTool::Navigate;
    std::uint8_t m_activeClass = 0;
    double m_brushSize = 0.01;
    WandCriterion m_wandCriterion = WandCriterion::Height;
    double m_wandTolerance = 0.001;
    mutable std::vector<float> m_shades;        ///< the wand's shading values, made on first use
    mutable std::vector<std::uint8_t> m_valid;  ///< pixels with a height, made on first use
    std::unique_ptr<DeveloppeePaintTool> m_paint;
};

} // namespace stylos::widgets
