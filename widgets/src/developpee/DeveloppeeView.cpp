#include "stylos/widgets/developpee/DeveloppeeView.h"

#include "stylos/widgets/developpee/DeveloppeeJob.h"

#include "DeveloppeePaintTool.h"

#include <QKeyEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace stylos::widgets {

namespace {

constexpr int ClickSlop = 4;          ///< logical pixels a press may move and still be a click
constexpr double FitMargin = 8.0;     ///< logical pixels left around a fitted image
constexpr double WheelStep = 1.25;    ///< zoom factor of one wheel notch (120 eighths of a degree)
const QColor Background(48, 48, 48);
const QColor MarkerColour(255, 96, 32);
const QColor GuideColour(120, 190, 255); // as the flute lines in 3D
const QColor OutlineColour(255, 210, 0);  // the outline of a fragment in an assembly's développée

/** 1, 2 or 5 × a power of ten, the largest not over @p value (> 0). */
double niceLength(double value)
{
    const double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (double step : {5.0, 2.0, 1.0})
        if (step * decade <= value) return step * decade;
    return decade;
}

} // namespace

DeveloppeeView::DeveloppeeView(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("DeveloppeeView"));
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    setCursor(Qt::CrossCursor);
    setMinimumSize(160, 120);
    m_placeholder = tr("No développée yet: select a fragment and press Compute.");
    m_paint = std::make_unique<DeveloppeePaintTool>(*this);
}

DeveloppeeView::~DeveloppeeView() = default;

void DeveloppeeView::setDeveloppee(quint64 fragmentId, const QImage& image,
                                   std::shared_ptr<const core::shading::HeightField> heights,
                                   const core::unroll::UnrollMap& map,
                                   std::shared_ptr<const core::annotation::PixelLeafIndex> leafIndex)
{
    assert(heights && heights->width() == image.width() && heights->height() == image.height() &&
           map.width() == image.width() && map.height() == image.height() &&
           "DeveloppeeView::setDeveloppee(): the image, heights and map differ in size");
    if (fragmentId != m_fragmentId) m_marker.reset(); // a point of another fragment's frame
    m_fragmentId = fragmentId;
    m_image = image;
    m_pixmap = QPixmap::fromImage(image);
    m_heights = std::move(heights);
    m_map = map;
    m_leafIndex = leafIndex && leafIndex->width() == image.width() && leafIndex->height() == image.height()
                      ? std::move(leafIndex)
                      : nullptr;
    m_assemblyIndex.reset();
    resetPainting();
    setPieces(nullptr);
    fitToWindow();
    setReadout({});
    Q_EMIT developpeeChanged();
}

void DeveloppeeView::resetPainting()
{
    m_paint->cancel();
    m_overlay.clear();
    m_shades.clear();
    m_valid.clear();
}

void DeveloppeeView::setOverlayOpacity(double opacity)
{
    m_overlayOpacity = std::clamp(opacity, 0.0, 1.0);
    update();
}

void DeveloppeeView::setTool(PaintTool tool)
{
    if (tool == m_tool) return;
    m_paint->cancel();
    m_tool = tool;
    setCursor(Qt::CrossCursor);
    update();
    Q_EMIT toolChanged(tool);
}

std::vector<QPointF> DeveloppeeView::polygonInProgress() const
{
    std::vector<QPointF> out;
    for (const auto& p : m_paint->polygon()) out.emplace_back(p.x, p.y);
    return out;
}

std::vector<std::uint32_t> DeveloppeeView::wandPixels(std::uint32_t seed) const
{
    if (!m_heights) return {};
    const int w = m_image.width(), h = m_image.height();
    const std::size_t n = std::size_t(w) * std::size_t(h);
    if (m_valid.size() != n) {
        m_valid.resize(n);
        const auto states = m_heights->states();
        for (std::size_t i = 0; i < n; ++i) m_valid[i] = states[i] != core::shading::PixelState::Empty;
    }
    if (m_wandCriterion == WandCriterion::Height)
        return core::annotation::floodFill(m_heights->heights(), m_valid, w, h, seed, float(m_wandTolerance));
    if (m_shades.size() != n) { // the grey shown (premultiplied by coverage: divided back), 0..1
        m_shades.resize(n);
        for (int row = 0; row < h; ++row) {
            const auto* line = reinterpret_cast<const QRgb*>(m_image.constScanLine(row));
            for (int column = 0; column < w; ++column) {
                const QRgb c = line[column];
                m_shades[std::size_t(row) * std::size_t(w) + std::size_t(column)] =
                    qAlpha(c) > 0 ? float(qGray(c)) / float(qAlpha(c)) : 0.0f;
            }
        }
    }
    return core::annotation::floodFill(m_shades, m_valid, w, h, seed, float(m_wandTolerance));
}

