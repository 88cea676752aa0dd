// Drawing a composed plate in millimetres: panels, hatches, letters, bars, rulers, triads, legend, caption.
#include "stylos/plate/PlatePainter.h"

#include "stylos/core/plate/HatchLines.h"
#include "stylos/core/plate/OrthoRender.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QTextLayout>
#include <QPainterPath>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace stylos::plate {

namespace {

namespace cp = core::plate;
namespace ann = core::annotation;

constexpr double kPt = 25.4 / 72.0;          // mm per point
constexpr double kThinMm = 0.3 * kPt * 1.2;  // a little over 0.3 pt
constexpr double kHatchSpacingMm = 1.6;
constexpr double kHatchPenMm = 0.18;
constexpr double kLegendColumnMm = 60.0;

/** The plate's font @p pt points high at @p unitsPerMm device units per millimetre: what text() draws with and
 *  textWidthMm() measures. */
QFont plateFont(double pt, double unitsPerMm, bool bold = false, bool serif = false)
{
    QFont font(serif ? QStringLiteral("DejaVu Serif") : QStringLiteral("DejaVu Sans"));
    font.setPixelSize(std::max(1, int(std::lround(pt * kPt * unitsPerMm))));
    font.setBold(bold);
    font.setHintingPreference(QFont::PreferNoHinting);
    return font;
}

/** Draws @p text with its baseline-left (or aligned box) at @p at (mm), @p pt points high, in device pixels so
 *  glyphs are laid out at the device's resolution. */
/** @return the x (mm) where the text ends. */
double text(QPainter& p, const QPointF& at, const QString& s, double pt, bool bold = false, bool serif = false,
            Qt::Alignment align = Qt::AlignLeft)
{
    // Draw in device-sized units (the current transform less its scale, so a rotation stays), with a font sized in
    // device pixels: glyphs are laid out at the device's resolution whatever the page's scale.
    const QTransform t = p.transform();
    const double scale = std::sqrt(std::abs(t.determinant()));
    const QFont font = plateFont(pt, scale, bold, serif);
    p.save();
    p.setTransform(QTransform::fromScale(1.0 / scale, 1.0 / scale) * t);
    p.setFont(font);
    p.setPen(Qt::black);
    const QFontMetricsF m(font);
    double x = at.x() * scale;
    if (align & Qt::AlignHCenter) x -= 0.5 * m.horizontalAdvance(s);
    else if (align & Qt::AlignRight) x -= m.horizontalAdvance(s);
    p.drawText(QPointF(x, at.y() * scale), s);
    p.restore();
    return (x + m.horizontalAdvance(s)) / scale;
}

/** The width on paper (mm) of @p s drawn @p pt points high by text(). */
double textWidthMm(const QString& s, double pt)
{
    constexpr double unitsPerMm = 100.0;
    return QFontMetricsF(plateFont(pt, unitsPerMm)).horizontalAdvance(s) / unitsPerMm;
}

QPen pen(double widthMm, const QColor& colour = Qt::black)
{
    QPen p(colour, widthMm);
    p.setCapStyle(Qt::FlatCap);
    p.setJoinStyle(Qt::MiterJoin);
    return p;
}

void arrow(QPainter& p, const QPointF& from, const QPointF& to)
{
    p.setPen(pen(kThinMm * 1.5));
    p.drawLine(from, to);
    const QPointF d = to - from;
    const double len = std::hypot(d.x(), d.y());
    if (len <= 0) return;
    const QPointF u = d / len, n(-u.y(), u.x());
    QPainterPath head;
    head.moveTo(to);
    head.lineTo(to - 1.6 * u + 0.7 * n);
    head.lineTo(to - 1.6 * u - 0.7 * n);
    head.closeSubpath();
    p.fillPath(head, Qt::black);
}

QString viewTitle(const cp::PanelSpec& panel, const PlateTexts& texts)
{
    return texts.views[std::size_t(panel.view)] + QStringLiteral(", ") + texts.shadings[std::size_t(panel.shading)];
}

/** @p number ("0.5 m", "1:2.5") with the plate's decimal point. */
QString localNumber(const std::string& number, const PlateTexts& texts)
{
    QString out = QString::fromStdString(number);
    out.replace(QLatin1Char('.'), texts.decimalPoint);
    return out;
}

void drawBar(QPainter& p, const cp::PanelBox& box, const PlateTexts& texts)
{
    const cp::ScaleBar& bar = box.bar;
    if (bar.segments <= 0) return;
    const QRectF r(box.barRect.x, box.barRect.y, box.barRect.w, box.barRect.h);
    const double seg = r.width() / bar.segments;
    for (int i = 0; i < bar.segments; ++i) {
        const QRectF s(r.x() + i * seg, r.y(), seg, r.height());
        p.fillRect(s, i % 2 == 0 ? Qt::black : Qt::white);
    }
    p.setPen(pen(kThinMm));
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
    const bool every = seg >= 8.0;
    for (int i = 0; i <= bar.segments; ++i) {
        const double x = r.x() + i * seg;
        p.drawLine(QPointF(x, r.y() - 0.8), QPointF(x, r.y()));
        if (every || i == 0 || i == bar.segments)
            text(p, QPointF(x, r.y() - 1.3), localNumber(bar.tickLabel(i), texts), 6.5, false, false,
                 i == bar.segments && !every ? Qt::AlignLeft : Qt::AlignHCenter);
    }
    text(p, QPointF(r.right() + 9.0, r.bottom()), localNumber(box.scaleText, texts), 8);
}

void drawRuler(QPainter& p, const cp::PanelBox& box, const QString& axis)
{
    const QRectF r(box.rulerRect.x, box.rulerRect.y, box.rulerRect.w, box.rulerRect.h);
    const double top = r.y() + 0.8;
    p.setPen(pen(kThinMm));
    p.drawLine(QPointF(r.x(), top), QPointF(r.right(), top));
    // The whole turn, or a fragment's arc: degrees from the image's left edge. Labels about every 10 mm or more.
    const double degrees = std::clamp(box.rulerDegrees, 1.0, 360.0);
    const double perTurn = r.width() * 360.0 / degrees; // mm the whole turn would take
    const int labelEvery = degrees < 360.0 && perTurn >= 360 ? 10 : perTurn >= 120 ? 30 : (perTurn >= 50 ? 90 : 180);
    for (int deg = 0; deg <= int(degrees + 1e-9); deg += 10) {
        const double x = r.x() + r.width() * deg / degrees;
        const bool major = deg % 30 == 0;
        p.drawLine(QPointF(x, top), QPointF(x, top + (major ? 1.8 : 1.0)));
        if (deg % labelEvery == 0)
            text(p, QPointF(x, top + 4.6), QStringLiteral("%1°").arg(deg), 6, false, false,
                 deg == 0 ? Qt::AlignLeft : (deg == 360 ? Qt::AlignRight : Qt::AlignHCenter));
    }
    if (degrees < 360.0) p.drawLine(QPointF(r.right(), top), QPointF(r.right(), top + 1.0)); // the arc's end
    // The axis: an arrow up the left edge of the image.
    const QRectF img(box.image.x, box.image.y, box.image.w, box.image.h);
    const double len = std::min(12.0, img.height());
    arrow(p, QPointF(img.x() - 2.5, img.bottom()), QPointF(img.x() - 2.5, img.bottom() - len));
    p.save();
    const QPointF at(img.x() - 3.4, img.bottom() - 0.5);
    p.translate(at);
    p.rotate(-90);
    text(p, QPointF(0, 0), axis, 6);
    p.restore();
}

void drawTriad(QPainter& p, const cp::PanelSpec& panel, const cp::PanelBox& box, double titleEnd)
{
    // In the letter band, at the image's top right: the scene's X, Y and Z projected on the page (an axis seen
    // end-on is left out), so an oblique camera shows its true directions.
    const Eigen::Matrix3d m = cp::panelOrientation(panel).toRotationMatrix(); // camera → scene
    // After the title when the panel is too narrow for both.
    const QPointF o(std::max(box.image.right() - 10.0, titleEnd + 3.0), box.image.y - 1.2);
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d v = m.transpose().col(k); // scene axis k in camera axes
        const QPointF d(v.x(), -v.y());                  // page: x right, y down
        if (std::hypot(d.x(), d.y()) < 0.15) continue;
        arrow(p, o, o + 4.5 * d);
        const QPointF at = o + 5.6 * d + QPointF(-0.8, 1.0);
        text(p, at, QString(QChar("XYZ"[k])), 6.5);
    }
}

