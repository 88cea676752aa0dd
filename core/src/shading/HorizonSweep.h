#pragma once
// Internal to the skydome: the linear-time horizon of every pixel of a band of rasterised lines.
#include "stylos/core/shading/DirectionRaster.h"
#include "stylos/core/shading/HeightField.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace stylos::core::shading::detail {

/**
 * A vertex of the upper convex hull of a profile: position t along the walk and height h (metres),
 * and the slope dh/dt of the hull edge that arrives at it from the vertex below it on the stack.
 */
struct HullPoint {
    double t;
    double h;
    double slope;
};

/** Lines swept together: the pixels of one step of a band are neighbours in memory. */
constexpr int kBandLines = 64;

/** Scratch of one worker: kBandLines interleaved hull stacks (level k of line j at k·kBandLines + j). */
struct BandScratch {
    std::vector<HullPoint> stacks;
    int tops[kBandLines] = {};
    /** Room for the sentinel (level 0) and a whole line. */
    explicit BandScratch(int longestLine) : stacks(std::size_t(longestLine + 2) * kBandLines, HullPoint{0.0, 0.0, 0.0}) {}
};

/**
 * @brief Walks lines [firstLine, firstLine + count) (count ≤ kBandLines) of @p raster and calls
 *        sink(element index, rise, run) for every non-empty pixel p, where rise / run is the largest
 *        slope (h_q − h_p) / dist(p, q) over the pixels q of p's profile (DirectionRaster.h), rise in
 *        metres and run > 0 in metres; (0, 1) when the profile has no non-empty pixel. Empty pixels are
 *        skipped: they neither get a value nor occlude.
 *
 * Each line is walked against the direction, so a pixel comes after its whole profile; its stack keeps
 * the upper convex hull of the points visited (t increasing along the walk, so dist(p, q) = t_p − t_q).
 * The highest slope from p to the hull is at the tangent vertex; the vertices above it on the stack
 * (nearer p) lie under the segment from p to the tangent and leave the hull when p joins it, so one
 * pop loop both finds the tangent and restores convexity: amortised O(1) per pixel. A vertex v leaves
 * when p is on or above the line of v's incoming edge, h_p ≥ h_v + slope_v (t_p − t_v): one vertex read
 * per test, and the new vertex's slope is the horizon slope just computed. Decisions between nearly
 * collinear vertices may differ from exact arithmetic by rounding, so may the horizon (by ~1e-16
 * relative). A branch-free variant (two unconditional pops, then a loop) measured 40–50 % slower:
 * speculation past the well-predicted part of the loop beats a longer dependency chain.
 *
 * The band's lines advance together one major index at a time: the pixels of a step are consecutive
 * along the minor axis (contiguous in memory for row-major lines, one row apart otherwise), so a band
 * touches a few cache lines and pages per step instead of one per pixel when a single line crosses
 * the image diagonally.
 */
template <typename Sink>
void sweepBand(const DirectionRaster& raster, int firstLine, int count, const float* heights,
               const PixelState* states, int width, double pixelSize, BandScratch& scratch, Sink&& sink)
{
    const bool columnMajor = raster.columnMajor();
    // t = −along · pixelSize grows along the walk (which runs against the direction).
    const double tMajor = -(columnMajor ? raster.columnStep() : raster.rowStep()) * pixelSize;
    const double tMinor = -(columnMajor ? raster.rowStep() : raster.columnStep()) * pixelSize;
    const auto [f0, l0] = raster.lineSpan(firstLine);
    const auto [f1, l1] = raster.lineSpan(firstLine + count - 1);
    const int first = std::min(f0, f1), last = std::max(l0, l1);
    const int i0 = raster.intercept(firstLine), minorLast = raster.minorSize() - 1;
    // Level 0 of every stack is a sentinel: before every point of the grid, so low that no slope
    // toward it is ever positive, and with an infinite incoming slope so that it is never popped.
    HullPoint* stacks = scratch.stacks.data();
    int* tops = scratch.tops;
    const double extent = (double(raster.majorSize()) + raster.minorSize() + 1.0) * pixelSize;
    for (int j = 0; j < count; ++j) {
        tops[j] = 0;
        stacks[j] = HullPoint{-extent - 1.0, -1e30, std::numeric_limits<double>::infinity()};
    }

    auto step = [&](int a) {
        const int o = raster.offset(a);
        const int bLo = std::max(0, i0 + o), bHi = std::min(minorLast, i0 + count - 1 + o);
        const double ta = a * tMajor;
        for (int b = bLo; b <= bHi; ++b) {
            const std::size_t i = columnMajor ? std::size_t(b) * std::size_t(width) + std::size_t(a)
                                              : std::size_t(a) * std::size_t(width) + std::size_t(b);
            if (states[i] == PixelState::Empty) continue;
            const int j = b - i0 - o;
            HullPoint* stack = stacks + j;
            const double t = ta + b * tMinor;
            const double h = heights[i];
            int top = tops[j];
            for (;;) {
                const HullPoint& v = stack[std::size_t(top) * kBandLines];
                if (h >= v.h + v.slope * (t - v.t))
                    --top;
                else
                    break;
            }
            const HullPoint& tangent = stack[std::size_t(top) * kBandLines];
            const double rise = tangent.h - h, run = t - tangent.t;
            sink(i, rise, run); // the sentinel gives a rise of about −1e30
            ++top;
            stack[std::size_t(top) * kBandLines] = HullPoint{t, h, -rise / run};
            tops[j] = top;
        }
    };
    if (raster.majorStep() > 0) {
        for (int a = last - 1; a >= first; --a) step(a);
    } else {
        for (int a = first; a < last; ++a) step(a);
    }
}

} // namespace stylos::core::shading::detail
