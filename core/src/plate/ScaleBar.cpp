#include "stylos/core/plate/ScaleBar.h"

#include <cmath>
#include <cstdio>

namespace stylos::core::plate {

namespace {

/** A number without trailing zeros: 0.5, 20, 2.5. */
std::string trimmed(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

} // namespace

std::string ScaleBar::tickLabel(int i) const
{
    if (segments <= 0 || i < 0 || i > segments) return {};
    const double value = lengthM / unitM * double(i) / double(segments);
    std::string label = trimmed(std::abs(value) < 1e-12 ? 0.0 : value);
    if (i == segments) label.append(" ").append(unit);
    return label;
}

ScaleBar chooseScaleBar(double scale)
{
    ScaleBar best;
    if (!(scale > 0) || !std::isfinite(scale)) return best;
    const double ideal = 0.5 * (kScaleBarMinMm + kScaleBarMaxMm);
    // Candidate lengths around the one whose paper length is ideal: 10^(k-1) … 10^(k+1) × {1, 2, 5}.
    const int k = int(std::floor(std::log10(ideal * scale / 1000.0)));
    for (int e = k - 1; e <= k + 1; ++e)
        for (const int m : {1, 2, 5}) {
            const double lengthM = double(m) * std::pow(10.0, e);
            const double mm = lengthM * 1000.0 / scale;
            if (mm < kScaleBarMinMm - 1e-9 || mm > kScaleBarMaxMm + 1e-9) continue;
            if (best.segments != 0 && std::abs(mm - ideal) >= std::abs(best.lengthMm - ideal)) continue;
            best.lengthM = lengthM;
            best.lengthMm = mm;
            best.segments = m == 2 ? 4 : 5;
        }
    if (best.segments == 0) return best;
    if (best.lengthM < 0.01 - 1e-12) best.unit = "mm", best.unitM = 0.001;
    else if (best.lengthM < 1.0 - 1e-12) best.unit = "cm", best.unitM = 0.01;
    else best.unit = "m", best.unitM = 1.0;
    return best;
}

} // namespace stylos::core::plate
