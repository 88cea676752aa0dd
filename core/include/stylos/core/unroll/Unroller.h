#pragma once
/** @file
 * @brief Unrolls a cloud onto its fitted surface: every point to (u, v, h) (UnrollMap.h), rasterised
 *        into a HeightField, small holes filled; the développée before shading.
 *
 * Steps of unrollCloud():
 *  1. Frame: e1 = defaultReferenceDir(axis direction) (UnrollMap.h), stored in the map.
 *  2. The band: a point is dropped (counted in pointsOffSurface) when the surface gives it no meridian
 *     coordinates (a revolution, beyond the meridian's reach), a coordinate is not finite, or it lies
 *     farther than the band from the surface: |h| > band, band = 0.15 × referenceRadius by default
 *     (82 mm on a 0.55 m drum: flutes, broken cavities and the outer ring of the bed faces stay; the
 *     centre of the bed faces, the far side of a hollow scan and far outliers go).
 *  3. The cut angle (radians from e1, counter-clockwise about the axis), unless given: where the fewest
 *     kept points lie — a histogram of their azimuths (all of them up to 4 Mi points, beyond that a
 *     deterministic pseudo-random sample of about 4 Mi) in 720 bins of 0.5°, smoothed by a circular
 *     moving sum over 11 bins (5.5°); the cut is the middle of the longest run of bins with the
 *     smallest sum (the first from e1 on a tie). A given cut is wrapped into [0, 2π).
 *  4. The sampling spacing d, estimated from the density of the kept points on the développée: a
 *     deterministic sample of at most 2 Mi of them counted in square cells of side c holding ~64
 *     sampled points each; s = c · √(rate / m), m the median count of the occupied cells — the
 *     spacing of a grid with that many points per cell, so about one point per pixel where one scan
 *     covers the surface (overlaps of scans and partly covered cells along the edges are outvoted).
 *     The pixel size s, unless given, is max(d, kLeafEdgesPerPixel × cloud.spacing): one point per pixel
 *     for a point file; for a .poct (cloud.spacing = the leaf edge) never less than three leaf edges, whose
 *     heights step by the leaf edge (at one edge a pixel the shading reads those steps as relief).
 *     Fewer than 16 kept points: InvalidArgument (give a pixel size), unless the cloud states a spacing.
 *     A given s is checked against d before anything is rasterised: when (s / d)² < kMinPointsPerPixel
 *     the image would be mostly empty, and it is refused (InvalidArgument) with the share of the surface
 *     it would cover and the pixel size that works (d).
 *  5. The image: width = ceil(2π·R / s) columns (u wraps; the last column is partial),
 *     v_top = s · ceil(max v / s) (rows aligned on multiples of s), height = floor((v_top − min v) / s)
 *     + 1 rows (v over the kept points). Over HeightField::kMaxSide a side: InvalidArgument "SOURCE:
 *     the développée would be W × H pixels (pixel size X mm); the limit is 32768 a side: give a larger
 *     --pixel-size", before anything is allocated.
 *  6. Per pixel, the outermost surface as seen from outside: a kept point lands in the pixel that
 *     map.pixelOf() gives (bit for bit); the points of a pixel whose h lies within depthTolerance
 *     (default 2·s) of the pixel's largest h are averaged (two passes over the points: the largest h,
 *     then the average, summed in fixed point — 1 nm — so the result does not depend on the thread
 *     count); deeper points (the bed face seen behind the rim) change nothing. These pixels are
 *     Measured; pixels without points stay Empty.
 *  7. shading::fillHoles with options.holes (small holes Filled, large ones and regions open to the
 *     border stay Empty) unless fillHoles is false; filledFraction = Filled / (Measured + Filled).
 *  8. The coverage (shading::measureCoverage, closing radius ⌈2 d / s⌉ pixels, at most 64): the share of
 *     the object's footprint that has a height. Then, unless fillHoles is false, the gaps inside that
 *     footprint are Filled whatever their extent (shading::fillFootprintGaps; the coverage is the one before). A given pixel size whose image covers less than
 *     options.minCoverage of it is refused (InvalidArgument, the coverage and the pixel size that works).
 *     The default pixel (with hole filling on), when its image covers less than kDefaultCoverage — scans
 *     merged from many views, whose density varies, as the Happy Buddha's —, is enlarged by 1.25, 1.5, 2
 *     and 3 in turn until it does (steps 5–8 again; the last is kept whatever its coverage).
 *
 * Cost: three passes over all the points (statistics; the largest h; the average), each a projection
 * per point (a few dot products and a square root, for a revolution a meridian lookup; the azimuth by a
 * branch-free polynomial, libm's atan2 only near column boundaries), plus one over the ≤ 2 Mi
 * sampled points when the spacing is estimated; split over options.threads workers in chunks of
 * 32 Ki points. Then the hole filling (single-threaded, shading::fillHoles). Memory besides the cloud:
 * the field (5 bytes a pixel) and 16 bytes a pixel while rasterising, plus at most 16 MiB per worker
 * for the density grid.
 *
 * Units: metres, radians. Thread-safety: reentrant; starts and joins its own threads. Progress in
 * [0, 1] (statistics to 0.3, spacing to 0.35, rasterising to 0.9, hole filling to 1) and cancel
 * (ErrorCode::Cancelled, checked every 32 Ki points and after the hole filling) through ProgressSink.
 * Failure modes (InvalidArgument, "SOURCE: problem" with SOURCE = cloud.source or "<memory>"): an empty
 * cloud, options out of range (a non-finite cut; a pixel size or band ≤ 0; a tolerance < 0; hole
 * options), no point within the band, too few points to estimate the spacing, an image too large;
 * OutOfBudget when the field or the rasteriser's 16 bytes a pixel cannot be allocated.
 */