bool DeveloppeeView::setResult(const DeveloppeeResult& result)
{
    if (!result.ok() || !result.heights) return false;
    setDeveloppee(result.fragmentId, result.image, result.heights, *result.map, result.leafIndex);
    setPieces(result.pieceAt);
    if (result.assemblyIndex) setAssemblyIndex(result.assemblyIndex);
    return true;
}

void DeveloppeeView::setAssemblyIndex(std::shared_ptr<const core::annotation::AssemblyLeafIndex> index)
{
    if (!m_map || !index || index->width() != m_image.width() || index->height() != m_image.height()) return;
    m_assemblyIndex = std::move(index);
    Q_EMIT developpeeChanged(); // the overlay is made again, now from the pieces' labels
}

void DeveloppeeView::setPieces(std::shared_ptr<const std::vector<std::uint64_t>> pieceAt)
{
    m_pieceAt = m_map && pieceAt && pieceAt->size() == std::size_t(m_image.width()) * std::size_t(m_image.height())
                    ? std::move(pieceAt)
                    : nullptr;
    m_outline = {};
    if (m_pieceAt) {
        // Each piece's outline: its pixels with a 4-neighbour that is not the same piece.
        const int w = m_image.width(), h = m_image.height();
        m_outline = QImage(w, h, QImage::Format_ARGB32_Premultiplied);
        m_outline.fill(Qt::transparent);
        const auto& at = *m_pieceAt;
        for (int row = 0; row < h; ++row) {
            auto* line = reinterpret_cast<QRgb*>(m_outline.scanLine(row));
            for (int column = 0; column < w; ++column) {
                const std::uint64_t id = at[std::size_t(row) * w + column];
                if (id == 0) continue;
                const auto other = [&](int c, int r) {
                    return c < 0 || r < 0 || c >= w || r >= h || at[std::size_t(r) * w + c] != id;
                };
                if (other(column - 1, row) || other(column + 1, row) || other(column, row - 1) || other(column, row + 1))
                    line[column] = OutlineColour.rgba();
            }
        }
    }
    update();
}

std::uint64_t DeveloppeeView::pieceAt(int column, int row) const
{
    if (!m_pieceAt || column < 0 || row < 0 || column >= m_image.width() || row >= m_image.height()) return 0;
    return (*m_pieceAt)[std::size_t(row) * std::size_t(m_image.width()) + std::size_t(column)];
}

void DeveloppeeView::clear()
{
    m_fragmentId = 0;
    m_image = {};
    m_pixmap = {};
    m_heights.reset();
    m_map.reset();
    m_pieceAt.reset();
    m_outline = {};
    m_leafIndex.reset();
    m_assemblyIndex.reset();
    resetPainting();
    m_autoFit = true;
    setReadout({});
    update();
    Q_EMIT developpeeChanged();
}

void DeveloppeeView::setPlaceholderText(const QString& text)
{
    m_placeholder = text;
    if (!hasDeveloppee()) update();
}

void DeveloppeeView::setTransform(double zoom, const QPointF& offset)
{
    m_zoom = std::clamp(zoom, MinZoom, MaxZoom);
    m_offset = offset;
    m_autoFit = false;
    update();
}

void DeveloppeeView::zoomAbout(const QPointF& widget, double factor)
{
    const QPointF anchor = widgetToImage(widget);
    m_zoom = std::clamp(m_zoom * factor, MinZoom, MaxZoom);
    m_offset = widget - anchor * m_zoom;
    m_autoFit = false;
    update();
}

void DeveloppeeView::fitToWindow()
{
    m_autoFit = true;
    if (m_image.isNull()) return;
    const double w = std::max(1.0, width() - 2.0 * FitMargin);
    const double h = std::max(1.0, height() - 2.0 * FitMargin);
    m_zoom = std::clamp(std::min(w / m_image.width(), h / m_image.height()), MinZoom, MaxZoom);
    m_offset = QPointF((width() - m_image.width() * m_zoom) / 2.0, (height() - m_image.height() * m_zoom) / 2.0);
    update();
}

std::optional<Eigen::Vector3d> DeveloppeeView::pointAtPixel(int column, int row) const
{
    if (!m_map || !m_heights || !m_heights->contains(column, row) || !m_heights->hasHeight(column, row))
        return std::nullopt;
    return m_map->worldAtPixel(column + 0.5, row + 0.5, double(m_heights->heightAt(column, row)));
}

