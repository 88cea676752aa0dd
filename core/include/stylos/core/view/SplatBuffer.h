#pragma once
/** @file
 * @brief The CPU side of a fragment's splats: one vertex per cell of a level-of-detail cut, ready to be
 *        copied into a GL vertex buffer (PointRenderer::upload). Built on a worker thread, uploaded on the
 *        GUI thread. The vertices are in a pseudo-random order (a seeded shuffle), so that any prefix of
 *        the buffer is an even subsample of the cut: while the camera moves, the renderer draws only a
 *        prefix, with splats enlarged to cover the gaps.
 *
 * Per-cell attributes of the octree are per leaf; an inner cell of the cut takes those of its first leaf
 * (following first children down to the leaf level). A splat's size is the larger of the cell's edge and
twice the spacing of that leaf (a disc of radius h reaches the neighbouring samples) (PackedOctree::leafSpacing: the leaf's share of the surface), so that leaves
smaller than the sampling still close the surface. Units: metres (positions relative to the octree's
 * root box origin, in the octree's frame). Thread-safety: reentrant, reads the octree only. Failure modes:
 * none; a "colour" or "ambient" layer of another type or size is ignored, as if absent.
 */
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/octree/ViewCut.h"

#include <array>
#include <cstdint>
#include <vector>

namespace stylos::core::view {

/** @brief One splat as the vertex shader reads it (24 bytes). */
struct SplatVertex {
    std::array<float, 3> position{};       ///< cell centre, metres, relative to the root box origin
    float size = 0;                        ///< footprint, metres: max(cell edge, 2 × its first leaf's spacing)
    std::array<std::int8_t, 4> normal{};   ///< unit normal × 127 (w unused)
    std::array<std::uint8_t, 4> colour{};  ///< scan colour (rgb; 255 when none) and ambient × 255 (a; 255 when none)
};
static_assert(sizeof(SplatVertex) == 24, "SplatVertex is uploaded as is");

/** @brief A cut's splats and what the cut reported. */
struct SplatBuffer {
    std::vector<SplatVertex> vertices;
    std::array<double, 3> origin{};        ///< the root box origin (octree frame), metres
    bool hasColour = false;                ///< the octree has the "colour" layer
    bool hasAmbient = false;               ///< the octree has the "ambient" layer (Float32 × 1)
    bool budgetReached = false;
    int deepestLevel = 0;
};

/** @brief Index at the leaf level of the first leaf under the cell (@p level, @p index). */
std::uint64_t firstLeafOf(const octree::PackedOctree& octree, int level, std::uint64_t index);

/** @brief The splats of @p cut (cells of @p octree), shuffled with @p seed (0: in the cut's order). */
SplatBuffer makeSplatBuffer(const octree::PackedOctree& octree, const octree::CutResult& cut,
                            std::uint64_t seed = 1);

} // namespace stylos::core::view