void drawHatches(QPainter& p, const cp::PanelSpec& panel, const cp::PanelBox& box, const cp::PanelImage& image,
                 const ann::Legend& legend)
{
    if (!panel.layer || !panel.hatches || image.classes.empty()) return;
    const double mmPerPx = box.image.w / double(image.width);
    const double myPerPx = box.image.h / double(image.height);
    p.setPen(pen(kHatchPenMm));
    for (const ann::LegendClass& c : legend.classes(*panel.layer)) {
        if (std::find(image.classes.begin(), image.classes.end(), c.id) == image.classes.end()) continue;
        const auto segments = cp::hatchSegments(image.classes, image.width, image.height, c.id, c.hatch, kHatchSpacingMm / mmPerPx);
        for (const cp::HatchSegment& s : segments) {
            const QPointF a(box.image.x + s.x0 * mmPerPx, box.image.y + s.y0 * myPerPx);
            const QPointF b(box.image.x + s.x1 * mmPerPx, box.image.y + s.y1 * myPerPx);
            if (a == b) p.fillRect(QRectF(a.x() - 0.15, a.y() - 0.15, 0.3, 0.3), Qt::black);
            else p.drawLine(a, b);
        }
    }
}

struct LegendEntry {
    QString title;                       // a layer's title row
    const ann::LegendClass* cls = nullptr;
    bool coloured = false;               // some panel shows the layer in colour
    bool hatched = false;                // some panel shows it in hatches
    ann::AnnotationLayer layer = ann::AnnotationLayer::Material;
};