void DeveloppeeView::setMarker(const std::optional<Eigen::Vector3d>& point)
{
    m_marker = point;
    update();
}

std::optional<QPointF> DeveloppeeView::markerPixel() const
{
    if (!m_marker || !m_map) return std::nullopt;
    const auto hit = m_map->pixelOf(*m_marker);
    if (!hit) return std::nullopt;
    return QPointF(hit->column, hit->row);
}

QString DeveloppeeView::formatReadout(double uMetres, double vMetres, std::optional<double> hMetres)
{
    const QLocale locale;
    const QString u = locale.toString(uMetres * 1e3, 'f', 1);
    const QString v = locale.toString(vMetres * 1e3, 'f', 1);
    if (!hMetres) return tr("u %1 mm   v %2 mm   (no data)").arg(u, v);
    return tr("u %1 mm   v %2 mm   h %3 mm").arg(u, v, locale.toString(*hMetres * 1e3, 'f', 2));
}

QString DeveloppeeView::readoutAt(const QPointF& image) const
{
    if (!m_map || !m_heights) return {};
    const int column = static_cast<int>(std::floor(image.x()));
    const int row = static_cast<int>(std::floor(image.y()));
    if (!m_heights->contains(column, row)) return {};
    const double s = m_map->pixelSize();
    std::optional<double> h;
    if (m_heights->hasHeight(column, row)) h = m_heights->heightAt(column, row);
    return formatReadout(image.x() * s, m_map->vTop() - image.y() * s, h);
}

void DeveloppeeView::setReadout(const QString& text)
{
    if (text == m_readout) return;
    m_readout = text;
    update();
    Q_EMIT readoutChanged(m_readout);
}

void DeveloppeeView::updateReadout(const QPointF& widget) { setReadout(readoutAt(widgetToImage(widget))); }

void DeveloppeeView::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.fillRect(rect(), Background);
    if (!hasDeveloppee() || m_pixmap.isNull()) {
        painter.setPen(QColor(200, 200, 200));
        painter.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap, m_placeholder);
        return;
    }
    // Only the visible part of the image, whole pixels, so that deep zooms stay cheap.
    const QRectF visible = QRectF(widgetToImage(QPointF(0, 0)), widgetToImage(QPointF(width(), height())))
                               .intersected(QRectF(m_pixmap.rect()));
    if (!visible.isEmpty()) {
        const QRect source(QPoint(int(std::floor(visible.left())), int(std::floor(visible.top()))),
                           QPoint(int(std::ceil(visible.right())) - 1, int(std::ceil(visible.bottom())) - 1));
        const QRectF target(imageToWidget(source.topLeft()), QSizeF(source.width(), source.height()) * m_zoom);
        painter.setRenderHint(QPainter::SmoothPixmapTransform, m_zoom < 1.0);
        painter.drawPixmap(target, m_pixmap, QRectF(source));
        if (!m_overlay.isEmpty() && m_overlayOpacity > 0.0 && m_overlay.width() == m_image.width() &&
            m_overlay.height() == m_image.height()) {
            painter.setOpacity(m_overlayOpacity);
            painter.drawImage(target, m_overlay.image(), QRectF(source));
            painter.setOpacity(1.0);
        }
        if (!m_outline.isNull()) painter.drawImage(target, m_outline, QRectF(source));
    }
    painter.setPen(QColor(96, 96, 96));
    painter.drawRect(QRectF(m_offset, QSizeF(m_pixmap.size()) * m_zoom));
    drawGuideLines(painter);
    drawMarker(painter);
    m_paint->draw(painter, m_cursor, m_cursorInside);
    drawOverlays(painter);
}

void DeveloppeeView::setGuideLines(std::vector<GuideLine> lines)
{
    m_guideLines = std::move(lines);
    update();
}

std::optional<std::pair<QPointF, QPointF>> DeveloppeeView::guideEnds(const GuideLine& line) const
{
    if (!m_map) return std::nullopt;
    // Two points of the line a drum height apart, through the map; the line is straight in the image (it is
    // parallel to the axis), so extend it to the top and bottom rows.
    const double span = std::max(1.0, double(m_image.height())) * m_map->pixelSize();
    const auto a = m_map->pixelOf(line.point), b = m_map->pixelOf(line.point + span * line.direction.normalized());
    if (!a || !b || std::abs(b->row - a->row) < 1e-9) return std::nullopt;
    const auto columnAt = [&](double row) { return a->column + (b->column - a->column) * (row - a->row) / (b->row - a->row); };
    const double bottom = double(m_image.height());
    return std::pair{QPointF(columnAt(0.0), 0.0), QPointF(columnAt(bottom), bottom)};
}

