#pragma once
// Internal: the depth-first walk of the construction octree restricted to one level, which lists that
// level's cells in breadth-first order without memory proportional to the tree (one frame per level).
#include "stylos/core/octree/CellArena.h"
#include "stylos/core/octree/RootBox.h"

#include <array>
#include <cstdint>

namespace stylos::core::octree {

/**
 * @brief Calls fn(first, count) for each run of consecutive cells (a child table, or @p start itself
 *        when @p level == @p startLevel) of @p level below cell @p start of @p startLevel, in
 *        breadth-first order. Every cell above @p level must have its child table (a complete tree).
 */
template <typename Fn>
void forEachRangeBelow(const CellArena& arena, std::uint32_t start, int startLevel, int level, Fn&& fn)
{
    if (level == startLevel) {
        fn(start, 1u);
        return;
    }
    struct Range {
        std::uint32_t next, end;
    };
    std::array<Range, MaxOctreeDepth + 2> stack{};
    const std::uint8_t* first = arena.cell(start);
    const unsigned firstCount = cell::count(cell::mask(first));
    if (firstCount == 0) return;
    int m = startLevel + 1;
    stack[std::size_t(m)] = {cell::value(first), cell::value(first) + firstCount};
    while (m > startLevel) {
        Range& top = stack[std::size_t(m)];
        if (m == level) {
            fn(top.next, top.end - top.next);
            --m;
            continue;
        }
        if (top.next == top.end) {
            --m;
            continue;
        }
        const std::uint8_t* c = arena.cell(top.next++);
        const unsigned count = cell::count(cell::mask(c));
        if (count > 0) {
            const std::uint32_t table = cell::value(c);
            stack[std::size_t(m) + 1] = {table, table + count};
            ++m;
            if (m < level) {
                // These cells' children are visited one subtree after another: fetch them all now.
                for (unsigned i = 0; i < count; ++i) {
                    const std::uint8_t* child = arena.cell(table + i);
                    if (cell::mask(child)) __builtin_prefetch(arena.cell(cell::value(child)));
                }
            }
        }
    }
}

/** @brief forEachRangeBelow() one cell at a time: fn(index). */
template <typename Fn>
void forEachCellBelow(const CellArena& arena, std::uint32_t start, int startLevel, int level, Fn&& fn)
{
    forEachRangeBelow(arena, start, startLevel, level, [&](std::uint32_t first, std::uint32_t count) {
        for (std::uint32_t i = 0; i < count; ++i) fn(first + i);
    });
}

} // namespace stylos::core::octree