std::vector<LegendEntry> legendEntries(const cp::PlateSpec& spec, const std::vector<cp::RenderedPanel>& panels,
                                       const ann::Legend& legend, const PlateTexts& texts)
{
    std::vector<LegendEntry> out;
    if (!spec.legend) return out;
    for (const ann::AnnotationLayer layer : ann::AllAnnotationLayers) {
        std::array<bool, 256> present{};
        bool used = false, hatched = false, coloured = false;
        for (std::size_t i = 0; i < spec.panels.size() && i < panels.size(); ++i) {
            if (spec.panels[i].layer != layer) continue;
            used = true;
            hatched = hatched || spec.panels[i].hatches;
            coloured = coloured || !spec.panels[i].hatches;
            if (spec.panels[i].view == cp::PanelView::Developpee) { // the surface seen from outside: all it holds
                for (const std::uint8_t id : panels[i].image.classes) present[id] = true;
                continue;
            }
            // A 3D view: the regions it shows, not a far side glimpsed in a few pixels; on blocks of ~1/72 inch, so
            // that the preview (72 dpi) and the file list the same classes.
            const int block = std::max(1, int(std::lround(double(spec.dpi) / 72.0)));
            const std::array<bool, 256> shown = cp::shownClasses(panels[i].image, block);
            for (std::size_t id = 0; id < shown.size(); ++id) present[id] = present[id] || shown[id];
        }
        if (!used) continue;
        std::vector<LegendEntry> rows;
        for (const ann::LegendClass& c : legend.classes(layer))
            if (present[c.id]) rows.push_back({{}, &c, coloured, hatched, layer});
        if (rows.empty()) continue;
        out.push_back({texts.layerTitles[layer == ann::AnnotationLayer::Material ? 0 : 1], nullptr, false, false, layer});
        out.insert(out.end(), rows.begin(), rows.end());
    }
    return out;
}

int legendColumns(double widthMm) { return std::max(1, int(widthMm / kLegendColumnMm)); }

/** legendEntries()' layers, each its number of classes (its title first in the entries). */
std::vector<int> classesPerLayer(const std::vector<LegendEntry>& entries)
{
    std::vector<int> counts;
    for (const LegendEntry& e : entries) {
        if (!e.cls) counts.push_back(0);
        else ++counts.back();
    }
    return counts;
}

