#pragma once
// Internal to the surface fit: a second seed for a cylinder's axis, from pairs of normals scored by
// inliers (RANSAC), for clouds whose surface of revolution holds only a minority of the normals (a
// drum fragment: its outer face is about a quarter of its points among fracture and bed faces, and
// the line complex of all normal lines then leans towards the fracture planes).
#include "FitSample.h"
#include "FitSeed.h"

#include <cstddef>
#include <cstdint>

namespace stylos::core::unroll::detail {

/** @brief How well an axis holds a sample: the densest band of distances from it. */
struct AxisScore {
    std::size_t inliers = 0; ///< points within ±band of radius whose normal is within 30° of radial
    double radius = 0.0;     ///< middle of the densest band of distances from the axis, fit-frame metres
};

/**
 * @brief Scores @p line (fit frame: sample coordinates less @p centre) on at most 4000 points of
 *        @p sample (a fixed stride): the distances ρ of the points whose normal is within 30° of the radial
 *        direction (a terrain's vertical normals fit a large circle only near its top), sorted; the window
 *        of width 2·@p band holding the most of them. Needs normals.
 */
AxisScore scoreCylinderAxis(const FitPoints& sample, const Eigen::Vector3d& centre, const FitLine& line, double band);

/**
 * @brief The best-scoring of @p trials candidate axes, each from two sample points i, j drawn from a
 *        counter-based generator of @p seed: direction nᵢ × nⱼ (pairs less than 17° apart skipped), through
 *        the intersection of the two normal lines projected on the plane ⊥ that direction (the centre of
 *        the circle they are normal to); the 8 best polished on their inliers (polishAxis). Deterministic.
 *        Needs normals; @p score gets the best's score.
 */
FitLine pairSeedAxis(const FitPoints& sample, const Eigen::Vector3d& centre, double band, int trials,
                     std::uint64_t seed, AxisScore& score);

/**
 * @brief @p line polished on its inliers (LO-RANSAC), 3 rounds while the score does not drop: the
 *        direction least aligned with their normals (smallest eigenvector of Σ n nᵀ), then the axis
 *        through the centre of the circle algebraically fitted to their projections. @p score gets its score.
 */
FitLine polishAxis(const FitPoints& sample, const Eigen::Vector3d& centre, const FitLine& line, double band,
                   AxisScore& score);

/**
 * @brief Whether the normals of @p line's inliers turn with their azimuth about it, as on a circle (the
 *        regression slope of the normal's azimuth on the point's, outward normals, within (0.5, 1.5)):
 *        false for a nearly flat cloud that a huge circle holds within the band (a terrain's normals stay
 *        vertical across the arc).
 */
bool normalsTurnWithTheArc(const FitPoints& sample, const Eigen::Vector3d& centre, const FitLine& line, double band,
                           const AxisScore& score);

} // namespace stylos::core::unroll::detail
