#pragma once
// Internal to the surface fit: the per-point loop of the cylinder / cone fit (FitCylinder).
#include "FitResidualHistogram.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace stylos::core::unroll::detail {

/** @brief Sums of one pass over some points (a chunk, or a whole pass once chunks are added in order). */
struct RadialSums {
    std::array<double, 21> jtj{}; ///< lower triangle of JᵀJ, row by row
    std::array<double, 6> jtr{};
    double cost = 0.0;                         ///< Σ min(h², τ²)
    double sumSquares = 0.0;                   ///< Σ h² over the inliers (profile subtracted)
    double sumTrueSquares = 0.0;               ///< Σ (r − r(t))² over the inliers (profile not subtracted)
    double sumT = 0.0, minT = 0.0, maxT = 0.0; ///< t over the inliers
    std::uint64_t inliers = 0, points = 0;
    /** Adds @p other (min / max for the extremes). */
    void add(const RadialSums& other);
};

/** @brief The model in the form the per-point loop wants. */
struct RadialKernel {
    double qx, qy, qz;                     ///< axis point, cloud-local
    double dx, dy, dz;                     ///< axis direction
    double e1x, e1y, e1z;                  ///< reference ⊥ direction (azimuth 0)
    double e2x, e2y, e2z;                  ///< direction × e1
    double radius, slope;                  ///< r(t) = radius + slope · t
    const double* profileValues = nullptr; ///< FitAzimuthProfile tables (when profiled)
    const double* profileSlopes = nullptr;
    int profileBins = 0;
    double profilePerRadian = 0.0;
};

/** (fastAngle × 2²⁸, r − r(t)) of an inlier, for FitAzimuthProfile. */
using RadialSamples = std::vector<std::pair<std::uint32_t, float>>;

/**
 * @brief Sums over the points [begin, end) of @p xyz (cloud-local floats): h = ρ − r(t) − f(φ); the
 *        inliers |h| ≤ τ enter the sums; with the Jacobian of h in (turn toward e1, turn toward e2,
 *        shift along e1, shift along e2, radius[, slope]) when equations are asked.
 */
using RadialAccumulate = void (*)(const float* xyz, std::size_t begin, std::size_t end, const RadialKernel& kernel,
                                  double tau, FitResidualHistogram* histogram, RadialSamples* samples, RadialSums& out);

/**
 * @brief The loop for these options: @p equations (JᵀJ, Jᵀh), @p histogram (|h| of every point),
 *        @p collect (the inliers' samples for the profile), @p profiled (subtract f), @p cone (the
 *        slope's column). Points go two at a time through the compiler's 2-lane vectors (SSE2 / NEON),
 *        each lane summing its own points, the lanes added at the end; an odd last point alone. Branch-free
 *        per point (inliers and outliers alternate unpredictably in a shuffled or cluttered cloud): the
 *        inlier test is a selection, which also keeps a non-finite point out of the sums. The result
 *        depends only on the points and [begin, end).
 */
RadialAccumulate radialAccumulate(bool equations, bool histogram, bool collect, bool profiled, bool cone);

} // namespace stylos::core::unroll::detail
