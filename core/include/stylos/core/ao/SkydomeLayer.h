#pragma once
/** @file
 * @brief The 3D skydome of a packed octree as one call, for every caller (stylos-cli ao, the workbench's
 *        Compute skydome, the demo): the cells of the level (default closedSurfaceLevel: the deepest whose
 *        cells still close the surface) as occluders, every leaf measured at its own centre and normal
 *        against them (DepthMap, leafReceivers; or, with leafReceivers off or Slices, each cell measured
 *        at its centre and its value spread to its leaves, valuesPerLeaf), written as the octree's "ambient" layer (.poct, atomically; the output
 *        may be the octree's own file) or as a PLY of leaf centres with an "ambient" property.
 *
 * Progress: reading the cells (and leaves) to about 0.1, the skydome to 0.9, writing to 1. A cancel is honoured until the
 * write starts (the last moment that leaves the output as it was); the writer then finishes or fails.
 * Memory: the cells of the level (AoCells), one float a leaf, and with leaf receivers 24 + 28 bytes a
 * leaf and 8 bytes a leaf per thread (the sums; two-sided: 16 per thread during the probe, then 8 more
 * a leaf for the probe's sums); the smoothing 20 bytes a leaf and its bins. Units: directions over the unit sphere;
 * values are fractions of the sky in [0, 1]. Thread-safety: reentrant (the octree is only read).
 * Failure modes: InvalidArgument (a level outside 0..depth, options out of range), the writer's errors
 * (Unwritable, OutOfBudget), Cancelled.
 */
#include "stylos/core/ao/AmbientOcclusion.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace stylos::core::ao {

enum class SkydomeOutput {
    Poct, ///< the octree with its "ambient" layer (replacing any older one)
    Ply,  ///< leaf centres, normals and an "ambient" float property
};

/** The widest smoothing, in edges of the level's cells: beyond it the smoothing averages whole parts of the object
 *  (and its cost grows with the cube of the radius). */
inline constexpr double MaxSmoothingEdges = 16.0;

/** The default smoothing's widest radius in sampling spacings (the leaves' median spacing): at a coarse --level
 *  the cells' 1.5 edges would span much of the object, and every leaf would be averaged with most others (the
 *  cost, receivers × neighbours, then grows with the square of the leaves). At the closed-surface level the
 *  default is 2–3 spacings, well within it. */
inline constexpr double MaxDefaultSmoothingSpacings = 8.0;

struct SkydomeLayerOptions {
    AoOptions ao;              ///< directions, method, bias, weighting, threads
    std::optional<int> level;  ///< the level of the cells; default closedSurfaceLevel(octree)
    /** DepthMap: measure every leaf at its own centre and normal against the level's cells (AoReceivers);
     *  false: measure each cell at its centre and give its value to the leaves under it. */
    bool leafReceivers = true;
    /** With leaf receivers: the values smoothed over neighbouring leaves of the same surface (SkydomeSmoothing.h)
     *  within this many edges of the level's cells (at the closed-surface level, one to two sampling
     *  spacings), at most MaxDefaultSmoothingSpacings sampling spacings; 0: the raw per-leaf values. */
    double smoothing = 1.5;
    /** The smoothing's radius in metres instead (0: off); unset: `smoothing` edges of the level's cells. Either
     *  way at most MaxSmoothingEdges edges (InvalidArgument beyond). */
    std::optional<double> smoothingRadius;
    SkydomeOutput output = SkydomeOutput::Poct;
};

struct SkydomeLayerReport {
    int level = 0;
    std::uint64_t cells = 0;     ///< cells of the level
    std::uint64_t leaves = 0;    ///< values written
    double meanAmbient = 0.0;    ///< mean over the leaves
    double readSeconds = 0.0;
    double aoSeconds = 0.0;      ///< the skydome, its smoothing included
    double smoothingRadius = 0.0;///< metres; 0 when not smoothed
    double smoothSeconds = 0.0;
    double writeSeconds = 0.0;
};

/**
 * @brief The skydome's value of every leaf of @p octree (leaf order), without writing anything: what
 *        computeSkydomeLayer writes. Fills @p report (when given) except writeSeconds. Progress: reading
 *        the cells to 0.1, the skydome to 1.
 */
Result<std::vector<float>> computeLeafSkydome(const octree::PackedOctree& octree, const SkydomeLayerOptions& options = {},
                                              ProgressSink* progress = nullptr, SkydomeLayerReport* report = nullptr);

/** @brief Computes the skydome of @p octree and writes it to @p output (see the file comment). */
Result<SkydomeLayerReport> computeSkydomeLayer(const octree::PackedOctree& octree, const std::filesystem::path& output,
                                               const SkydomeLayerOptions& options = {},
                                               ProgressSink* progress = nullptr);

} // namespace stylos::core::ao
