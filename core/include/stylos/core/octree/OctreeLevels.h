#pragma once
/** @file
 * @brief What a finished octree hands to the `.poct` writer: its description and, level by level, its
 *        cells in breadth-first order. The construction structure implements it; tests implement it
 *        with small hand-made trees. Breadth-first order: level by level; within a level, the children
 *        of the previous level's cells in that order, each parent's children in increasing slot order
 *        (RootBox.h, childSlot) — which is also the order of a depth-first walk restricted to the level.
 */
#include "stylos/core/octree/NormalCode.h"
#include "stylos/core/octree/RootBox.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace stylos::core::octree {

/** @brief Everything about an octree except its cells. */
struct OctreeDescription {
    RootBox box;
    int depth = 0;                                ///< leaves are at this level; root is level 0
    NormalCodeKind normalCode = NormalCodeKind::Octahedral16;
    std::uint64_t points = 0;                     ///< input points averaged into the leaves
    std::vector<std::uint64_t> cellsPerLevel;     ///< depth + 1 entries; [0] == 1
    bool hasColour = false;                       ///< leaves carry an average RGB colour

    bool operator==(const OctreeDescription&) const = default;
};

/**
 * @brief A block of consecutive cells of one level, in breadth-first order. `masks` is empty at the
 *        leaf level (leaves have no children); `colours` (r g b per cell) is empty unless the level is
 *        the leaf level and the octree has colour.
 */
struct CellBlock {
    std::span<const std::uint8_t> masks;
    std::span<const std::uint16_t> normals;
    std::span<const std::uint8_t> colours;
};

class OctreeLevels {
public:
    virtual ~OctreeLevels() = default;
    virtual const OctreeDescription& description() const = 0;
    /**
     * @brief Calls @p sink with the cells of @p level in breadth-first order, in blocks (each block
     *        at most a few tens of thousands of cells; the spans are valid during the call only).
     *        Precondition: 0 <= level <= depth.
     */
    virtual void visitLevel(int level, const std::function<void(const CellBlock&)>& sink) const = 0;

    /**
     * @brief Calls @p sink(level, block) with the cells of every level: each level's blocks in breadth-first
     *        order as visitLevel() gives them, the levels' blocks interleaved in any order. The default visits
     *        the levels one after another; a tree whose levels are costly to reach one by one (the
     *        construction structure) lists them all in one walk.
     */
    virtual void visitLevels(const std::function<void(int level, const CellBlock&)>& sink) const;

    /**
     * @brief For each cell of @p ancestorLevel in breadth-first order, the number of its descendants at each
     *        of @p levels: result[k][i] for levels[k] and the i-th cell. Precondition: every level in
     *        @p levels is in ancestorLevel..depth. The default derives them from visitLevel(), a level at a time.
     */
    virtual std::vector<std::vector<std::uint64_t>> descendantCounts(int ancestorLevel,
                                                                     std::span<const int> levels) const;
};

} // namespace stylos::core::octree
