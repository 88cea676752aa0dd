#pragma once
// Internal to the surface fit: a smooth meridian (and optionally the axis) of a general surface of
// revolution, by principal-curve iterations on the points' (t, r).
#include "FitParallel.h"
#include "FitResidualHistogram.h"
#include "FitSample.h"
#include "FitSeed.h"

#include "stylos/core/unroll/Meridian.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

namespace stylos::core::unroll::detail {

/** @brief How well a meridian fits: over the inliers (|h| ≤ the threshold). */
struct MeridianStats {
    std::uint64_t points = 0;
    std::uint64_t inliers = 0;
    double rms = 0.0;                    ///< RMS of h over the inliers, metres
    double tSpread = 0.0, rSpread = 0.0; ///< standard deviations of t and r over the inliers, metres
    double inlierFraction() const { return points ? double(inliers) / double(points) : 0.0; }
};

/**
 * @brief Fits a meridian polyline to points about an axis (fit frame), bottom (low t) to top.
 *
 * Start: the median radius of slices of t (FitBins). Then rounds of:
 *  1. project every point on the current meridian (Meridian::project; points beyond either end along
 *     the end's direction over its last 4 vertices) → (v, h);
 *  2. τ ← the fixed point of τ = max(3 × 1.4826 × median{|h| ≤ τ}, floor) (FitResidualHistogram);
 *  3. take the points within the capture band |h| ≤ c, where c starts at 3 % of the scale and halves
 *     each round down to 3τ (a ledge or a corner the slices missed is pulled in before the band
 *     narrows); their range of v (all but the 20 extreme ones at each end), in K equal bins
 *     (K = points / 400, 16..300, and each bin at least 4τ long: no detail finer than the scatter);
 *     beyond the current ends only as far as the bins are occupied (≥ 10 points and 2 % of the median
 *     bin) without a break, and sparse end bins let go: the curve grows over a bed face or up to an
 *     apex, never across empty space along a stray tangent;
 *  4. move each bin's centre point along the normal by the shorth midpoint of its h (the middle of the
 *     densest half: relief proud of the surface on less than half of a circle of latitude — a net,
 *     flutes — does not pull it, where a median creeps outward round after round), the moves smoothed
 *     by (1, 2, 1) / 4 (the moves, not the curve: nothing shrinks), r ≥ 0; the ends at the range's ends;
 *  5. when the axis is free, one Gauss–Newton step of the axis (direction turned toward e1, e2; point
 *     moved along e1, e2) on the inliers' h with the meridian held (∂h = n·∂(t, r)), limited to
 *     0.02 rad and 2 % of the scale per round;
 * until c = 3τ, τ moves less than 2 %, the RMS move is under 10 % of τ, the ends move less than τ and
 * the axis step is below 1e−5 (at most 16 rounds). Deterministic: chunks of fixed size reduced in order,
 * integer histograms.
 */
class FitMeridian {
  public:
    FitMeridian(bool axisFree, unsigned threads, const Eigen::Vector3d& centre, double scale);

    /** @brief Fits from @p axis on @p sample. @return false when cancelled; see failed(). */
    bool fit(const FitPoints& sample, const FitLine& axis, const FitStage& stage);
    /** Reverses the axis direction, the vertex order and t: the same surface. */
    void reverse();

    /** No meridian could be made (fewer than 2 bins of points). */
    bool failed() const { return m_failed; }
    const FitLine& axis() const { return m_axis; }
    /** Vertices (t, r) about axis().point, bottom to top. */
    const std::vector<Eigen::Vector2d>& vertices() const { return m_vertices; }
    double threshold() const { return m_tau; }
    const MeridianStats& stats() const { return m_stats; }
    int iterations() const { return m_iterations; }
    /** The longest stretch of the meridian (metres) where the sample has (almost) no inliers. */
    double gap() const { return m_gap; }

    /** Per-chunk sums of a projection pass. */
    struct Sums {
        Eigen::Matrix4d jtj = Eigen::Matrix4d::Zero();
        Eigen::Vector4d jtr = Eigen::Vector4d::Zero();
        double sumSquares = 0.0;
        double sumT = 0.0, sumTT = 0.0, sumR = 0.0, sumRR = 0.0; ///< of the inliers, about the axis point
        std::uint64_t inliers = 0, points = 0;
    };

  private:
    /** Projects @p count points; fills m_v / m_h when @p keep, the histogram, and the sums. */
    bool project(const float* xyz, std::size_t count, const Meridian& meridian, bool keep, bool equations,
                 const FitStage& stage, Sums& sums);
    std::optional<Meridian> makeMeridian(double reach) const;
    /** Step 3: a new polyline from the kept (v, h). false when too few bins hold points. */
    bool updateVertices(const Meridian& meridian);
    void startVertices(const FitPoints& sample);
    void moveAxis(const Sums& sums);
    void setStats(const Sums& sums);
    /** Resamples @p polyline at @p count points of uniform arc length (distinct consecutive points). */
    static std::vector<Eigen::Vector2d> resample(const std::vector<Eigen::Vector2d>& polyline, int count);

    bool m_axisFree;
    unsigned m_threads;
    Eigen::Vector3d m_centre;
    double m_scale;
    FitLine m_axis;
    std::vector<Eigen::Vector2d> m_vertices;
    double m_tau = 0.0;
    double m_moved = 0.0;    ///< largest (smoothed) median move of the last update, metres
    double m_endMoved = 0.0; ///< how far the ends moved in the last update, metres
    double m_capture = 0.0;  ///< the band of |h| the curve follows, halved each round down to 3τ
    double m_axisStep = 0.0; ///< size of the last axis step (radians + metres / scale)
    MeridianStats m_stats;
    int m_iterations = 0;
    double m_gap = 0.0;
    bool m_failed = false;
    std::vector<float> m_v, m_h; ///< per sample point; NaN when not projected
    std::vector<FitResidualHistogram> m_histograms;
};

/** Length of the polyline @p vertices, metres. */
double meridianLength(const std::vector<Eigen::Vector2d>& vertices);

} // namespace stylos::core::unroll::detail
