#include "UnrollCut.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <vector>

namespace stylos::core::unroll::detail {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
}

std::size_t azimuthBin(double angle)
{
    const double bin = std::floor(angle / kTwoPi * double(kAzimuthBins));
    if (!(bin >= 0.0)) return 0;
    return std::min(kAzimuthBins - 1, std::size_t(bin));
}

double chooseCutAngle(std::span<const std::uint64_t> counts)
{
    assert(counts.size() == kAzimuthBins && "chooseCutAngle(): histogram of the wrong size");
    const std::size_t n = counts.size();
    std::vector<std::uint64_t> smoothed(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k <= 2 * kAzimuthSmoothing; ++k)
            smoothed[i] += counts[(i + n + k - kAzimuthSmoothing) % n];
    const std::uint64_t least = *std::min_element(smoothed.begin(), smoothed.end());

    // Walk once round the circle from just after a bin above the minimum, so no run is cut in two.
    std::size_t above = n;
    for (std::size_t i = 0; i < n && above == n; ++i)
        if (smoothed[i] != least) above = i;
    if (above == n) return 0.0; // flat: no preferred azimuth

    std::size_t bestStart = 0, bestLength = 0, runStart = 0, runLength = 0;
    for (std::size_t step = 1; step <= n; ++step) {
        const std::size_t i = (above + step) % n;
        if (smoothed[i] == least) {
            if (runLength++ == 0) runStart = i;
            continue;
        }
        if (runLength > bestLength || (runLength == bestLength && runLength > 0 && runStart < bestStart)) {
            bestStart = runStart;
            bestLength = runLength;
        }
        runLength = 0;
    }
    const double middle = (double(bestStart) + 0.5 * double(bestLength)) / double(n) * kTwoPi;
    return middle >= kTwoPi ? middle - kTwoPi : middle;
}

std::optional<OccupiedArc> occupiedArc(std::span<const std::uint64_t> counts)
{
    assert(counts.size() == kAzimuthBins && "occupiedArc(): histogram of the wrong size");
    const std::size_t n = counts.size();
    std::size_t occupied = n;
    for (std::size_t i = 0; i < n && occupied == n; ++i)
        if (counts[i] != 0) occupied = i;
    if (occupied == n) return std::nullopt; // no points
    // Walk once round from an occupied bin: every empty run is whole.
    std::size_t bestStart = 0, bestLength = 0, runStart = 0, runLength = 0;
    for (std::size_t step = 1; step <= n; ++step) {
        const std::size_t i = (occupied + step) % n;
        if (counts[i] == 0) {
            if (runLength++ == 0) runStart = i;
            continue;
        }
        if (runLength > bestLength) bestStart = runStart, bestLength = runLength;
        runLength = 0;
    }
    if (bestLength < n / 2) return std::nullopt;
    const std::size_t kept = n - bestLength + 2 * kArcMarginBins; // < n: bestLength ≥ 360
    const std::size_t first = (bestStart + bestLength + n - kArcMarginBins) % n; // the first occupied bin − margin
    return OccupiedArc{double(first) / double(n) * kTwoPi, double(kept) / double(n) * kTwoPi};
}

} // namespace stylos::core::unroll::detail
