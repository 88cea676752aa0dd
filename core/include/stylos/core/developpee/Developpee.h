#pragma once
/** @file
 * @brief The développée of a scan in one call, for every caller (stylos-cli unroll, the workbench's
 *        Développée dock, plates): load → fit the surface (or take the given axis, and radius) → unroll → fill the
 *        small holes → shade → contrast stretch. One options struct owns every default; the result keeps
 *        the height field with its Measured / Filled / Empty states, the full-precision shading (a plate can
 *        print it in 16 bits) and the pixel ↔ 3D map.
 *
 * Steps and progress: reading to 0.15 (core::cloud::loadPointCloud: a point file, or a .poct as one point
 * per leaf), fitting to 0.4 (core::unroll::fitSurface), unrolling and filling to 0.7
 * (core::unroll::unrollCloud, whose pixel-size rule and coverage check are the défaults here), shading to
 * 0.98, then 1. The points are released before shading.
 *
 * Memory: the cloud (24 bytes a point with normals) until unrolled, then the field (5 bytes a pixel) and
 * the shading (5 bytes a pixel). Units: metres and radians; everything is in the input file's frame.
 * Thread-safety: reentrant; starts and joins its own worker threads.
 * Failure modes: the reader's (NotFound, Unreadable, UnknownFormat, Malformed, Truncated, Empty),
 * InvalidArgument (options out of range, no surface fits, a pixel size that leaves the image mostly empty
 * or an image too large — with the pixel size that works), OutOfBudget, Cancelled.
 */
#include "stylos/core/cloud/PointCloud.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/developpee/DeveloppeeShading.h"
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/shading/HeightShading.h"
#include "stylos/core/shading/LightShading.h"
#include "stylos/core/shading/ShadedImage.h"
#include "stylos/core/unroll/SurfaceFit.h"
#include "stylos/core/unroll/UnrollMap.h"
#include "stylos/core/unroll/Unroller.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <filesystem>
#include <optional>
#include <string>

namespace stylos::core::developpee {

/** @brief Everything a développée depends on, with its defaults. */
struct DeveloppeeOptions {
    static constexpr int kMinDirections = 1;
    static constexpr int kMaxDirections = 4096;

    unroll::SurfaceKind surface = unroll::SurfaceKind::Cylinder;
    /** Given axis in the file's frame (any non-zero direction, normalised here): only the radius, slope or
     *  profile is fitted. A fragment needs it. */
    std::optional<unroll::Axis> axis;
    /** With a given axis: the unrolling radius (metres, > 0), e.g. the leading radius of the drum's guides, so a
     *  fragment and its drum unroll at the same scale. A cylinder is then that cylinder about the axis (nothing
     *  fitted; the fit report's RMS is that of the distances from it over the robust band of the lateral surface, τ = 3 × 1.4826 × median, as the fitter reports it; inlierFraction the share in the band); a cone or a surface of
     *  revolution is fitted and measures arc length at this radius (its referenceRadius). Ignored without an axis. */
    std::optional<double> radius;
    /** With a given axis and radius: the guides' taper, d radius / dt along the axis (DrumGuides::slope). A
     *  cylinder is then the cone of that radius at the axis point and that slope (nothing fitted). */
    std::optional<double> radiusSlope;
    Shading shading = Shading::Skydome;
    int directions = 40;                     ///< skydome azimuths, [kMinDirections, kMaxDirections]
    bool stretch = true;                     ///< skydome: stretch 1–99 % to [0, 1] (false: the exact Ω / 2π)
    /** Skydome: the Gaussian σ (metres) that smooths the heights before the horizon sweep, so that scanner noise
     *  does not read as relief (shading/HeightNoise.h); default: from the noise measured on the field
     *  (noiseSmoothingSigma); 0: the raw heights. The field kept in the result stays raw. */
    std::optional<double> smoothing;
    shading::LightShadingOptions light;      ///< light: azimuth, elevation (radians)
    shading::HeightShadingOptions height;    ///< height: the percentiles
    /** Metres per pixel; default: the unroller's rule (the sampling spacing, at least three leaf edges of a
     *  .poct). A given size that would leave the image mostly empty is refused. */
    std::optional<double> pixelSize;
    std::optional<double> cutAngle;          ///< radians about the axis; default: where the fewest points lie
    /** With the default cut, a fragment (points on at most half the turn) gets an image of its arc alone
     *  (unroll::UnrollOptions::cropToPoints); false: the whole circumference. */
    bool cropToPoints = true;
    bool fillHoles = true;                   ///< fill the small holes (unroll::UnrollOptions::holes)
    unsigned threads = 0;                    ///< worker threads; 0 = all cores; no effect on the result
    /** How a point file is read (text columns, one scan, the import frame: up axis, unit, offset); ignored
     *  for a .poct and by the overload that takes a cloud. "The input file's frame" is then the corrected one. */
    io::ReadOptions read;

    /** @brief InvalidArgument "SOURCE: problem" when a value is out of range (directions, pixel size,
     *         cut angle, light, axis), else success. */
    Status check(const std::string& source) const;
};

/** @brief Wall time of each step, seconds. */
struct DeveloppeeTimings {
    double load = 0.0;
    double fit = 0.0;
    double unroll = 0.0;
    double shading = 0.0;
    double total = 0.0;
};

/** @brief A développée: the field, its shading, its map and how they were made. */
struct Developpee {
    shading::HeightField field;   ///< heights off the surface (metres) and Measured / Filled / Empty states
    shading::ShadedImage shaded;  ///< [0, 1] per pixel, full precision; coverage 0 where the field is Empty
    unroll::UnrollMap map;        ///< pixel ↔ 3D, in the file's frame
    unroll::FitReport fit;
    unroll::UnrollReport unroll;  ///< pixel size, cut, sampling spacing, coverage, counts
    DeveloppeeTimings timings;
    double heightNoise = 0.0;     ///< σ of the height noise measured on the field, metres (skydome only; else 0)
    double smoothing = 0.0;       ///< the Gaussian σ the skydome's heights were smoothed with, metres (0: none)
};

/** @brief Runs the whole chain on the file @p input (see the file comment). */
Result<Developpee> computeDeveloppee(const std::filesystem::path& input, const DeveloppeeOptions& options = {},
                                     ProgressSink* progress = nullptr);

/** @brief The same on a cloud in memory (progress: fitting to 0.3, unrolling to 0.65, shading to 1). */
Result<Developpee> computeDeveloppee(const cloud::PointCloud& cloud, const DeveloppeeOptions& options = {},
                                     ProgressSink* progress = nullptr);

/** @brief What shadeField() measured and applied (skydome only; zeros for the other shadings). */
struct ShadingReport {
    double heightNoise = 0.0;     ///< metres
    double smoothing = 0.0;       ///< the Gaussian σ used, metres
};

/** @brief Shades @p field as @p options say (the skydome on smoothed heights and stretched when asked);
 *         @p report, when given, receives the noise measured and the smoothing used. */
Result<shading::ShadedImage> shadeField(const shading::HeightField& field, const DeveloppeeOptions& options,
                                        ProgressSink* progress = nullptr, ShadingReport* report = nullptr);

} // namespace stylos::core::developpee
