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

namespace {

struct Run {
    std::size_t start = 0, length = 0;
};

/**
 * The longest circular run of consecutive bins (of @p n) where @p inRun holds, the smallest start on a tie (a
 * run may wrap through bin 0); none when every bin is in a run. The walk starts just after a bin outside,
 * so no run is cut in two.
 */
template <typename InRun>
std::optional<Run> longestCircularRun(std::size_t n, InRun inRun)
{
    std::size_t outside = n;
    for (std::size_t i = 0; i < n && outside == n; ++i)
        if (!inRun(i)) outside = i;
    if (outside == n) return std::nullopt;
    Run best, run;
    for (std::size_t step = 1; step <= n; ++step) {
        const std::size_t i = (outside + step) % n;
        if (inRun(i)) {
            if (run.length++ == 0) run.start = i;
            continue;
        }
        if (run.length > best.length || (run.length == best.length && run.length > 0 && run.start < best.start))
            best = run;
        run.length = 0;
    }
    return best;
}

} // namespace

double chooseCutAngle(std::span<const std::uint64_t> counts)
{
    assert(counts.size() == kAzimuthBins && "chooseCutAngle(): histogram of the wrong size");
    const std::size_t n = counts.size();
    std::vector<std::uint64_t> smoothed(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k <= 2 * kAzimuthSmoothing; ++k)
            smoothed[i] += counts[(i + n + k - kAzimuthSmoothing) % n];
    const std::uint64_t least = *std::min_element(smoothed.begin(), smoothed.end());
    const auto lowest = longestCircularRun(n, [&](std::size_t i) { return smoothed[i] == least; });
    if (!lowest) return 0.0; // flat: no preferred azimuth
    const double middle = (double(lowest->start) + 0.5 * double(lowest->length)) / double(n) * kTwoPi;
    return middle >= kTwoPi ? middle - kTwoPi : middle;
}

std::optional<OccupiedArc> occupiedArc(std::span<const std::uint64_t> counts)
{
    assert(counts.size() == kAzimuthBins && "occupiedArc(): histogram of the wrong size");
    const std::size_t n = counts.size();
    const auto empty = longestCircularRun(n, [&](std::size_t i) { return counts[i] == 0; });
    if (!empty) return std::nullopt; // no points
    const std::size_t bestStart = empty->start, bestLength = empty->length;
    if (bestLength < n / 2) return std::nullopt;
    const std::size_t kept = n - bestLength + 2 * kArcMarginBins; // < n: bestLength ≥ 360
    const std::size_t first = (bestStart + bestLength + n - kArcMarginBins) % n; // the first occupied bin − margin
    return OccupiedArc{double(first) / double(n) * kTwoPi, double(kept) / double(n) * kTwoPi};
}

} // namespace stylos::core::unroll::detail