std::vector<double> DeveloppeeView::guideColumns() const
{
    std::vector<double> columns;
    for (const GuideLine& line : m_guideLines)
        if (const auto ends = guideEnds(line)) columns.push_back(0.5 * (ends->first.x() + ends->second.x()));
    return columns;
}

void DeveloppeeView::drawGuideLines(QPainter& painter) const
{
    if (m_guideLines.empty() || !m_map) return;
    painter.setRenderHint(QPainter::Antialiasing, true);
    for (const GuideLine& line : m_guideLines) {
        const auto ends = guideEnds(line);
        if (!ends) continue;
        // A fragment's développée spans an arc: the drum's flutes beyond it are not drawn on the empty canvas.
        const double width = double(m_image.width());
        if (std::max(ends->first.x(), ends->second.x()) < 0.0 || std::min(ends->first.x(), ends->second.x()) > width)
            continue;
        const QPointF top = imageToWidget(ends->first), bottom = imageToWidget(ends->second);
        painter.setPen(QPen(GuideColour, 1.0, Qt::DotLine));
        painter.drawLine(top, bottom);
        painter.setPen(QPen(GuideColour, 2.0));
        painter.drawLine(top, top - QPointF(0.0, 8.0)); // the tick above the image
    }
    painter.setRenderHint(QPainter::Antialiasing, false);
}

void DeveloppeeView::drawMarker(QPainter& painter) const
{
    const auto pixel = markerPixel();
    if (!pixel) return;
    const QPointF c = imageToWidget(*pixel);
    painter.setRenderHint(QPainter::Antialiasing, true);
    for (const auto& [colour, width] : {std::pair{QColor(0, 0, 0, 160), 4.0}, std::pair{MarkerColour, 2.0}}) {
        painter.setPen(QPen(colour, width));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(c, 7.0, 7.0);
        painter.drawLine(c + QPointF(-14, 0), c + QPointF(-4, 0));
        painter.drawLine(c + QPointF(4, 0), c + QPointF(14, 0));
        painter.drawLine(c + QPointF(0, -14), c + QPointF(0, -4));
        painter.drawLine(c + QPointF(0, 4), c + QPointF(0, 14));
    }
    painter.setRenderHint(QPainter::Antialiasing, false);
}

void DeveloppeeView::drawOverlays(QPainter& painter) const
{
    const QFontMetrics metrics = painter.fontMetrics();
    const int pad = 4;
    const int boxHeight = metrics.height() + 2 * pad;
    if (!m_readout.isEmpty()) {
        const QRect box(6, height() - 6 - boxHeight, metrics.horizontalAdvance(m_readout) + 2 * pad, boxHeight);
        painter.fillRect(box, QColor(0, 0, 0, 170));
        painter.setPen(Qt::white);
        painter.drawText(box.adjusted(pad, 0, -pad, 0), Qt::AlignVCenter | Qt::AlignLeft, m_readout);
    }
    // Scale bar: the longest 1-2-5 length that fits in 120 logical pixels.
    const double metresPerWidgetPixel = m_map->pixelSize() / m_zoom;
    const double length = niceLength(120.0 * metresPerWidgetPixel);
    const double barPixels = length / metresPerWidgetPixel;
    const QLocale locale;
    const QString label = length >= 1.0 ? tr("%1 m").arg(locale.toString(length, 'g', 3))
                                        : tr("%1 mm").arg(locale.toString(length * 1e3, 'g', 4));
    const int boxWidth = int(std::ceil(std::max<double>(barPixels, metrics.horizontalAdvance(label)))) + 2 * pad;
    const QRect box(width() - 6 - boxWidth, height() - 6 - boxHeight - 8, boxWidth, boxHeight + 8);
    painter.fillRect(box, QColor(0, 0, 0, 170));
    painter.setPen(Qt::white);
    painter.drawText(QRect(box.left(), box.top() + 2, box.width(), metrics.height()), Qt::AlignHCenter, label);
    const double y = box.bottom() - pad - 1;
    const double x0 = box.left() + (box.width() - barPixels) / 2.0;
    painter.setPen(QPen(Qt::white, 2.0));
    painter.drawLine(QPointF(x0, y), QPointF(x0 + barPixels, y));
    painter.drawLine(QPointF(x0, y - 4), QPointF(x0, y));
    painter.drawLine(QPointF(x0 + barPixels, y - 4), QPointF(x0 + barPixels, y));
}

