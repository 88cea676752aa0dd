#pragma once
/** @file
 * @brief Surface area on the object per annotation class, from the octree's cells (not from a développée's
 *        pixel count, which ignores relief and the distortion of the unrolling).
 *
 * Method (a kernel density of leaves on the surface): the samples are the cells of closedSurfaceLevel()
 * (ao/AoCells.h: they cover the surface without holes), each weighted by the leaves under it. Around every
 * *query cell* — `levelsUp` (default 2) levels above the samples — a plane is fitted to the samples within a
 * sphere of radius R = `radius` (default 1) query edges (4 sample edges) of a centre moved onto the plane
 * (three rounds: fit, project the query cell's own centroid, fit again). The leaves per m² there are
 * Σ w |nᵢ·n| K(ρ) / ∫K dA over the samples of the surface's slab (|h| ≤ 1.5 sample edges), with ρ the distance
 * along the plane, nᵢ the sample's normal (the surface beside it leans on the plane by |nᵢ·n|: flutes, creases)
 * and the smooth kernel K(ρ) = (1 − ρ²/R²)², ∫K dA = π R² / 3; each leaf of the query cell stands for the
 * inverse of that density. A class's area is the sum of its leaves' areas. The smooth kernel matters: the
 * samples sit on a lattice, and a hard disc counted them unevenly (−3.9 % to +4.3 % on the patch below).
 * With fewer than 8 leaves in reach or no plane (a line of samples), a query cell falls back to the crossing
 * density (a plane crosses |n|₁ / e² cubes of edge e per m²).
 *
 * Measured accuracy (tests/core/AnnotationAreaTest.cpp, docs/annotation.md), generated drums, noise 0.33 mm,
 * generator seeds 11, 3, 5: a 0.42 m × 0.06 m patch on a plain drum (r 0.2 m, h 0.3 m, 2 mm spacing) −0.67 %
 * to +0.35 % (octree depths 7 and 9), the whole drum −0.35 % to 0.00 %; a patch across 12 flutes of the default
 * fluted drum (4 mm spacing, 2.8 % more surface than its unrolled rectangle) −0.33 % to −0.60 % at depth 9,
 * −0.5 % to −1.35 % at depth 8 (about one sample a leaf). The crossing density it replaces read +1.26 % on
 * the plain patch and −4.8 % on the whole drum.
 * Assumptions and limits: the surface nearly flat across R (curvature radius ≫ R); at the open border of a
 * scan (a hole, a fragment not scanned all round) the kernel is only partly covered, so the leaves within R
 * of the border read too large (at most twice at the border itself). The développée's pixel count would ignore
 * the flutes' extra surface and the relief of fractures.
 * Cost: 20 bytes per sample cell and 48 per query cell; 8.3 M leaves (a 20 M-point drum at depth 11) in about
 * 8 s on one loaded core (docs/benchmarks.md).
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
    int levelsUp = 2;     ///< the query level is max(0, closedSurfaceLevel − levelsUp), levelsUp in 0..7
    double radius = 1.0; ///< the sphere's radius, in edges of the query level
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
