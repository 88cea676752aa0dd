// The default ways through an OctreeLevels: every level in turn, and descendant counts a level at a time.
#include "stylos/core/octree/OctreeLevels.h"

#include <algorithm>
#include <bit>
#include <cassert>

namespace stylos::core::octree {

void OctreeLevels::visitLevels(const std::function<void(int level, const CellBlock&)>& sink) const
{
    const int depth = description().depth;
    for (int level = 0; level <= depth; ++level)
        visitLevel(level, [&](const CellBlock& block) { sink(level, block); });
}

namespace {

/**
 * @brief From the first index at @p level of each ancestor's descendants (@p starts, one more entry than
 *        ancestors, the last the level's cell count) to the same at level + 1, by a running count of children.
 */
std::vector<std::uint64_t> nextStarts(const OctreeLevels& levels, int level, const std::vector<std::uint64_t>& starts)
{
    std::vector<std::uint64_t> next(starts.size(), 0);
    std::uint64_t cell = 0, children = 0;
    std::size_t ancestor = 0;
    levels.visitLevel(level, [&](const CellBlock& block) {
        for (const std::uint8_t mask : block.masks) {
            while (ancestor < starts.size() && starts[ancestor] == cell) next[ancestor++] = children;
            children += static_cast<std::uint64_t>(std::popcount(mask));
            ++cell;
        }
    });
    while (ancestor < starts.size()) next[ancestor++] = children;
    return next;
}

} // namespace

std::vector<std::vector<std::uint64_t>> OctreeLevels::descendantCounts(int ancestorLevel,
                                                                       std::span<const int> levels) const
{
    const OctreeDescription& d = description();
    assert(ancestorLevel >= 0 && ancestorLevel <= d.depth);
    const std::uint64_t ancestors = d.cellsPerLevel[std::size_t(ancestorLevel)];
    std::vector<std::vector<std::uint64_t>> counts(levels.size());
    int deepest = ancestorLevel;
    for (const int l : levels) {
        assert(l >= ancestorLevel && l <= d.depth);
        deepest = std::max(deepest, l);
    }
    std::vector<std::uint64_t> starts(ancestors + 1);
    for (std::uint64_t i = 0; i <= ancestors; ++i) starts[i] = i;
    for (int level = ancestorLevel;; ++level) {
        for (std::size_t k = 0; k < levels.size(); ++k) {
            if (levels[k] != level) continue;
            counts[k].resize(ancestors);
            for (std::uint64_t i = 0; i < ancestors; ++i) counts[k][i] = starts[i + 1] - starts[i];
        }
        if (level == deepest) break;
        starts = nextStarts(*this, level, starts);
    }
    return counts;
}

} // namespace stylos::core::octree