#include "stylos/core/cloud/PointCloud.h"
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/shading/HoleFilling.h"
#include "stylos/core/unroll/UnrollMap.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <optional>

namespace stylos::core::unroll {

/** The default pixel of a .poct is at least this many leaf edges (step 4). */
inline constexpr double kLeafEdgesPerPixel = 3.0;
/** The default pixel is enlarged (×1.25, 1.5, 2, 3, in turn) while its image covers less of the footprint. */
inline constexpr double kDefaultCoverage = 0.9;
/** A given pixel size s with (s / d)² below this many points a pixel is refused before rasterising. */
inline constexpr double kMinPointsPerPixel = 0.1;

struct UnrollOptions {
    std::optional<double> cutAngle;  ///< radians about the axis from the reference direction; default: fewest points
    /** With the default cut: points that leave at least half the turn empty (a fragment) give an image of their
     *  arc alone (1° more each side), its left edge the cut; false, or a given cut: the whole circumference. */
    bool cropToPoints = true;
    std::optional<double> pixelSize; ///< metres (> 0); default: the sampling spacing of the cloud
    /** Largest |h| kept, metres (> 0); default 0.15 × the surface's reference radius. */
    std::optional<double> band;
    /** Points of a pixel within this depth of its outermost one are averaged, metres (≥ 0);
     *  default 2 × the pixel size. */
    std::optional<double> depthTolerance;
    shading::HoleFillOptions holes;  ///< which holes are filled
    bool fillHoles = true;
    /** A given pixel size whose image would cover less than this share of the object's footprint is
     *  refused (step 8); 0 = never. The default pixel size is not checked. */
    double minCoverage = 0.5;
    unsigned threads = 0;            ///< workers, the caller's included; 0 = hardware threads
};

struct UnrollReport {
    std::uint64_t points = 0;        ///< points of the cloud
    std::uint64_t pointsUsed = 0;    ///< points that landed in a pixel (kept by the band)
    std::uint64_t pointsOffSurface = 0; ///< dropped: farther than the band from the surface, no coordinates, or
                                        ///< beyond a fragment's arc (a sampled histogram's strays)
    std::uint64_t pointsHidden = 0;  ///< of pointsUsed, deeper than the tolerance behind their pixel's outermost point
    double cutAngle = 0.0;           ///< chosen or given, radians in [0, 2π): the image's left edge
    double arc = 6.283185307179586;  ///< radians the image spans: 2π, or less when cropped to a fragment's arc
    double pixelSize = 0.0;          ///< chosen or given, metres
    double band = 0.0;               ///< used, metres
    double depthTolerance = 0.0;     ///< used, metres
    double filledFraction = 0.0;     ///< Filled pixels / non-empty pixels
    double samplingSpacing = 0.0;    ///< d estimated from the density (step 4), metres; 0 when too few points
    double coverage = 0.0;           ///< share of the footprint with a height (step 8), in [0, 1]
    double seconds = 0.0;            ///< wall time of unrollCloud()
};

struct Unrolled {
    shading::HeightField field;
    UnrollMap map;
    UnrollReport report;
};

/** @brief Unrolls @p cloud about @p surface (see the file comment). */
Result<Unrolled> unrollCloud(const cloud::PointCloud& cloud, const Surface& surface, const UnrollOptions& options = {},
                             ProgressSink* progress = nullptr);

} // namespace stylos::core::unroll
