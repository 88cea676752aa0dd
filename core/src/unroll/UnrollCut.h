#pragma once
// Internal to the unroller: the default cut angle, where the fewest points lie.
#include <cstddef>
#include <cstdint>
#include <optional>
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

/** The arc the points occupy: from @p start (radians in [0, 2π)) over @p span radians counter-clockwise. */
struct OccupiedArc {
    double start = 0.0, span = 0.0;
};

/** Bins kept each side of the occupied bins (1°): the histogram is a sample of the points. */
inline constexpr std::size_t kArcMarginBins = 2;

/**
 * @brief From the raw histogram (kAzimuthBins counts over [0, 2π)): when the longest circular run of empty
 *        bins is at least half the turn — a fragment, not a drum, however broken — the rest of the turn
 *        with kArcMarginBins more each side; otherwise (or with no points) nothing.
 */
std::optional<OccupiedArc> occupiedArc(std::span<const std::uint64_t> counts);

} // namespace stylos::core::unroll::detail
