// Placing a plate's panels, bars, rulers, legend and caption on the page.
#include "stylos/core/plate/PlateLayout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stylos::core::plate {

namespace {

std::string mm(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", value);
    return text;
}

double blockHeight(const PanelSpec& panel, double imageH)
{
    return kLetterBandMm + imageH + (panel.view == PanelView::Developpee ? kRulerBandMm : 0.0) + kBarBandMm;
}

/** Fills the bands of a panel whose image's top-left is (x, y). */
PanelBox place(const PanelSpec& panel, double x, double y, const std::array<double, 2>& size, const std::string& letter)
{
    PanelBox box;
    box.letter = letter;
    box.scaleText = scaleText(panel.scale);
    box.image = {x, y, size[0], size[1]};
    double below = box.image.bottom();
    if (panel.view == PanelView::Developpee) {
        box.ruler = true;
        box.rulerRect = {x, below, size[0], kRulerBandMm};
        below += kRulerBandMm;
    }
    box.bar = chooseScaleBar(panel.scale);
    // Labels sit above the bar (4 mm), the bar is 1.5 mm thick.
    box.barRect = {x, below + 5.0, box.bar.lengthMm, 1.5};
    return box;
}

} // namespace

std::string scaleText(double scale)
{
    char text[48];
    std::snprintf(text, sizeof text, "1:%.10g", scale); // never an exponent: 1:1000000, not 1:1e+06
    return text;
}

namespace {

Result<PlateLayout> layoutAt(const PlateSpec& spec, std::span<const std::array<double, 2>> imageMm, int legendRows,
                             double captionMm, const PanelLabelWidth& labelWidth, bool suggest, LayoutFailure* failure);

/**
 * The scales that would fit where the panels at @p spec's scales need too much height: the smallest factor f
 * (bisection) for which every panel at scale · f fits, the scales then rounded up (one per panel, placed panels
 * keeping theirs); empty when none fits below 1:1,000,000.
 */
std::vector<double> fittingScales(const PlateSpec& spec, std::span<const std::array<double, 2>> imageMm, int legendRows,
                                  double captionMm, const PanelLabelWidth& labelWidth)
{
    const auto fitsAt = [&](double f, PlateSpec* scaled) {
        PlateSpec s = spec;
        std::vector<std::array<double, 2>> images(imageMm.begin(), imageMm.end());
        for (std::size_t i = 0; i < s.panels.size(); ++i) {
            if (spec.panels[i].atMm) continue; // placed panels keep their place and scale
            s.panels[i].scale = f == 1.0 ? spec.panels[i].scale : std::ceil(spec.panels[i].scale * f);
            const double shrink = spec.panels[i].scale / s.panels[i].scale;
            images[i] = {imageMm[i][0] * shrink, imageMm[i][1] * shrink};
        }
        if (scaled) *scaled = s;
        return layoutAt(s, images, legendRows, captionMm, labelWidth, false, nullptr).ok();
    };
    double largest = 0;
    for (const PanelSpec& p : spec.panels)
        if (!p.atMm) largest = std::max(largest, p.scale);
    if (largest <= 0) return {}; // only placed panels: their scales are the layout file's
    double low = 1.0, high = 1e6 / std::max(largest, 1e-9);
    if (!(high > low) || !fitsAt(high, nullptr)) return {};
    for (int i = 0; i < 60 && high / low > 1.0 + 1e-9; ++i) {
        const double mid = std::sqrt(low * high);
        (fitsAt(mid, nullptr) ? high : low) = mid;
    }
    PlateSpec scaled;
    if (!fitsAt(high, &scaled)) return {};
    std::vector<double> scales;
    for (const PanelSpec& p : scaled.panels) scales.push_back(p.scale);
    return scales;
}

/** "A 1:7, B 1:13" (letters only for several panels; placed panels left out). */
std::string scalesText(const PlateSpec& spec, const std::vector<double>& scales)
{
    std::string text;
    for (std::size_t i = 0; i < scales.size() && i < spec.panels.size(); ++i) {
        if (spec.panels[i].atMm) continue;
        if (!text.empty()) text += ", ";
        if (spec.panels.size() > 1) text += std::string(1, char('A' + i)) + " ";
        text += scaleText(scales[i]);
    }
    return text;
}

} // namespace

