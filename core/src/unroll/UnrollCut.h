#pragma once
// Internal to the unroller: the default cut angle, where the fewest points lie.
#include <cstddef>
#include <cstdint>
#include <span>

namespace stylos::core::unroll::detail {

/** Points the azimuth histogram is taken from at most: a deterministic sample (UnrollSample) beyond. */
inline constexpr double kAzimuthSamples = 4.0 * 1024 * 1024;
/** Bins of the azimuth histogram: 720, half a degree each. */
inline constexpr std::size_t kAzimuthBins = 720;
/** Half-width of the circular moving sum that smooths the histogram, bins (±2.5°, a 5.5° window). */
inline constexpr std::size_t kAzimuthSmoothing = 5;

/** Bin of an angle in [0, 2π) (clamped into the last bin against rounding). */
std::size_t azimuthBin(double angle);

/**
 * @brief The cut angle (radians in [0, 2π)) from a histogram of kAzimuthBins counts over [0, 2π):
 *        the histogram is smoothed by a circular moving sum over ±kAzimuthSmoothing bins; among the
 *        bins with the smallest sum, the longest circular run of consecutive such bins is taken (the
 *        first, counting from bin 0, on a tie; a run may wrap through bin 0), and the cut is at the
 *        middle of that run. All counts equal (e.g. none): 0 — the cut is the reference direction.
 */
double chooseCutAngle(std::span<const std::uint64_t> counts);

} // namespace stylos::core::unroll::detail