void DeveloppeeView::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    if (m_autoFit) fitToWindow();
}

void DeveloppeeView::mousePressEvent(QMouseEvent* event)
{
    setFocus(Qt::MouseFocusReason);
    event->accept();
    if (event->button() == Qt::LeftButton && event->buttons() == Qt::LeftButton && m_tool != PaintTool::Navigate &&
        m_paint->press(event->position())) {
        m_painting = true;
        return;
    }
    m_pressPosition = m_lastPosition = event->position().toPoint();
    m_pressButtons = event->buttons();
    m_dragged = false;
}

void DeveloppeeView::mouseMoveEvent(QMouseEvent* event)
{
    const QPoint position = event->position().toPoint();
    m_cursor = event->position();
    m_cursorInside = true;
    if (m_tool != PaintTool::Navigate) update(); // the brush outline follows
    if (m_painting && (event->buttons() & Qt::LeftButton)) {
        m_paint->move(event->position());
        updateReadout(event->position());
        return;
    }
    if (event->buttons() != Qt::NoButton && m_pressButtons != Qt::NoButton) {
        if (!m_dragged && (position - m_pressPosition).manhattanLength() > ClickSlop) {
            m_dragged = true;
            setCursor(Qt::ClosedHandCursor);
        }
        if (m_dragged && hasDeveloppee()) {
            m_offset += QPointF(position - m_lastPosition);
            m_autoFit = false;
            update();
        }
    }
    m_lastPosition = position;
    updateReadout(event->position());
}

void DeveloppeeView::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_painting && event->button() == Qt::LeftButton) {
        m_painting = false;
        m_paint->release(event->position());
        return;
    }
    const bool click = !m_dragged && event->button() == Qt::LeftButton && m_pressButtons == Qt::LeftButton;
    m_pressButtons = Qt::NoButton;
    m_dragged = false;
    setCursor(Qt::CrossCursor);
    if (!click || !hasDeveloppee()) return;
    const QPointF image = widgetToImage(event->position());
    const int column = int(std::floor(image.x())), row = int(std::floor(image.y()));
    if (const std::uint64_t piece = pieceAt(column, row)) Q_EMIT piecePicked(piece);
    const auto point = pointAtPixel(column, row);
    if (!point) return;
    m_marker = point;
    update();
    Q_EMIT pointPicked(m_fragmentId, *point);
}

void DeveloppeeView::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) return;
    if (m_tool == PaintTool::Navigate) fitToWindow();
    else if (m_tool == PaintTool::Lasso) m_paint->doubleClick();
    else mousePressEvent(event); // a quick second dab or fill
}

void DeveloppeeView::wheelEvent(QWheelEvent* event)
{
    const QPoint delta = event->angleDelta();
    const int steps = delta.y() != 0 ? delta.y() : delta.x();
    if (steps == 0 || !hasDeveloppee()) return;
    zoomAbout(event->position(), std::pow(WheelStep, steps / 120.0));
    updateReadout(event->position());
    event->accept();
}

void DeveloppeeView::keyPressEvent(QKeyEvent* event)
{
    const QPointF centre(width() / 2.0, height() / 2.0);
    if (m_paint->key(event->key())) {
        event->accept();
        return;
    }
    switch (event->key()) {
    case Qt::Key_F: fitToWindow(); break;
    case Qt::Key_N: setTool(PaintTool::Navigate); break;
    case Qt::Key_B: setTool(PaintTool::Brush); break;
    case Qt::Key_E: setTool(PaintTool::Eraser); break;
    case Qt::Key_L: setTool(PaintTool::Lasso); break;
    case Qt::Key_W: setTool(PaintTool::Wand); break;
    case Qt::Key_H: setTool(PaintTool::Holes); break;
    case Qt::Key_Plus:
    case Qt::Key_Equal: zoomAbout(centre, WheelStep); break;
    case Qt::Key_Minus: zoomAbout(centre, 1.0 / WheelStep); break;
    default: QWidget::keyPressEvent(event); return;
    }
    event->accept();
}

void DeveloppeeView::leaveEvent(QEvent* event)
{
    QWidget::leaveEvent(event);
    m_cursorInside = false;
    if (m_tool != PaintTool::Navigate) update();
    setReadout({});
}

} // namespace stylos::widgets
