#pragma once
// Internal to the surface fit: trimmed Gauss–Newton fit of a cylinder or a cone to points.
#include "FitAzimuthProfile.h"
#include "FitParallel.h"
#include "FitRadialKernel.h"
#include "FitResidualHistogram.h"
#include "FitSample.h"
#include "FitSeed.h"

#include <array>
#include <cstdint>
#include <vector>

namespace stylos::core::unroll::detail {

/** @brief r(t) = radius + slope · t about an axis (fit frame); a cylinder has slope 0. */
struct RadialModel {
    FitLine axis;
    Eigen::Vector3d reference = Eigen::Vector3d::UnitX(); ///< e1 ⊥ axis: azimuth 0 of the profile
    double radius = 1.0;                                  ///< at axis.point, metres
    double slope = 0.0;                                   ///< dr/dt
};

/** @brief How well a model fits: over the inliers (|h| ≤ the threshold) unless stated. */
struct RadialStats {
    std::uint64_t points = 0; ///< points evaluated
    std::uint64_t inliers = 0;
    double rms = 0.0; ///< RMS of h = r − r(t) over the inliers, metres (profile not subtracted)
    double minT = 0.0, maxT = 0.0, meanT = 0.0; ///< axial coordinates of the inliers, metres
    double inlierFraction() const { return points ? double(inliers) / double(points) : 0.0; }
};

/**
 * @brief Fits r(t) = R + s·t by Gauss–Newton on the radial residuals hᵢ = ρᵢ − R − s·tᵢ − f(φᵢ) (ρ the
 *        distance from the axis, f the azimuthal profile, FitAzimuthProfile), minimising the truncated
 *        cost Σ min(hᵢ², τ²): only the inliers |hᵢ| ≤ τ enter the normal equations, and a step is
 *        halved until that cost does not grow. Parameters: the axis direction turned by (α, β) toward
 *        e1, e2 ⊥ it, its point moved by (x, y) along e1, e2 (then slid to the foot of the fit centre),
 *        R, and s for a cone; the axis ones are left out when the axis is given.
 *
 *        refine() iterates on a sample in memory: each round sets τ to the fixed point of
 *        τ = max(3 × 1.4826 × median{|h| ≤ τ}, floor) (FitResidualHistogram), so τ settles on the
 *        scale of the dominant band of residuals whatever the share of bed faces, breaks or clutter,
 *        and takes one Gauss–Newton step (the trial pass of the accepted step serves as the next
 *        round's pass). Phase 1 runs on every k-th point (250 k) with f = 0 until the step and τ
 *        settle; phase 2, on the whole sample, estimates f from the inliers every round (when the
 *        inliers go all round the axis; at most 8 times) and goes on until the step, τ and f settle
 *        (at most 30 rounds in all). polish() takes one Gauss–Newton step over every point with τ and f
 *        fixed, the statistics from the same pass. Work is split in fixed chunks of 16 Ki points
 *        reduced in order, so the result does not depend on the thread count.
 */
class FitCylinder {
  public:
    FitCylinder(bool cone, bool axisFree, unsigned threads, const Eigen::Vector3d& centre, double scale);

    /** @brief Iterates on @p sample from @p start and the threshold @p tau0 (metres).
     *  @return false when cancelled. */
    bool refine(const FitPoints& sample, const RadialModel& start, double tau0, const FitStage& stage);
    /** @brief One pass over the @p count points at @p xyz (cloud-local floats) with the current τ and f:
     *  the statistics at the current model, then its Gauss–Newton step. @return false when cancelled. */
    bool polish(const float* xyz, std::size_t count, const FitStage& stage);

    /** @brief The longest empty stretch of the axis (metres) between the inliers among about 250 k
     *  points of @p sample (fewer than 3 in a slice of 1/200 of their extent): separate objects. */
    double gap(const FitPoints& sample) const;

    /** Turns the axis round (direction reversed, slope negated): the same surface. */
    void reverse();

    const RadialModel& model() const { return m_model; }
    double threshold() const { return m_tau; }
    const RadialStats& stats() const { return m_stats; }
    int iterations() const { return m_iterations; }
    /** The model ran away (radius or slope not finite or absurd): not a cylinder or a cone. */
    bool degenerate() const { return m_degenerate; }
    /** Whether the azimuthal profile was subtracted (the points go all round the axis). */
    bool profiled() const { return m_profile.enabled(); }

  private:
    /** One pass: the sums, optionally the histogram of |h| and (bin, h + f) of the inliers for the profile. */
    bool pass(const float* xyz, std::size_t count, const RadialModel& model, double tau, bool equations, bool histogram,
              bool profile, const FitStage& stage, RadialSums& sums);
    /** Re-estimates the profile from the samples of the last pass; the largest change of f. */
    double updateProfile();
    /** The Gauss–Newton step for the free parameters from @p sums (zeros elsewhere). */
    std::array<double, 6> solve(const RadialSums& sums) const;
    RadialModel apply(const RadialModel& model, const std::array<double, 6>& step, double fraction) const;
    bool negligible(const std::array<double, 6>& step) const;
    void setStats(const RadialSums& sums);
    bool runaway(const RadialModel& model) const;

    bool m_cone;
    bool m_axisFree;
    unsigned m_threads;
    Eigen::Vector3d m_centre;
    double m_scale;
    RadialModel m_model;
    double m_tau = 0.0;
    RadialStats m_stats;
    int m_iterations = 0;
    bool m_degenerate = false;
    std::vector<FitResidualHistogram> m_histograms; ///< one per worker
    FitAzimuthProfile m_profile;
    int m_profileBins = 0;                       ///< fixed by the first profile that covers the circle
    std::vector<RadialSamples> m_profileSamples; ///< per chunk
};

/** @brief An orthonormal pair (e1, e2) ⊥ @p direction, a fixed function of it. */
void perpendicularFrame(const Eigen::Vector3d& direction, Eigen::Vector3d& e1, Eigen::Vector3d& e2);

} // namespace stylos::core::unroll::detail
