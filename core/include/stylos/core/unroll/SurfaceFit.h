#pragma once
/** @file
 * @brief Fits the surface of revolution a développée is unrolled from — a cylinder, a cone or a
 *        general meridian — to millions of points, robust to bed faces, broken regions and outliers;
 *        or fits only the radius / slope / meridian about an axis the user gives.
 *
 * Seed (no axis given). A stratified random sample of ≤ 100 k points with normals (the cloud's own, or
 * k = 16 PCA normals estimated on the sample). The axis of the linear line complex that best holds
 * their normal lines (Pottmann & Randrup, "Rotational and helical surface approximation for reverse
 * engineering", 1998): lines (l, l̄) = (n, p × n) in coordinates centred on the sample's centroid and
 * scaled by its RMS radius; minimise Σ (c·l̄ + c̄·l)² over |c| = 1 (c̄ eliminated, c the smallest
 * eigenvector of the Schur complement, C slightly regularised since a cylinder leaves the pitch free);
 * the lines beyond 2.5 robust σ of the residual are dropped and the complex refitted, 10 rounds. Axis:
 * direction c through c × c̄. The normal lines of any surface of revolution meet the axis and those of a
 * bed face are parallel to it, so both lie in the complex; the cavity's and the clutter's are trimmed.
 *
 * Cylinder and cone. The start: r(t) = R + s·t through the median radii of 8–128 axial slices of the
 * seed's sample (Theil–Sen; s = 0 for a cylinder), moved onto the densest band of radii about it (bed,
 * fracture faces and clutter spread out, the surface peaks), τ from 5 % of R. Then trimmed Gauss–Newton
 * on the radial residuals h = ρ − R − s·t − f(φ) (ρ the distance from the axis) over a stratified sample
 * of ≤ 1 M points, minimising Σ min(h², τ²) with steps halved until that cost does not grow, where τ is
 * the fixed point of τ = 3 × 1.4826 × median{|h| ≤ τ} (a histogram of |h|): the scale of the band of
 * residuals that holds the surface, whatever the share of bed faces (over half the points of a short
 * drum), breaks and clutter. Phase 1 (on 250 k of the sample, f = 0) until the step and τ settle; phase 2
 * (the whole sample) adds f, the median residual per azimuth bin with its mean and first harmonics
 * removed (those are R and the axis position): a fluted drum's flutes, 8 mm deep, leave only the noise, τ
 * comes down from ~10 mm to ~1 mm and the shallow rim of a broken cavity stops pulling the axis. f needs
 * ≥ 98 % of the bins of the arc the points cover (the circle less its longest empty run) to hold points,
 * and that arc to be at least 8 % of the circle. Last, one Gauss–Newton step over every
 * point with τ and f fixed; the statistics below come from that pass (taken just before its step, which
 * moves the axis by micrometres). R is the least-squares radius of the inliers: for a fluted drum the
 * mean radius of the flutes as the scan samples them, not the fillet radius.
 *
 * Revolution. A meridian (Meridian.h) from the median radii of axial slices, then principal-curve rounds
 * on a sample of ≤ 200 k points (FitMeridian.h): project on the meridian (points beyond an end along its
 * direction over the last vertices, so the curve grows over bed faces and up to an apex, but only across
 * occupied bins: not along a stray tangent through clutter), τ as above, cut the inliers' range of arc
 * length into bins at least 4τ long (≤ 300; finer detail than the scatter only wanders), move each bin's
 * point along the normal by the shorth midpoint of its h (the densest half: the omphalos's net, proud of
 * the ovoid on less than half of a circle, does not pull it), smoothing the moves by (1, 2, 1) / 4; the
 * band the curve follows starts at 3 % of the cloud's size and halves each round down to 3τ, so ledges
 * and corners missed by the slices are pulled in first. Without a given axis, one Gauss–Newton step of
 * the axis per round on the inliers' h with the meridian held. At most 16 rounds. The statistics (RMS,
 * inlier fraction) are the sample's: within a percent of all points' for a larger cloud, in a fraction of
 * the time (the unroller projects every point anyway). referenceRadius() is the meridian's
 * arc-length-weighted mean radius; its reach (how far the unroller finds points) is max(8τ, 5 % of the
 * meridian's size).
 *
 * Orientation, when the axis is not given: a cone's wider end and a revolution's wider end (the mean
 * radius of the lowest vs the highest quarter of the meridian's t range) at the bottom when they differ
 * by more than 5 % (cone) or 10 % (revolution) — columns taper upward, an omphalos sits on its plinth;
 * otherwise, and for a cylinder, the direction's largest world component is positive. A given axis
 * keeps its direction. axis.point lies at the lowest axial coordinate of the inliers (cylinder, cone:
 * the lower bed) or of the meridian (revolution), so v = t starts near 0; a given axis's point slides
 * along its line to it.
 *
 * Failure: InvalidArgument naming the source, with the fit residual, e.g.
 * "FILE: not a cylinder: RMS residual 212.4 mm for radius 0.35 m (inliers 31 %)", never a garbage
 * surface, when: fewer than 100 points; a given axis not finite or of zero direction; the fit runs away
 * (radius over 1000 × the cloud's size, |slope| > 100); the RMS residual exceeds 30 % of the (mean)
 * radius or 20 % of the cloud's size (the RMS distance of its points from their centroid) — for a
 * revolution 15 % and 10 %; fewer than 5 % inliers; the inliers leave a gap of more than 20 % of their
 * extent along the axis (or the meridian): separate objects; a revolution whose inliers spread less
 * than 2 % as much along the axis as across it: a plane; with a free axis, a cylinder or cone nearly
 * flat over the cloud — radius over 10 × its size, or an arc bulging (sagitta ≈ 0.75 size² / R) less
 * than 3 RMS residuals: an airborne terrain scan (Autzen: a 9.6 km cylinder, a 1.7 km cone) is refused,
 * a shallow arc of a large drum fits with its axis given. Measured (RMS / radius, RMS / size):
 * generated drums 0.5 %, 0.5 %; the omphalos as a revolution 0.06 %, 0.04 %; the Happy Buddha
 * (1.1 M points, a statuette) as a cylinder 25 %, 11 %, a cone 19 %, 9 %, a revolution 11 %, 5 %: all
 * accepted; the Igea head: cylinder 29 %, 22 % (refused), cone 27 %, 19 % (accepted), revolution 15 %,
 * 10 % (refused); the lion among vegetation: cylinder 24 %, 24 %, cone 29 %, 21 %, revolution 14 %, 11 %:
 * all refused. Garbage: a 1 m square (cylinder 33 %, 40 %; cone 22 %, 26 %; revolution: a plane); a 1 m
 * cube of random points (cylinder, cone 37 %, 28 %; revolution 24 %, 18 %); two Gaussian blobs 1 m apart
 * (51 %, 12 %; 61 %, 12 %); a thick spherical shell (38 %, 29 %; 20 %, 14 %); two spheres 1 m apart: a gap
 * of 0.59 m in 1.4 m.
 *
 * Second seed (cylinder, cone): a drum fragment's outer face holds about a quarter of its normals among
 * fracture and bed faces, and the line complex then leans towards the fracture planes (an axis 90° off,
 * radius 0.14 m, was accepted). So 400 candidate axes are also drawn from pairs of sample normals
 * (direction n₁ × n₂, through the crossing of the two normal lines projected ⊥ it), each scored by its
 * inliers — points within ±3 % of the cloud's size of the densest band of distances from the axis whose
 * normal is within 30° of radial —, the 8 best polished on their inliers (LO-RANSAC: the direction least
 * aligned with their normals, the circle through their projections), and the line complex's axis
 * polished and scored the same way. The pair seed replaces it when it holds 1.2 times its inliers and
 * its inliers' normals turn with their azimuth as on a circle (regression slope 0.5–1.5: a terrain's
 * normals stay vertical along a huge arc). On whole drums both agree; generated fragments (50° arcs)
 * then fit their drum's axis direction within 0.04° (test). The flute profile f (below) is estimated on
 * the covered arc when the points cover at least 8 % of the circle, so a fragment's flutes are removed
 * from the residuals as a drum's are. An arc of 50° still leaves the radius and the radial position of
 * the axis weakly determined together (7–20 mm): docking fixes them against the drum's guides.
 * With a given axis (FitOptions::axis) only the radius is fitted, and the radius start seeks the densest
 * band of radii, so a fragment's outer face is found (test).
 *
 * Determinism: the same cloud, options and seed give the same surface bit for bit, whatever the
 * thread count (samples from a counter-based generator; work in fixed chunks reduced in order; integer
 * histograms; normal estimation is itself thread-count independent). The seed changes which points the
 * samples hold (clouds over 100 k points), hence the last digits.
 *
 * Speed (stylos_fit_benchmark --points 30000000, idle 2-core 2.5 GHz Xeon dev box): 30 M points of a
 * broken fluted drum with 2 % clutter, no normals, fitted as a cylinder in 1.27–1.56 s (10 runs; one
 * thread 2.6 s), as a cone in 1.7 s, as a revolution in 1.0–1.1 s; a plain drum 1.2 s. Half of it is the
 * final pass over all points (about 36 ns of one core per point). Memory: the samples (≤ 1.3 M points, about
 * 50 MB with the per-point work arrays) beside the cloud.
 * Units: metres, radians. Thread-safety: reentrant; starts and joins its own threads. Progress (rising
 * to 1) and cancel through ProgressSink, checked every 16 Ki points (Cancelled).
 */
