// The développée's brush, eraser, polygon / lasso, magic wand and hole fill.
#include "DeveloppeePaintTool.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace stylos::widgets {

namespace {

using core::annotation::GridPoint;

constexpr double ClickSlop = 4.0;  ///< logical pixels a press may move and still be a click
constexpr double CloseRadius = 6.0; ///< logical pixels: a click this near the first vertex closes the polygon

GridPoint grid(const QPointF& image) { return {image.x(), image.y()}; }

} // namespace

double DeveloppeePaintTool::brushRadiusPixels() const
{
    if (!m_view.map()) return 0.0;
    // At least half a pixel's diagonal: a dab always takes the pixel under the cursor.
    return std::max(0.5 * m_view.brushSize() / m_view.map()->pixelSize(), 0.7072);
}

std::uint8_t DeveloppeePaintTool::strokeClass() const
{
    return m_view.tool() == PaintTool::Eraser ? std::uint8_t(0) : m_view.activeClass();
}

void DeveloppeePaintTool::emitFill(const std::vector<std::uint32_t>& pixels, std::uint8_t classId)
{
    if (pixels.empty()) return;
    Q_EMIT m_view.strokeStarted();
    Q_EMIT m_view.pixelsPainted(pixels, classId);
    Q_EMIT m_view.strokeFinished();
}

void DeveloppeePaintTool::dab(const QPointF& from, const QPointF& to)
{
    const QImage& image = m_view.image();
    const auto pixels = core::annotation::brushPixels(grid(from), grid(to), brushRadiusPixels(), image.width(), image.height());
    if (!pixels.empty()) Q_EMIT m_view.pixelsPainted(pixels, strokeClass());
}

bool DeveloppeePaintTool::press(const QPointF& widget)
{
    if (!m_view.canPaint()) return false;
    const QPointF image = m_view.widgetToImage(widget);
    const int column = int(std::floor(image.x())), row = int(std::floor(image.y()));
    const int w = m_view.image().width(), h = m_view.image().height();
    const bool inside = column >= 0 && row >= 0 && column < w && row < h;
    const std::uint32_t pixel = inside ? std::uint32_t(row) * std::uint32_t(w) + std::uint32_t(column) : 0;
    switch (m_view.tool()) {
    case PaintTool::Navigate: return false;
    case PaintTool::Brush:
    case PaintTool::Eraser:
        if (m_view.tool() == PaintTool::Brush && m_view.activeClass() == 0) return true; // no class chosen
        m_stroking = true;
        m_last = image;
        Q_EMIT m_view.strokeStarted();
        dab(image, image);
        return true;
    case PaintTool::Lasso:
        m_pressWidget = widget;
        m_lassoPress = m_polygon.empty();
        m_lassoDragged = false;
        return true;
    case PaintTool::Wand:
        if (inside && m_view.activeClass() != 0) emitFill(m_view.wandPixels(pixel), m_view.activeClass());
        return true;
    case PaintTool::Holes:
        if (inside) emitFill(core::annotation::enclosedHoles(m_view.overlay().ids(), w, h, pixel),
                             m_view.overlay().idAt(column, row));
        return true;
    }
    return false;
}

bool DeveloppeePaintTool::move(const QPointF& widget)
{
    const QPointF image = m_view.widgetToImage(widget);
    if (m_stroking) {
        dab(m_last, image);
        m_last = image;
        return true;
    }
    if (m_view.tool() != PaintTool::Lasso || !m_lassoPress) return false;
    if (!m_lassoDragged && (widget - m_pressWidget).manhattanLength() > ClickSlop) {
        m_lassoDragged = true;
        m_polygon.push_back(grid(m_view.widgetToImage(m_pressWidget)));
    }
    if (m_lassoDragged) {
        const GridPoint& last = m_polygon.back();
        if (std::hypot(image.x() - last.x, image.y() - last.y) * m_view.zoom() >= 1.0) m_polygon.push_back(grid(image));
        m_view.update();
    }
    return true;
}

bool DeveloppeePaintTool::release(const QPointF& widget)
{
    if (m_stroking) {
        m_stroking = false;
        Q_EMIT m_view.strokeFinished();
        return true;
    }
    if (m_view.tool() != PaintTool::Lasso) return m_view.tool() != PaintTool::Navigate;
    if (m_lassoPress && m_lassoDragged) { // a freehand lasso closes when the button is let go
        m_lassoPress = m_lassoDragged = false;
        closePolygon();
        return true;
    }
    m_lassoPress = false;
    // A click: a vertex, or the end when it lands on the first one.
    const QPointF image = m_view.widgetToImage(widget);
    if (m_polygon.size() >= 3) {
        const QPointF first = m_view.imageToWidget(QPointF(m_polygon.front().x, m_polygon.front().y));
        if (QLineF(first, widget).length() <= CloseRadius) {
            closePolygon();
            return true;
        }
    }
    m_polygon.push_back(grid(image));
    m_view.update();
    return true;
}

bool DeveloppeePaintTool::doubleClick()
{
    if (m_view.tool() != PaintTool::Lasso) return m_view.tool() != PaintTool::Navigate;
    closePolygon();
    return true;
}

bool DeveloppeePaintTool::key(int key)
{
    if (key == Qt::Key_Escape) {
        const bool busy = !m_polygon.empty() || m_stroking;
        cancel();
        return busy;
    }
    if ((key == Qt::Key_Return || key == Qt::Key_Enter) && m_view.tool() == PaintTool::Lasso && !m_polygon.empty()) {
        closePolygon();
        return true;
    }
    return false;
}

void DeveloppeePaintTool::cancel()
{
    if (m_stroking) Q_EMIT m_view.strokeFinished();
    m_stroking = false;
    m_polygon.clear();
    m_lassoPress = m_lassoDragged = false;
    m_view.update();
}

void DeveloppeePaintTool::closePolygon()
{
    std::vector<GridPoint> polygon;
    polygon.swap(m_polygon);
    m_view.update();
    if (polygon.size() < 3 || m_view.activeClass() == 0) return;
    emitFill(core::annotation::polygonPixels(polygon, m_view.image().width(), m_view.image().height()), m_view.activeClass());
}

void DeveloppeePaintTool::draw(QPainter& painter, const QPointF& cursor, bool cursorInside) const
{
    painter.setRenderHint(QPainter::Antialiasing, true);
    if (!m_polygon.empty()) {
        QPolygonF line;
        for (const GridPoint& p : m_polygon) line << m_view.imageToWidget(QPointF(p.x, p.y));
        if (cursorInside && !m_lassoDragged) line << cursor;
        for (const auto& [colour, width] : {std::pair{QColor(0, 0, 0, 180), 3.0}, std::pair{QColor(255, 255, 255), 1.0}}) {
            painter.setPen(QPen(colour, width));
            painter.drawPolyline(line);
        }
    }
    const PaintTool tool = m_view.tool();
    if (cursorInside && (tool == PaintTool::Brush || tool == PaintTool::Eraser)) {
        const double r = brushRadiusPixels() * m_view.zoom();
        painter.setBrush(Qt::NoBrush);
        for (const auto& [colour, width] : {std::pair{QColor(0, 0, 0, 180), 3.0}, std::pair{QColor(255, 255, 255), 1.0}}) {
            painter.setPen(QPen(colour, width, tool == PaintTool::Eraser ? Qt::DashLine : Qt::SolidLine));
            painter.drawEllipse(cursor, r, r);
        }
    }
    painter.setRenderHint(QPainter::Antialiasing, false);
}

} // namespace stylos::widgets
