#pragma once
// Internal to the surface fit: the seed axis, from the normal lines of a sample (line complex).
#include "FitParallel.h"
#include "FitSample.h"

#include "stylos/core/util/Result.h"

#include <Eigen/Core>

#include <string>

namespace stylos::core::unroll::detail {

/** @brief A line in the fit frame (cloud-local coordinates less the fit centre), unit direction. */
struct FitLine {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

/**
 * @brief Gives @p sample normals by k-nearest-neighbour PCA (normals::estimateNormals, k = 16,
 *        unoriented: the normal lines need no orientation). Errors: Cancelled or what the estimation
 *        returns, with @p source in the message.
 */
Status estimateSampleNormals(FitPoints& sample, const Eigen::Vector3d& centre, unsigned threads, const FitStage& stage,
                             const std::string& source);

/**
 * @brief The axis of the linear line complex that best contains the normal lines of @p sample
 *        (Pottmann & Randrup 1998): with lines (l, l̄) = (n, p × n) in coordinates centred on @p centre
 *        and divided by @p scale, minimises Σ wᵢ (c·l̄ᵢ + c̄·lᵢ)² over |c| = 1 — c̄ = −C⁻¹Bᵀc
 *        eliminated, c the eigenvector of the smallest eigenvalue of A − BC⁻¹Bᵀ (A = Σ l̄l̄ᵀ,
 *        B = Σ l̄lᵀ, C = Σ llᵀ, slightly regularised since a cylinder leaves the pitch free) — and
 *        reweights: lines whose residual exceeds 2.5 × 1.4826 × the median residual get weight 0
 *        (the broken cavity, noise, clutter), 10 rounds or until the axis stops moving. The axis is
 *        direction c through c × c̄ (the pitch component of c̄ dropped). Normal lines of any surface
 *        of revolution meet its axis; those of a bed face are parallel to it; both lie in the complex.
 *        The direction's sign is arbitrary. Deterministic.
 */
FitLine lineComplexAxis(const FitPoints& sample, const Eigen::Vector3d& centre, double scale);

} // namespace stylos::core::unroll::detail
