#pragma once
/** @file
 * @brief Surface area on the object per annotation class, from the octree's cells (not from a développée's
 *        pixel count, which ignores relief and the distortion of the unrolling).
 *
 * Method ("crossing density"): a plane with unit normal n crosses, per square metre, |n|₁ / e² cubes of a
 * grid of edge e (|n|₁ = |nx| + |ny| + |nz|: a cube is crossed when its centre lies within e·|n|₁ / 2 of the
 * plane), so each cell a surface crosses stands for e² / |n|₁ m² of it on average. The estimate is made at the
 * *area level* — `levelsUp` (default 2) levels above closedSurfaceLevel() (ao/AoCells.h), where the cells
 * still cover the surface without holes and are several times wider than the scan's noise — with each
 * cell's pulled normal, and each cell's area is shared equally among the leaves under it. A class's area is
 * the sum of its leaves' shares.
 *
 * Measured accuracy (tests/core/AnnotationAreaTest.cpp, docs/annotation.md): a generated plain cylinder
 * (radius 0.2 m, 2 mm spacing, depth 8) — the whole lateral surface and a painted 0.1 m × 0.15 m patch within
 * 1.5 % of the analytic area (see docs/annotation.md for the figures); the développée pixel count would miss the flutes'
 * extra surface (≈ +2.6 % on the default fluted drum) and the relief of fractures entirely.
 * Assumptions: the sampling is roughly uniform within an area-level cell (the leaves split its area by
 * count) and the surface is nearly flat across one (curvature radius ≫ the cell edge).
 *
 * Units: square metres. Thread-safety: reentrant. Failure modes: Cancelled.
 */
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <span>
#include <vector>

namespace stylos::core::annotation {

struct LeafAreaOptions {
    int levelsUp = 2; ///< the area level is max(0, closedSurfaceLevel − levelsUp)
};

/** @brief Each leaf's share of the surface, m², in leaf order; their sum is the object's surface area. */
Result<std::vector<double>> leafAreas(const octree::PackedOctree& octree, const LeafAreaOptions& options = {},
                                      ProgressSink* progress = nullptr);

/** @brief Leaf count and area of one class id. */
struct ClassMeasure {
    std::uint64_t cells = 0;
    double areaM2 = 0.0;
};

/** @brief Cells and area for every id 0..255 (index = id). Precondition (asserted): equal sizes. */
std::vector<ClassMeasure> measureClasses(std::span<const std::uint8_t> labels, std::span<const double> areas);

} // namespace stylos::core::annotation
