#pragma once
/** @file
 * @brief Fits the surface of revolution a développée is unrolled from — a cylinder, a cone or a
 *        general meridian — to millions of points, robust to bed faces, broken regions and outliers;
 *        or fits only the radius / profile about an axis the user gives.
 *
 * Method (to be documented precisely by the implementation): a seed axis from a random subsample with
 * normals (the cloud's own, or estimated on the subsample), e.g. the linear line complex of the normal
 * lines (Pottmann & Randrup 1998) or a RANSAC on pairs of normals; then trimmed Gauss–Newton
 * refinement on the points (a large subsample, then all points), re-weighting or trimming residuals
 * beyond a robust multiple of the median absolute residual, so bed faces and the broken cavity drop out.
 * Cylinder and cone have axis.point at the lowest axial coordinate of the inliers (the lower bed), so
 * v = t starts near 0. A revolution fits a smooth meridian (Meridian.h) from the bottom to the top.
 *
 * Failure: a cloud that is not remotely a surface of revolution gets InvalidArgument with the fit
 * residual in the message, e.g. "FILE: not a cylinder: RMS residual 212.4 mm for radius 0.35 m
 * (inliers 31 %)", never a garbage surface.
 *
 * Units: metres, radians. Thread-safety: reentrant; starts and joins its own threads. Progress and
 * cancel through ProgressSink (Cancelled).
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
    unsigned threads = 0; ///< worker threads, the caller's included; 0 = hardware threads
    std::uint64_t seed = 1; ///< of the subsampling: same cloud, same seed, same surface
};

/** @brief The fitted surface and how well it fits. */
struct FitReport {
    Surface surface = Surface::cylinder({}, 1.0).value();
    double rmsResidual = 0.0;      ///< RMS of h over the inliers, metres
    double inlierFraction = 0.0;   ///< points kept by the final trimming, in [0, 1]
    std::uint64_t points = 0;      ///< points of the cloud
    int iterations = 0;            ///< refinement iterations done
    double seconds = 0.0;          ///< wall time of the fit
};

/** @brief Fits @p options.kind to @p cloud (see the file comment). */
Result<FitReport> fitSurface(const cloud::PointCloud& cloud, const FitOptions& options = {},
                             ProgressSink* progress = nullptr);

} // namespace stylos::core::unroll
