#pragma once
/** @file
 * @brief The surface each leaf stands for: a per-leaf "spacing" h (metres) such that h² is the leaf's share
 *        of the scanned surface, so that a splat of diameter ≈ 1.5 h around every leaf closes the surface
 *        (QSplat keeps a radius per node for the same reason). Kept in the `.poct` as the attribute layer
 *        "spacing" (Float32 × 1) by the builders; computed from the cells when a file without it is opened
 *        (PackedOctree::leafSpacing).
 *
 * Estimate, exactly (tests rely on it): with D the depth and e the leaf edge, every leaf belongs to its
 * ancestor C at level m = max(0, D − k) (edge S = 2^k e), k = 4 — or the first k of 5…8 for which, at level m + 1,
 * at least half the leaves lie in ancestors where n ≥ 2 o₁ (below): an octree deeper than its scan (4 mm samples
 * at depth 12, leaves of 0.42 mm) has one sample per cell of 8 edges, and k = 4 would cap h near that edge. One k
 * for the whole octree: one merged from a dense and a sparse scan takes the k of the majority of its leaves. Under C, n leaves and, at levels m + 1 and m + 2
 * (edges s₁, s₂, capped at D), o₁ and o₂ occupied cells. A plane of normal u crosses on average
 * |u|₁ / s² cubes of edge s per unit area, so the surface in C is A = o · s² / |u|₁, with u C's normal
 * (|u|₁ ∈ [1, √3]). The finer level is used (o₂, s₂) when it is saturated, n ≥ 2 o₂ (the samples are
 * denser than its cells), else the coarser (o₁, s₁). Then h = √(A / n) for every leaf under C.
 *
 * Units: metres. Thread-safety: reentrant (reads the levels only). Cost: one pass over the masks of
 * levels m … D − 1 (not the leaves; OctreeLevels::descendantCounts), memory 24 bytes per cell of level m
 * plus the result. The counts need the tree's shape only, not its normals: leafSpacingShape() may run
 * while the normals are being pulled, and leafSpacingLayer(levels, shape) finishes after. Failure modes:
 * none; an empty octree gives an empty vector.
 */
#include "stylos/core/octree/OctreeLevels.h"
#include "stylos/core/octree/PoctWriter.h"

#include <vector>

namespace stylos::core::octree {

/** @brief The name of the layer: "spacing", Float32 × 1 per leaf, metres. */
inline constexpr const char* LeafSpacingLayerName = "spacing";

/** @brief Per-leaf spacing of @p levels, in leaf order (see the file comment). */
std::vector<float> computeLeafSpacing(const OctreeLevels& levels);

/** @brief @p spacing as the "spacing" attribute layer (little-endian Float32). */
AttributeLayer leafSpacingLayer(const std::vector<float>& spacing);
/** @brief What the spacing needs of the tree's shape: the descendant counts of every level-m cell. */
struct LeafSpacingShape {
    int ancestorLevel = 0;
    std::vector<std::vector<std::uint64_t>> counts;   ///< at levels m + 1, m + 2 (capped at D) and D
};
/** @brief The shape part of the spacing of @p levels: reads only child masks and tables (safe while
 *         another thread pulls the normals of a ConstructionOctree). */
LeafSpacingShape leafSpacingShape(const OctreeLevels& levels);
/** @brief The layer from @p levels (pulled normals) and its @p shape (from leafSpacingShape of the same tree). */
AttributeLayer leafSpacingLayer(const OctreeLevels& levels, const LeafSpacingShape& shape);
/** @brief The same layer computed straight from @p levels (computeLeafSpacing's values, 4 bytes a leaf, no copy);
 *         empty bytes when there is no leaf. */
AttributeLayer leafSpacingLayer(const OctreeLevels& levels);

} // namespace stylos::core::octree
