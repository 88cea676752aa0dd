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
 * Coordinates: "image" positions are the UnrollMap's continuous pixel coordinates (pixel (c, r) spans
 * [c, c + 1) × [r, r + 1), row 0 at the top); "widget" positions are logical pixels of this widget;
 * widget = offset + zoom · image. GUI thread only.
 */
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/unroll/UnrollMap.h"
// Q_DECLARE_METATYPE(Eigen::Vector3d) is made there; pointPicked() uses the same type.
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <Eigen/Core>

#include <QImage>
#include <QPixmap>
#include <QPointF>
#include <QString>
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

namespace stylos::widgets {

struct DeveloppeeResult;

class DeveloppeeView : public QWidget {
    Q_OBJECT

public:
    static constexpr double MinZoom = 1.0 / 256.0; ///< widget pixels per image pixel
    static constexpr double MaxZoom = 64.0;

    explicit DeveloppeeView(QWidget* parent = nullptr);

    /**
     * @brief Shows @p image (any format; grey + alpha from DeveloppeeJob) of fragment @p fragmentId, with
     *        its @p heights and @p map (same size as the image; asserted) and fits it to the window. The
     *        marker is kept (placed again through the new map) for the same fragment, dropped for another.
     */
    void setDeveloppee(quint64 fragmentId, const QImage& image,
                       std::shared_ptr<const core::shading::HeightField> heights, const core::unroll::UnrollMap& map);
    /** @brief setDeveloppee() from a successful job result; a failed one is ignored (returns false). */
    bool setResult(const DeveloppeeResult& result);
    /** @brief Shows nothing (the placeholder text). */
    void clear();

    bool hasDeveloppee() const { return m_map.has_value(); }
    quint64 fragmentId() const { return m_fragmentId; }
    const std::optional<core::unroll::UnrollMap>& map() const { return m_map; }
    const QImage& image() const { return m_image; }

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
};

} // namespace stylos::widgets