void drawSwatch(QPainter& p, const QRectF& r, const ann::LegendClass& c, bool hatched)
{
    if (!hatched) {
        p.fillRect(r, QColor(c.colour.r, c.colour.g, c.colour.b));
    } else {
        // The hatch traced as on the panels, over a swatch-sized raster of the class.
        const int w = int(std::lround(r.width() * 10)), h = int(std::lround(r.height() * 10));
        const std::vector<std::uint8_t> ids(std::size_t(w) * std::size_t(h), c.id);
        p.setPen(pen(kHatchPenMm));
        for (const cp::HatchSegment& s : cp::hatchSegments(ids, w, h, c.id, c.hatch, kHatchSpacingMm * 10)) {
            const QPointF a(r.x() + s.x0 / 10, r.y() + s.y0 / 10), b(r.x() + s.x1 / 10, r.y() + s.y1 / 10);
            if (a == b) p.fillRect(QRectF(a.x() - 0.15, a.y() - 0.15, 0.3, 0.3), Qt::black);
            else p.drawLine(a, b);
        }
    }
    p.setPen(pen(kThinMm));
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
}

} // namespace

PlateTexts PlateTexts::english()
{
    PlateTexts t;
    t.views = {QStringLiteral("développée"), QStringLiteral("front view"), QStringLiteral("back view"),
               QStringLiteral("left view"),  QStringLiteral("right view"), QStringLiteral("top view"),
               QStringLiteral("bottom view"), QStringLiteral("orthographic view")};
    t.shadings = {QStringLiteral("skydome"), QStringLiteral("light"), QStringLiteral("height"), QStringLiteral("headlight")};
    t.layerTitles = {QStringLiteral("Material / condition"), QStringLiteral("Tool marks")};
    return t;
}

int legendRows(const cp::PlateSpec& spec, const std::vector<cp::RenderedPanel>& panels, const ann::Legend& legend)
{
    const auto entries = legendEntries(spec, panels, legend, PlateTexts::english());
    if (entries.empty()) return 0;
    const double width = spec.orientedPage().widthMm - 2 * spec.marginMm;
    return cp::legendGridRows(classesPerLayer(entries), legendColumns(width));
}

/** The caption's lines at @p width (the font's units): wrapped at word boundaries, and inside a word only when a
 *  word alone is wider than the line (a long URL or a run of characters without spaces: it ran past the print area and
 *  was cut mid-glyph); line breaks kept. Returns the height taken. */
static double layOutCaption(QTextLayout& layout, const QString& caption, const QFont& font, double width)
{
    QString text = caption;
    text.replace(QLatin1Char('\n'), QChar::LineSeparator);
    layout.setText(text);
    layout.setFont(font);
    QTextOption option;
    option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    layout.setTextOption(option);
    double y = 0;
    layout.beginLayout();
    for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
        line.setLineWidth(width);
        line.setPosition(QPointF(0, y));
        y += line.height();
    }
    layout.endLayout();
    return y;
}

double captionHeightMm(const QString& caption, double widthMm)
{
    if (caption.trimmed().isEmpty()) return 0;
    QFont font(QStringLiteral("DejaVu Serif"));
    font.setPixelSize(int(std::lround(9 * kPt * 100))); // 0.01 mm units
    QTextLayout layout;
    return layOutCaption(layout, caption, font, widthMm * 100) / 100 + 2.0;
}

QImage panelQImage(const cp::PanelImage& image, bool sixteenBits)
{
    const int w = image.width, h = image.height;
    const bool rgb = image.channels == 3;
    QImage out(w, h, rgb ? (sixteenBits ? QImage::Format_RGBX64 : QImage::Format_RGB888)
                         : (sixteenBits ? QImage::Format_Grayscale16 : QImage::Format_Grayscale8));
    for (int y = 0; y < h; ++y) {
        uchar* line = out.scanLine(y);
        for (int x = 0; x < w; ++x) {
            if (!rgb) {
                const std::uint16_t g = image.sample(x, y);
                if (sixteenBits) reinterpret_cast<quint16*>(line)[x] = g;
                else line[x] = uchar((g + 128) / 257);
            } else if (sixteenBits) {
                quint16* px = reinterpret_cast<quint16*>(line) + 4 * x;
                px[0] = image.sample(x, y, 0), px[1] = image.sample(x, y, 1), px[2] = image.sample(x, y, 2), px[3] = 65535;
            } else {
                for (int c = 0; c < 3; ++c) line[3 * x + c] = uchar((image.sample(x, y, c) + 128) / 257);
            }
        }
    }
    return out;
}

