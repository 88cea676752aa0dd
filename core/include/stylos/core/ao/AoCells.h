#pragma once
/** @file
 * @brief The cells of one octree level as the 3D skydome reads them: integer coordinates at that level,
 *        unit normal, opacity, and for every cell the range of leaves under it (breadth-first order of
 *        the leaf level keeps each cell's leaves consecutive), so per-cell results spread to the leaves.
 *
 * Opacity (the paper: "a cell blocks light according to how many points it holds"): a leaf is opaque
 * (1); a cell k levels above the leaves, with n leaves under it, has min(1, n / 4^k): a surface crossing
 * it fills about 4^k of its 8^k leaf slots. Cell edge = root edge / 2^level; the centre of the cell with
 * coordinates c is origin + (c + ½) · edge (metres, the octree's frame, whose z is the world's up).
 * Thread-safety: a value type. Memory: 32 bytes per cell.
 */
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace stylos::core::ao {

struct AoCells {
    int level = 0;
    double edge = 1.0;                                   ///< metres
    std::array<double, 3> origin{};                      ///< metres: the corner of coordinates (0, 0, 0)
    std::vector<std::array<std::uint32_t, 3>> coords;    ///< per cell, at `level`
    std::vector<std::array<float, 3>> normals;           ///< per cell, unit
    std::vector<float> opacity;                          ///< per cell, (0, 1]
    std::vector<std::uint64_t> leafBegin;                ///< cells + 1 entries: leaves [leafBegin[i], leafBegin[i+1])

    std::size_t size() const { return coords.size(); }
    std::array<double, 3> centre(std::size_t i) const;
};

/**
 * @brief The cells of @p octree at @p level (0..depth), in breadth-first order. Progress: the fraction of
 *        cells read; cancel is checked every 64 Ki cells.
 * @return the cells, or InvalidArgument (level outside 0..depth, naming the octree's file), Cancelled.
 */
Result<AoCells> cellsAtLevel(const octree::PackedOctree& octree, int level, ProgressSink* progress = nullptr);

/**
 * @brief The deepest level at which the cells still form a closed surface: the deepest level L ≥ 1 whose
 *        cell count is at least 3 times that of level L − 1 (a surface crossing a cell fills about 4 of its
 *        8 children while the sampling is finer than the cells; once the cells outgrow the sampling, each
 *        point gets its own cell and the ratio falls toward 1, and light leaks between them). The leaf
 *        level when no level qualifies. Measured: Igea (134 k points, depth 12) → 7; the Happy Buddha
 *        (1.1 M points, depth 12) → 9; a generated drum built at its spacing → its leaf level.
 */
int closedSurfaceLevel(const octree::PackedOctree& octree);

/**
 * @brief Where the skydome is measured when it is not at the cells' centres: receivers with their own
 *        position and normal (the leaves under the cells: LeafReceivers), tested against the cells as
 *        occluders (computeAmbientOcclusion with receivers, AmbientOcclusion.h). Positions are in cell
 *        edges of the occluders' level from their grid corner (a cell with coordinates c spans [c, c + 1]).
 * Memory: 24 bytes per receiver.
 */
struct AoReceivers {
    std::vector<std::array<float, 3>> positions;
    std::vector<std::array<float, 3>> normals; ///< unit
    std::size_t size() const { return positions.size(); }
};

/**
 * @brief The leaves of @p octree as receivers for the cells @p occluders (of the same octree): each leaf's
 *        centre and normal, in leaf order. Progress: the fraction of leaves read; cancel every 64 Ki.
 * @return the receivers, or Cancelled.
 */
Result<AoReceivers> leafReceivers(const octree::PackedOctree& octree, const AoCells& occluders,
                                  ProgressSink* progress = nullptr);

/** @brief Spreads per-cell @p values to the leaves under each cell (leafBegin.back() values). */
std::vector<float> valuesPerLeaf(const AoCells& cells, std::span<const float> values);

} // namespace stylos::core::ao