#include "stylos/core/cloud/PointCloud.h"
#include "stylos/core/unroll/Surface.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <optional>

namespace stylos::core::unroll {

/** @brief Parameters of the fit. */
struct FitOptions {
    SurfaceKind kind = SurfaceKind::Cylinder;
    /** Given axis (world, unit direction): only the radius, slope or meridian is fitted. */
    std::optional<Axis> axis;
    unsigned threads = 0;   ///< worker threads, the caller's included; 0 = hardware threads; no effect on the result
    std::uint64_t seed = 1; ///< of the subsampling: same cloud, same seed, same surface (bit for bit)
};

/** @brief The fitted surface and how well it fits. */
struct FitReport {
    Surface surface = Surface::cylinder({}, 1.0).value();
    double rmsResidual = 0.0;    ///< RMS of h over the inliers (r − r(t), or the meridian's h), metres
    double inlierFraction = 0.0; ///< points kept by the final trimming, in [0, 1]
    std::uint64_t points = 0;    ///< points of the cloud
    int iterations = 0;          ///< Gauss–Newton rounds (cylinder, cone) or principal-curve rounds done
    double seconds = 0.0;        ///< wall time of the fit
};

/** @brief Fits @p options.kind to @p cloud (see the file comment). Errors: InvalidArgument (see
 *         Failure), Cancelled, or the normal estimation's OutOfBudget. */
Result<FitReport> fitSurface(const cloud::PointCloud& cloud, const FitOptions& options = {},
                             ProgressSink* progress = nullptr);

} // namespace stylos::core::unroll
