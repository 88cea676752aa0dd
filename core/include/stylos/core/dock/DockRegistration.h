#pragma once
/** @file
 * @brief Docks a fragment against the guides of a drum: its pose in the drum frame refined by
 *        point-to-plane registration of its outer face onto the guides' flute profile (FluteModel),
 *        solved with only the free unknowns, after a flute snap.
 *
 * Unknowns, about the fragment as it stands (its inliers' centroid c, at azimuth θc, distance ρc and
 * height zc in the drum frame; u_r radial, u_t tangential at c): theta — rotation about the drum axis;
 * z — translation along the axis; r — along u_r; tangent — along u_t; tilt_lean — rotation about u_t
 * through c (leans the piece in or out); tilt_roll — rotation about u_r through c (turns its flutes
 * sideways). A locked unknown is removed from the normal equations (its column is not there), never
 * solved for and zeroed afterwards. The flute profile does not change along the axis, so z has no
 * column at all: it is reported "unobservable" and left where the start put it, unless locked.
 *
 * Stages, each a robust Gauss–Newton (Tukey weights of width τ on the residuals, so fracture faces, the
 * bed face and broken edges carry no weight):
 *  1. envelope — the points against the cylinder of the profile's mean radius (r, tangent, tilts; θ
 *     and z do not move it), τ from max(30 mm, 4 × depth) down to 1.5 × depth;
 *  2. flute snap (FluteSnap.h) — unless theta is locked;
 *  3. profile — every free unknown against P(θ): residual (ρ − P(θ)) / |∇|, |∇| = √(1 + (P′/ρ)²),
 *     τ from 2 × depth down to 4.685 × 1.4826 × the median |residual| (a Tukey biweight at the noise),
 *     until the step moves no point by more than 10 nm, at most 60 iterations.
 * Unobservable: an unknown whose column is zero or whose eigen-direction of the scaled normal matrix
 * has an eigenvalue below 1e-9 of the largest (reported by name, held). Uncertainty: the square roots of
 * the diagonal of s²·(JᵀWJ)⁻¹ over the free unknowns, s² the weighted residual variance.
 *
 * Failure (InvalidArgument, naming the fragment's source): no flutes on the fragment (the snap's
 * strength below 0.15 — noise gives about 1/√n), fewer than 200 points near the drum's surface at the
 * start ("too far from the drum"), or no convergence in 60 iterations; the caller keeps the fragment
 * where it was. Units: metres, radians. Thread-safety: reentrant. Deterministic.
 */
#include "stylos/core/cloud/PointCloud.h"
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stylos::core::dock {

/** @brief The drum-frame unknowns, in the solve's order. */
enum class DockUnknown { Theta, Z, R, Tangent, TiltLean, TiltRoll };
inline constexpr int DockUnknowns = 6;
/** "theta", "z", "r", "tangent", "tilt_lean", "tilt_roll". */
const char* dockUnknownName(DockUnknown unknown);
/** Lock names as the command line takes them: the names above, "tilt" (both tilts), and "theta" for the fragment's
 *  place round the drum (Theta and Tangent: on a fragment the sideways slide is the same motion as the turn). Empty on
 *  an unknown name. */
std::vector<DockUnknown> dockUnknownsFromName(std::string_view name);

struct DockOptions {
    std::array<bool, DockUnknowns> locked{}; ///< by DockUnknown
    bool snap = true;                        ///< snap to the nearest flute before the profile stage
    std::size_t maxPoints = 100'000;         ///< fragment points used (fixed stride)
    int maxIterations = 60;                  ///< of the profile stage
};

struct DockUncertainty {
    DockUnknown unknown;
    double sigma = 0.0; ///< radians for theta and the tilts, metres otherwise
};

struct DockResult {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity(); ///< fragment file frame → drum file frame
    double rms = 0.0;             ///< RMS point-to-profile residual of the inliers, metres
    double fluteShift = 0.0;      ///< rotation about the axis from start to end, in flute pitches
    double snapRotation = 0.0;    ///< the snap's part of it, radians
    double snapStrength = 0.0;
    std::vector<DockUnknown> unobservable;
    std::vector<DockUncertainty> uncertainty; ///< per free, observable unknown
    int iterations = 0;           ///< Gauss–Newton iterations, all stages
    std::size_t inliers = 0;      ///< points with weight > 0 at the end
    double seconds = 0.0;
};

/** @brief Why a dock failed, as values, so that the workbench can say it (and what to do) in the user's language;
 *         the Error's message stays English. */
struct DockFailure {
    enum class Kind {
        None,           ///< no failure, or one not listed here (the Error says it)
        TooFewPoints,   ///< `points`: the fragment's, under 200
        TooFar,         ///< `points` of the fragment lie within `reachM` of the drum's surface at the start: under 200
        LeftTheDrum,    ///< the outer face stopped meeting the drum's surface while it was brought to it
        NoFlutes,       ///< the flute signal `strength` is under `needed`
        LostOuterFace,  ///< fewer than 200 points stayed on the flutes
        NotConverged,   ///< the registration did not settle in `iterations`
    };
    Kind kind = Kind::None;
    std::size_t points = 0;
    double reachM = 0.0;
    double strength = 0.0;
    double needed = 0.0;
    int iterations = 0;
    bool thetaLocked = false;     ///< NotConverged with θ locked: it may be held off its flute
};

/** Docks @p fragment (its file frame) placed by @p start into the drum file frame against @p guides
 *  (with a profile). See the file comment. @p failure, when given, receives why it failed (Kind::None otherwise). */
Result<DockResult> dockFragment(const cloud::PointCloud& fragment, const DrumGuides& guides,
                                const Eigen::Isometry3d& start, const DockOptions& options = {},
                                ProgressSink* progress = nullptr, DockFailure* failure = nullptr);

} // namespace stylos::core::dock
