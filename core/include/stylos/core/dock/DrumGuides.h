#pragma once
/** @file
 * @brief The guides of an intact fluted drum: the axis of its leading cylinder (a cone when the drum
 *        tapers), the leading radius (the envelope of the fillets between the flutes), the flute count, depth
 *        and phase, and each flute's bottom line, parallel to the axis (along the cone's generator). The drum the fragments of a ruined one are docked against.
 *
 * Method. The axis comes from the cylinder fit (unroll/SurfaceFit.h), or is the one given (then only the
 * radius is fitted). Azimuths θ are measured about the axis direction d from the reference direction
 * e₁ = unroll::defaultReferenceDir(d), the développée's own (so the phase reads the same on the
 * développée of the same axis); e₂ = d × e₁. The lateral points are those within a band of
 * ±max(3 %·R, 4 × fit RMS) of the fitted radius R whose axial coordinate lies inside the drum, 2 % of its height (at least 5 mm) away from
 * the bed faces (the 1st–99th percentile of the band's axial coordinates); at most 2 M of them, taken
 * with a fixed stride. Their radial heights h = ρ − median ρ feed the single-frequency sums
 * S_N = Σ h·e^(−iNθ) for N = 12..64 (or the given count); the count is the N with the largest
 * |S_N| / Σ 1. The phase φ₀ (the azimuth of the bottom of flute 0, in [0, 2π/N)) starts at
 * (π − arg S_N) / N and is refined on the folded profile: the median ρ in 64 bins of
 * (θ − φ₀) mod 2π/N, the vertex of a parabola least-squares fitted to the bins within a quarter pitch of
 * the bottom (twice). The leading radius is the mean of the 3 highest bin medians (the fillets), the
 * depth that radius minus the parabola's vertex. Medians make the broken region, the claw band and the
 * registration offsets between scans only shift a few points per bin.
 *
 * A tapering drum. The heights of the lateral points above the folded profile are binned along the axis
 * (16 bins, medians) and a line fitted through them; when the radius changes by at least 0.5 mm over the
 * bins' span and the slope is at least 4 times its standard error, the drum is a cone: each point's ρ is
 * scaled back to the axis point's cross-section (ρ / (1 + slope·t / R)), the phase and the profile made
 * again, and the slope refined (3 rounds). A cylinder keeps slope 0 (the line is not significant: generated
 * drums without taper, their broken region and claw band included, stay below it).
 *
 * Flute k's bottom line: the point at azimuth φ₀ + k·2π/N, distance radius − depth from the axis, level
 * with the axis point; the axis direction, or on a cone its generator (leaning by (radius − depth)·slope / R). rms: the RMS of ρ minus the folded profile (interpolated)
 * over the lateral points within 5 robust σ.
 *
 * Failure (InvalidArgument, the message names the cloud's source): the fit refuses the cloud (not a
 * drum, with its residual); fewer than 1000 lateral points; a given flute count outside 3..1000; no
 * flute frequency standing out of the noise: the best |S_N| / Σ 1 below 30 × the noise level
 * √(Σ h²) / Σ 1 or below 8 × the median over the scanned N (a plain cylinder, a wrong given count).
 * Measured on generated drums: 200–270 and 70–110; a plain one (its broken region and claw band): 11 and 2.
 * Cancelled through @p progress.
 *
 * Units: metres, radians. Thread-safety: reentrant; the fit starts and joins its own threads. Memory:
 * the fit's samples plus 40 bytes per lateral point kept (≤ 80 MB). Deterministic for a cloud,
 * options and seed.
 */
#include "stylos/core/cloud/PointCloud.h"
#include "stylos/core/scene/Fragment.h"
#include "stylos/core/unroll/Surface.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

namespace stylos::core::dock {

/** @brief What fitDrumGuides() is told. */
struct GuideOptions {
    std::optional<unroll::Axis> axis; ///< given axis (world, unit direction); only the radius is fitted
    int flutes = 0;                   ///< given flute count (3..1000); 0 = found among 12..64
    unsigned threads = 0;             ///< of the surface fit; 0 = hardware threads
    std::uint64_t seed = 1;           ///< of the surface fit's sampling
};

/** @brief A line in world coordinates: a point and a unit direction, metres. */
struct FluteLine {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

/** @brief The guides of a drum, in the cloud's (world) frame. */
struct DrumGuides {
    unroll::Axis axis;            ///< the leading cylinder's axis; point at the lower bed (as fitted)
    Eigen::Vector3d reference = Eigen::Vector3d::UnitX(); ///< e₁: azimuth 0, unit, ⊥ axis
    double radius = 0.0;          ///< leading radius at the axis point: the envelope of the fillets, metres
    /** d(leading radius)/dt along the axis direction: a tapering drum's cone (the cross-section at t is the
     *  axis point's scaled by 1 + slope·t / radius); 0 for a cylinder. Dimensionless. */
    double slope = 0.0;
    double fluteDepth = 0.0;      ///< from the leading radius to a flute's bottom, metres
    int flutes = 0;               ///< flute count
    double phase = 0.0;           ///< azimuth of flute 0's bottom from reference, radians, in [0, 2π/flutes)
    std::vector<FluteLine> fluteLines; ///< flute k's bottom line, k = 0..flutes−1 counter-clockwise about axis
    /** The flute profile: the median distance from the axis in ProfileBins equal bins of one pitch centred
     *  on a flute bottom (bin b's centre at (b + ½ − ProfileBins/2)·pitch/ProfileBins from it), metres;
     *  what a fragment is registered against (FluteModel). Empty bins hold their neighbours' mean. */
    std::vector<double> profile;
    static constexpr int ProfileBins = 64;
    double rms = 0.0;             ///< RMS of the radial residual against the flute profile, metres
    double fitRms = 0.0;          ///< the cylinder fit's RMS residual, metres
    double strength = 0.0;        ///< |S_N| / Σ 1 over the noise level √(Σ h²) / Σ 1 (≥ 30 when accepted)
    std::uint64_t lateralPoints = 0; ///< lateral points used
    double seconds = 0.0;         ///< wall time, the fit included
};

/** @brief Sets @p g's flute lines from its axis, reference, radius, slope, depth, count and phase. */
void placeFluteLines(DrumGuides& g);

/** @brief How the workbench fits the guides of @p drum, a scene fragment whose guides were fitted before: about
 *         its first axis guide, with as many flutes as it has groove guides; nullopt without an axis guide or with
 *         fewer than 3 grooves (its guides cannot be fitted again, nor a fragment docked against it). */
std::optional<GuideOptions> guideOptionsFor(const scene::Fragment& drum);

/** @brief Fits the guides of the drum @p cloud (see the file comment). Errors: InvalidArgument naming
 *         the cloud's source, Cancelled, or the normal estimation's OutOfBudget. */
Result<DrumGuides> fitDrumGuides(const cloud::PointCloud& cloud, const GuideOptions& options = {},
                                 ProgressSink* progress = nullptr);

} // namespace stylos::core::dock
