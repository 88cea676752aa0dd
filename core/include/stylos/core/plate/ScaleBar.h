#pragma once
/** @file
 * @brief The graphic scale bar of a plate panel at 1:N: a length L from {1, 2, 5}·10^k metres whose length on
 *        paper, L · 1000 / N millimetres, lies in [20, 60] mm (the one nearest 40 mm when several do; there is
 *        always one, since consecutive candidates differ by a factor of at most 2.5), cut into at least two
 *        equal segments, with the unit its labels are written in (mm below 1 cm, cm below 1 m, m above).
 *
 * A bar, not a "1:N" text alone: a figure that a journal rescales keeps a true bar (plates-annotation.md, B2).
 * Units: metres for object lengths, millimetres on paper. Thread-safety: pure functions.
 * Failure modes: none; a scale ≤ 0 or not finite gives an empty bar (segments == 0).
 */
#include <string>

namespace stylos::core::plate {

struct ScaleBar {
    double lengthM = 0;      ///< on the object, metres: {1, 2, 5} · 10^k
    double lengthMm = 0;     ///< on paper: lengthM · 1000 / scale, exactly
    int segments = 0;        ///< ≥ 2 equal segments (5 for 1 and 5, 4 for 2), 0 for no bar
    std::string unit;        ///< "mm", "cm" or "m"
    double unitM = 1;        ///< metres per unit (0.001, 0.01 or 1)
    /** @brief The label of tick @p i (0..segments) in the bar's unit, e.g. "0", "10", "20 cm" (unit on the last). */
    std::string tickLabel(int i) const;
};

inline constexpr double kScaleBarMinMm = 20.0;
inline constexpr double kScaleBarMaxMm = 60.0;

/** @brief The bar for a panel at 1:@p scale (see the file comment). */
ScaleBar chooseScaleBar(double scale);

} // namespace stylos::core::plate