Result<PlateLayout> layoutPlate(const PlateSpec& spec, std::span<const std::array<double, 2>> imageMm, int legendRows,
                                double captionMm, const PanelLabelWidth& labelWidth, LayoutFailure* failure)
{
    if (failure) *failure = {};
    return layoutAt(spec, imageMm, legendRows, captionMm, labelWidth, true, failure);
}

namespace {

Result<PlateLayout> layoutAt(const PlateSpec& spec, std::span<const std::array<double, 2>> imageMm, int legendRows,
                             double captionMm, const PanelLabelWidth& labelWidth, bool suggest, LayoutFailure* failure)
{
    PlateLayout out;
    out.page = spec.orientedPage();
    const double m = spec.marginMm;
    out.printArea = {m, m, out.page.widthMm - 2 * m, out.page.heightMm - 2 * m};
    const RectMm& area = out.printArea;
    const std::string areaText = mm(area.w) + " × " + mm(area.h) + " mm";
    // A named page is portrait unless landscape; a W×H page is as stated unless turned (PlateSpec::orientedPage).
    const bool stated = spec.pageName.find_first_of("xX") != std::string::npos;
    const std::string pageText = "the " + spec.pageName + (spec.landscape ? (stated ? " turned" : " landscape") : "") +
                                 " print area is " + areaText;
    if (imageMm.size() != spec.panels.size())
        return Error{ErrorCode::InvalidArgument, "layoutPlate: one image size per panel is needed"};
    // What a panel takes across its row: its image, or its title line and bar when they are wider.
    std::vector<double> blocks(spec.panels.size());
    for (std::size_t i = 0; i < blocks.size(); ++i)
        blocks[i] = std::max(imageMm[i][0], labelWidth ? labelWidth(i, spec.panels[i]) : 0.0);
    const bool letters = spec.panels.size() > 1;

    // Panels too large on their own.
    for (std::size_t i = 0; i < spec.panels.size(); ++i) {
        const PanelSpec& p = spec.panels[i];
        const auto& s = imageMm[i];
        const double needW = s[0], needH = blockHeight(p, s[1]);
        if (needW <= area.w + 1e-9 && needH <= area.h + 1e-9) continue;
        const double fixedH = needH - s[1];
        const double factor = std::max(s[0] / area.w, s[1] / std::max(1e-9, area.h - fixedH));
        const std::string name = letters ? std::string(1, char('A' + i)) + " " : std::string();
        const double smaller = std::ceil(p.scale * factor);
        // Past 1:1,000,000 (the largest scale a panel takes), or with no height left beside the panel's labels,
        // no scale fits: only a larger page does.
        const bool fits = area.h - fixedH > 1e-9 && smaller <= 1e6;
        if (failure)
            *failure = {LayoutFailure::Kind::PanelTooLarge, i, s, {}, area, out.page,
                        fits ? std::optional<double>(smaller) : std::nullopt, {}};
        const std::string remedy = fits
                                       ? "use " + scaleText(smaller) + " or smaller, or a larger page"
                                       : "no scale fits this page; use a larger page";
        return Error{ErrorCode::InvalidArgument, "panel " + name + "(" + panelViewName(p.view) + ", " +
                                                     scaleText(p.scale) + ") is " + mm(s[0]) + " × " + mm(s[1]) +
                                                     " mm; " + pageText + ": " + remedy};
    }

    // Rows of stacked panels.
    double y = area.y;
    std::vector<std::size_t> row;
    double rowW = 0, rowH = 0;
    out.panels.resize(spec.panels.size());
    auto flush = [&]() {
        double x = area.x + std::max(0.0, 0.5 * (area.w - rowW)); // a row wider than the area (labels) starts at its edge
        for (const std::size_t i : row) {
            const std::string letter = letters ? std::string(1, char('A' + i)) : std::string();
            out.panels[i] = place(spec.panels[i], x, y + kLetterBandMm, imageMm[i], letter);
            x += blocks[i] + kPanelGapMm;
        }
        if (!row.empty()) y += rowH + kPanelGapMm;
        row.clear();
        rowW = rowH = 0;
    };
    for (std::size_t i = 0; i < spec.panels.size(); ++i) {
        const PanelSpec& p = spec.panels[i];
        if (p.atMm) {
            const auto [x, top] = *p.atMm;
            const std::string letter = letters ? std::string(1, char('A' + i)) : std::string();
            out.panels[i] = place(p, x, top, imageMm[i], letter);
            const PanelBox& b = out.panels[i];
            const double bottom = b.barRect.bottom() + 4.0;
            if (x < 0 || top - kLetterBandMm < 0 || std::max(b.image.right(), b.barRect.right()) > out.page.widthMm + 1e-9 ||
                bottom > out.page.heightMm + 1e-9) {
                if (failure)
                    *failure = {LayoutFailure::Kind::PanelOutside, i, {b.image.w, bottom - top}, {x, top}, area, out.page,
                                std::nullopt, {}};
                return Error{ErrorCode::InvalidArgument, "panel " + letter + " at (" + mm(x) + ", " + mm(top) + ") mm is " +
                                                             mm(b.image.w) + " × " + mm(bottom - top) +
                                                             " mm with its bands and leaves the " + mm(out.page.widthMm) +
                                                             " × " + mm(out.page.heightMm) + " mm page"};
            }
            continue;
        }
        const double w = blocks[i], h = blockHeight(p, imageMm[i][1]);
        if (!row.empty() && rowW + kPanelGapMm + w > area.w + 1e-9) flush();
        rowW += (row.empty() ? 0.0 : kPanelGapMm) + w;
        rowH = std::max(rowH, h);
        row.push_back(i);
    }
    flush();
    // The stacked panels' bottom (placed ones count too, so the legend goes under everything).
    double bottom = area.y;
    for (const PanelBox& b : out.panels) bottom = std::max(bottom, b.barRect.bottom() + 4.0);
    if (legendRows > 0) {
        out.legend = {area.x, bottom + 2.0, area.w, kLegendRowMm * double(legendRows)};
        bottom = out.legend.bottom() + 2.0;
    }
    if (captionMm > 0) {
        out.caption = {area.x, bottom + 2.0, area.w, captionMm};
        bottom = out.caption.bottom();
    }
    // The legend and caption alone fill the print area: no scale can help, only a shorter caption or a larger page.
    const double texts = (legendRows > 0 ? kLegendRowMm * double(legendRows) + 4.0 : 0.0) + (captionMm > 0 ? captionMm + 2.0 : 0.0);
    if (bottom > area.bottom() + 1e-9 && captionMm > 0 && texts >= area.h) {
        if (failure) *failure = {LayoutFailure::Kind::CaptionTooTall, 0, {area.w, texts}, {}, area, out.page, std::nullopt, {}};
        return Error{ErrorCode::InvalidArgument, std::string(legendRows > 0 ? "the legend and the caption alone need "
                                                                            : "the caption alone needs ") + mm(texts) + " mm of height; " + pageText +
                                                     ": shorten the caption or use a larger page"};
    }
    if (bottom > area.bottom() + 1e-9) {
        const std::vector<double> fitting =
            suggest ? fittingScales(spec, imageMm, legendRows, captionMm, labelWidth) : std::vector<double>{};
        const std::string scales = scalesText(spec, fitting);
        if (failure)
            *failure = {LayoutFailure::Kind::TooTall, 0, {area.w, bottom - area.y}, {}, area, out.page, std::nullopt, fitting};
        return Error{ErrorCode::InvalidArgument, "the panels" + std::string(legendRows > 0 ? ", the legend" : "") +
                                                     (captionMm > 0 ? " and the caption" : "") + " need " +
                                                     mm(bottom - area.y) + " mm of height; " + pageText +
                                                     ": use a smaller scale" +
                                                     (scales.empty() ? std::string() : " (" + scales + ")") +
                                                     ", a larger page or the page " +
                                                     (stated ? (spec.landscape ? "as stated" : "turned")
                                                             : (spec.landscape ? "upright" : "in landscape"))};
    }
    return out;
}

} // namespace

std::vector<LegendCell> legendGrid(std::span<const int> classesPerLayer, int columns)
{
    columns = std::max(columns, 1);
    const int first = columns > 1 ? 1 : 0; // the classes' first column
    std::vector<LegendCell> cells;
    int row = -1;
    for (const int classes : classesPerLayer) {
        if (classes <= 0) continue;
        cells.push_back({0, ++row}); // the layer's title starts a row
        int column = first == 0 ? columns : first;
        for (int k = 0; k < classes; ++k) {
            if (column >= columns) ++row, column = first;
            cells.push_back({column++, row});
        }
    }
    return cells;
}

int legendGridRows(std::span<const int> classesPerLayer, int columns)
{
    const auto cells = legendGrid(classesPerLayer, columns);
    return cells.empty() ? 0 : cells.back().row + 1;
}

} // namespace stylos::core::plate
