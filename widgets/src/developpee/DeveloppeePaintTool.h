#pragma once
// The painting tools of the développée view (DeveloppeeView's PaintTool): mouse and keys in, pixel sets out
// through the view's strokeStarted / pixelsPainted / strokeFinished signals. Reads the view's public state
// (map, heights, image, overlay); never the document. GUI thread only.
#include "stylos/core/annotation/PaintRegion.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"

#include <QPointF>

#include <vector>

class QPainter;

namespace stylos::widgets {

class DeveloppeePaintTool {
public:
    explicit DeveloppeePaintTool(DeveloppeeView& view) : m_view(view) {}

    /** A left press at @p widget (logical pixels); true when the tool took it. */
    bool press(const QPointF& widget);
    /** A move with the left button held; true when the tool took it. */
    bool move(const QPointF& widget);
    /** The left button released; true when the tool took it. */
    bool release(const QPointF& widget);
    /** A left double-click: closes a polygon; true when the tool took it. */
    bool doubleClick();
    /** Enter closes the polygon, Escape cancels it (or a stroke in progress ends); true when handled. */
    bool key(int key);
    /** Drops a polygon or stroke in progress (another tool, another développée). */
    void cancel();

    bool isStroking() const { return m_stroking; }
    const std::vector<core::annotation::GridPoint>& polygon() const { return m_polygon; }
    /** Draws the polygon in progress and the brush outline at @p cursor (widget). */
    void draw(QPainter& painter, const QPointF& cursor, bool cursorInside) const;

private:
    double brushRadiusPixels() const;
    void emitFill(const std::vector<std::uint32_t>& pixels, std::uint8_t classId);
    void closePolygon();
    void dab(const QPointF& from, const QPointF& to);
    std::uint8_t strokeClass() const;

    DeveloppeeView& m_view;
    bool m_stroking = false;       ///< brush or eraser between press and release
    QPointF m_last;                ///< image position of the last dab
    std::vector<core::annotation::GridPoint> m_polygon; ///< image positions
    bool m_lassoPress = false;     ///< the press that started a polygon: a drag makes it a lasso
    bool m_lassoDragged = false;
    QPointF m_pressWidget;
};

} // namespace stylos::widgets
