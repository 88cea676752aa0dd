#pragma once
// Internal: constant-time child lookup over the child masks of a packed octree. Per inner level, the
// number of children of all cells before every 64th cell (8 bytes per 64 cells); the first child of
// cell i is that prefix plus the popcount of the masks between the block start and i (at most eight
// 8-byte loads). Building it checks that every inner cell has children and that each level's children
// are exactly the next level's cells.
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace stylos::core::octree::poct {

class ChildIndex {
public:
    /**
     * @p masks: the masks of each inner level (levels 0 .. depth − 1), @p cellsPerLevel: depth + 1
     * counts. Malformed (naming @p file and the byte offset, from @p masksOffset) when a mask is 0 or
     * a level's children do not add up to the next level's cells.
     */
    static Result<ChildIndex> build(const std::vector<std::span<const std::uint8_t>>& masks,
                                    const std::vector<std::uint64_t>& cellsPerLevel, std::uint64_t masksOffset,
                                    const std::string& file);

    ChildIndex() = default;

    /** Index at level + 1 of the first child of cell @p index of inner level @p level. */
    std::uint64_t firstChild(int level, std::uint64_t index) const;

    /** Bytes the index occupies. */
    std::uint64_t bytes() const;

private:
    std::vector<std::span<const std::uint8_t>> m_masks;
    std::vector<std::vector<std::uint64_t>> m_prefix;   ///< per inner level, one per 64 cells (+1)
};

} // namespace stylos::core::octree::poct
