#pragma once
/** @file
 * @brief Where everything of a plate goes on the page, in millimetres from the page's top-left corner: each
 *        panel's image at its exact size (the object's extent · 1000 / N), its letter, its "1:N" text, its scale
 *        bar (core/plate/ScaleBar.h) and, for a développée, its angle ruler; then the legend and the caption.
 *        Pure geometry: the painter (plate/PlatePainter) draws what this places.
 *
 * Packing: panels without "at_mm" go in rows inside the print area (page less margins), left to right while
 * they fit, each row centred; a panel block is its letter band, its image, its ruler (développée) and its bar
 * band. Then the legend (one row per class) and the caption band, under the panels. Panels with "at_mm" keep
 * their place and must lie inside the page.
 * Failure modes: InvalidArgument when something does not fit — the message says what and how big, and the
 * smallest scale that would fit a panel too large on its own ("panel A (développée, 1:10) is 314.2 × 80.1 mm;
 * the A4 print area is 180.0 × 267.0 mm: use 1:18 or smaller"); nothing is placed then.
 * Thread-safety: pure function.
 */
#include "stylos/core/plate/PlateSpec.h"
#include "stylos/core/plate/ScaleBar.h"

#include <array>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace stylos::core::plate {

struct RectMm {
    double x = 0, y = 0, w = 0, h = 0;
    double right() const { return x + w; }
    double bottom() const { return y + h; }
};

/** Heights of the bands around an image, mm. */
inline constexpr double kLetterBandMm = 7.0;
inline constexpr double kRulerBandMm = 7.0;
inline constexpr double kBarBandMm = 11.0;
inline constexpr double kPanelGapMm = 6.0;
inline constexpr double kLegendRowMm = 5.5;

struct PanelBox {
    RectMm image;          ///< the panel's image at its exact size
    std::string letter;    ///< "A", "B", … ; empty for a plate of one panel
    std::string scaleText; ///< "1:10"
    ScaleBar bar;          ///< segments == 0: no bar
    RectMm barRect;        ///< the bar itself: x, y top-left, w = bar.lengthMm, h its thickness
    bool ruler = false;    ///< an angle ruler 0–360° under the image (développées)
    RectMm rulerRect;      ///< its band
    double rulerDegrees = 360; ///< the angle the ruler spans, from the image's left edge (a fragment's arc: less)
};

/** @brief Where a legend entry goes: its column (0 = the first) and row. */
struct LegendCell {
    int column = 0, row = 0;
    bool operator==(const LegendCell&) const = default;
};

/**
 * @brief The legend's grid for layers of @p classesPerLayer classes each (a layer of 0 is left out), on @p columns
 *        columns (≥ 1): each layer's title in the first column of a row of its own, its classes in the columns after
 *        it, row after row (one column: the title, then a class a row), so that a layer's classes never sit beside
 *        another layer's title. Entries in order: a layer's title, then its classes, layer after layer.
 */
std::vector<LegendCell> legendGrid(std::span<const int> classesPerLayer, int columns);
/** @brief The rows legendGrid() uses. */
int legendGridRows(std::span<const int> classesPerLayer, int columns);

struct PlateLayout {
    PageSize page;
    RectMm printArea;
    std::vector<PanelBox> panels;
    RectMm legend;         ///< h = 0: no legend
    RectMm caption;        ///< h = 0: no caption
};

/** @brief Why a plate does not fit its page, as values, so that the workbench can say it in the user's language. */
struct LayoutFailure {
    enum class Kind {
        None,           ///< it fits, or failed for another reason (the Error says which)
        PanelTooLarge,  ///< panel `panel`'s image (`sizeMm`) is larger than the print area on its own
        PanelOutside,   ///< placed panel `panel` at `atMm` with its bands (`sizeMm`) leaves the page
        TooTall,        ///< the panels, legend and caption need `sizeMm[1]` mm of height
        CaptionTooTall, ///< the legend and caption alone need `sizeMm[1]` mm, the print area's height or more: no scale helps
    };
    Kind kind = Kind::None;
    std::size_t panel = 0;
    std::array<double, 2> sizeMm{};
    std::array<double, 2> atMm{};
    RectMm printArea;
    PageSize page;                   ///< the page as laid out (oriented)
    /** PanelTooLarge: the scale that would fit (nullopt: none does, only a larger page). */
    std::optional<double> smallerScale;
    /** TooTall: a scale for each panel that would make them fit together (placed panels keep theirs); empty when
     *  none was found. */
    std::vector<double> fittingScales;
};

/** @brief The width on paper (mm) that panel @p index's title line and its bar with "1:N" take at the panel's scale
 *         (the painter measures them; the bar's length and "1:N" change with the scale). */
using PanelLabelWidth = std::function<double(std::size_t index, const PanelSpec& panel)>;

/**
 * @brief Places @p spec's panels, whose images are @p imageMm (width, height on paper, mm, one per panel), with
 *        a legend of @p legendRows rows (0: none) and a caption band of @p captionMm (0: none). With @p labelWidth, a
 *        panel takes max(image, labels) in its row, so a small image's texts do not run into the next panel (a row
 *        wider than the print area starts at its left edge). When the panels, legend and caption need more height
 *        than the print area, the message gives scales that would fit (the flowing panels' scales times one
 *        factor, rounded up; their labels measured again at those scales). @p failure, when given, receives
 *        the same as values when the plate does not fit (the message stays English); Kind::None otherwise.
 */
Result<PlateLayout> layoutPlate(const PlateSpec& spec, std::span<const std::array<double, 2>> imageMm, int legendRows,
                                double captionMm, const PanelLabelWidth& labelWidth = {},
                                LayoutFailure* failure = nullptr);

/** @brief "1:10", "1:2.5". */
std::string scaleText(double scale);

} // namespace stylos::core::plate