void paintPlate(QPainter& p, const PlateContent& plate)
{
    const cp::PlateLayout& layout = plate.layout;
    p.fillRect(QRectF(0, 0, layout.page.widthMm, layout.page.heightMm), Qt::white);
    p.setRenderHint(QPainter::LosslessImageRendering, true);
    p.setRenderHint(QPainter::Antialiasing, true);
    const bool sixteen = plate.spec.bits == 16;
    for (std::size_t i = 0; i < layout.panels.size() && i < plate.panels.size(); ++i) {
        const cp::PanelBox& box = layout.panels[i];
        const cp::PanelSpec& panel = plate.spec.panels[i];
        const cp::PanelImage& image = plate.panels[i].image;
        p.drawImage(QRectF(box.image.x, box.image.y, box.image.w, box.image.h), panelQImage(image, sixteen));
        drawHatches(p, panel, box, image, plate.legend);
        const double titleX = box.image.x + (box.letter.empty() ? 0.0 : 6.0);
        if (!box.letter.empty()) text(p, QPointF(box.image.x, box.image.y - 2.0), QString::fromStdString(box.letter), 12, true);
        const double titleEnd = text(p, QPointF(titleX, box.image.y - 2.0), viewTitle(panel, plate.texts), 7.5);
        if (box.ruler) drawRuler(p, box, plate.texts.axis);
        else drawTriad(p, panel, box, titleEnd);
        drawBar(p, box, plate.texts);
    }
    const auto entries = legendEntries(plate.spec, plate.panels, plate.legend, plate.texts);
    if (!entries.empty() && layout.legend.h > 0) {
        const std::vector<cp::LegendCell> cells = cp::legendGrid(classesPerLayer(entries), legendColumns(layout.legend.w));
        for (std::size_t k = 0; k < entries.size(); ++k) {
            const double x = layout.legend.x + cells[k].column * kLegendColumnMm;
            const double y = layout.legend.y + cells[k].row * cp::kLegendRowMm;
            const LegendEntry& e = entries[k];
            if (!e.cls) {
                text(p, QPointF(x, y + 3.8), e.title, 8, true);
                continue;
            }
            double sx = x;
            if (e.coloured) drawSwatch(p, QRectF(sx, y + 0.8, 8.0, 4.0), *e.cls, false), sx += 9.0;
            if (e.hatched) drawSwatch(p, QRectF(sx, y + 0.8, 8.0, 4.0), *e.cls, true), sx += 9.0;
            const QString name = plate.texts.className ? plate.texts.className(e.layer, *e.cls) : QString::fromStdString(e.cls->name);
            text(p, QPointF(sx + 1.0, y + 3.8), name, 8);
        }
    }
    if (layout.caption.h > 0) {
        const QTransform t = p.transform();
        const double scale = std::sqrt(std::abs(t.determinant()));
        QFont font(QStringLiteral("DejaVu Serif"));
        font.setPixelSize(std::max(1, int(std::lround(9 * kPt * scale))));
        font.setHintingPreference(QFont::PreferNoHinting);
        p.save();
        p.resetTransform();
        p.setFont(font);
        p.setPen(Qt::black);
        const QRectF r = t.mapRect(QRectF(layout.caption.x, layout.caption.y, layout.caption.w, layout.caption.h));
        QTextLayout lines;
        layOutCaption(lines, QString::fromStdString(plate.spec.caption), font, r.width());
        lines.draw(&p, r.topLeft());
        p.restore();
    }
}

double panelLabelWidthMm(const cp::PanelSpec& panel, bool lettered, const PlateTexts& texts)
{
    // The title line: the letter, the view and shading, and for a 3D view the triad after them when the image is
    // narrow (drawTriad: 3 mm on, arrows and letters within 7 mm).
    const bool ruler = panel.view == cp::PanelView::Developpee;
    const double title = (lettered ? 6.0 : 0.0) + textWidthMm(viewTitle(panel, texts), 7.5) + (ruler ? 0.0 : 10.0);
    // The bar, its last label (centred on its end, or after it when the segments are short: drawBar) and "1:N".
    const cp::ScaleBar bar = cp::chooseScaleBar(panel.scale);
    if (bar.segments <= 0) return title;
    const double last = textWidthMm(localNumber(bar.tickLabel(bar.segments), texts), 6.5);
    const bool every = bar.lengthMm / bar.segments >= 8.0;
    const double ticks = bar.lengthMm + (every ? 0.5 * last : last);
    const double scale = bar.lengthMm + 9.0 + textWidthMm(localNumber(cp::scaleText(panel.scale), texts), 8);
    return std::max({title, ticks, scale});
}

} // namespace stylos::plate
