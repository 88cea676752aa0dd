// The construction octree's levels all at once: one depth-first walk that hands every level its cells in
// breadth-first order (visitLevels, the writer's input), and descendant counts per ancestor (the leaf spacing).
// Walking the levels one by one re-walks every level above each one; these touch each cell once.
#include "stylos/core/octree/ConstructionOctree.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <cstring>
#include <thread>

namespace stylos::core::octree {

namespace {

/** Cells a level's block holds before visitLevels() hands it on. */
constexpr std::size_t levelBlockCells = 16384;

/** One level's pending cells. */
struct LevelBuffer {
    std::vector<std::uint8_t> masks;
    std::vector<std::uint16_t> normals;
    std::vector<std::uint8_t> colours;
    std::size_t n = 0;
    std::size_t capacity = 0;
};

} // namespace

void ConstructionOctree::visitLevels(const std::function<void(int level, const CellBlock&)>& sink) const
{
    if (m_arena.cellBytes() == CellArena::PlainCellBytes)
        visitAllCells<CellArena::PlainCellBytes>(sink);
    else
        visitAllCells<CellArena::ColourCellBytes>(sink);
}

template <unsigned CellBytes>
void ConstructionOctree::visitAllCells(const std::function<void(int level, const CellBlock&)>& sink) const
{
    const int depth = m_description.depth;
    const bool colour = CellBytes == CellArena::ColourCellBytes;
    std::vector<LevelBuffer> buffers(std::size_t(depth) + 1);
    for (int l = 0; l <= depth; ++l) {
        LevelBuffer& b = buffers[std::size_t(l)];
        b.capacity = std::size_t(std::min<std::uint64_t>(levelBlockCells, m_description.cellsPerLevel[std::size_t(l)]));
        b.capacity = std::max<std::size_t>(b.capacity, 1);
        if (l < depth) b.masks.resize(b.capacity);
        b.normals.resize(b.capacity);
        if (l == depth && colour) b.colours.resize(3 * b.capacity);
    }
    auto flush = [&](int l) {
        LevelBuffer& b = buffers[std::size_t(l)];
        if (b.n == 0) return;
        sink(l, CellBlock{std::span<const std::uint8_t>(b.masks.data(), l < depth ? b.n : 0),
                          std::span<const std::uint16_t>(b.normals.data(), b.n),
                          std::span<const std::uint8_t>(b.colours.data(), l == depth && colour ? 3 * b.n : 0)});
        b.n = 0;
    };
    auto addInner = [&](int l, const std::uint8_t* c) {
        LevelBuffer& b = buffers[std::size_t(l)];
        b.masks[b.n] = cell::mask(c);
        b.normals[b.n] = cell::normal(c);
        if (++b.n == b.capacity) flush(l);
    };

    const std::uint8_t* root = m_arena.cellOf<CellBytes>(m_root);
    if (depth == 0) {
        LevelBuffer& b = buffers[0];
        b.normals[0] = cell::normal(root);
        if (colour) std::memcpy(b.colours.data(), cell::colour(root), 3);
        b.n = 1;
        flush(0);
        return;
    }
    addInner(0, root);
    struct Range {
        std::uint32_t next, end;
    };
    std::array<Range, MaxOctreeDepth + 2> stack{};
    const unsigned rootChildren = cell::count(cell::mask(root));
    int m = 0;
    if (rootChildren > 0) {
        stack[1] = {cell::value(root), cell::value(root) + rootChildren};
        m = 1;
    }
    LevelBuffer& leaves = buffers[std::size_t(depth)];
    while (m > 0) {
        Range& top = stack[std::size_t(m)];
        if (m == depth) {
            // A table of leaves: consecutive cells of one chunk.
            const std::uint8_t* c = m_arena.cellOf<CellBytes>(top.next);
            for (std::uint32_t i = top.next; i < top.end; ++i, c += CellBytes) {
                leaves.normals[leaves.n] = cell::normal(c);
                if (colour) std::memcpy(&leaves.colours[3 * leaves.n], cell::colour(c), 3);
                if (++leaves.n == leaves.capacity) flush(depth);
            }
            --m;
            continue;
        }
        if (top.next == top.end) {
            --m;
            continue;
        }
        const std::uint8_t* c = m_arena.cellOf<CellBytes>(top.next++);
        addInner(m, c);
        const unsigned count = cell::count(cell::mask(c));
        if (count == 0) continue;
        const std::uint32_t table = cell::value(c);
        stack[std::size_t(m) + 1] = {table, table + count};
        ++m;
        if (m < depth) {
            // These cells' children are visited one subtree after another: fetch them all now.
            for (unsigned i = 0; i < count; ++i) {
                const std::uint8_t* child = m_arena.cellOf<CellBytes>(table + i);
                if (cell::mask(child)) __builtin_prefetch(m_arena.cellOf<CellBytes>(cell::value(child)));
            }
        }
    }
    for (int l = 0; l <= depth; ++l) flush(l);
}

std::vector<std::vector<std::uint64_t>> ConstructionOctree::descendantCounts(int ancestorLevel,
                                                                             std::span<const int> levels) const
{
    [[maybe_unused]] const int depth = m_description.depth;
    assert(ancestorLevel >= 0 && ancestorLevel <= depth);
    int deepest = ancestorLevel;
    for (const int l : levels) {
        assert(l >= ancestorLevel && l <= depth);
        deepest = std::max(deepest, l);
    }
    const std::vector<std::uint32_t> ancestors = cellIndices(ancestorLevel);
    const std::size_t n = ancestors.size();
    std::vector<std::vector<std::uint64_t>> result(levels.size(), std::vector<std::uint64_t>(n));
    const int below = deepest - ancestorLevel;  // relative level of the deepest count

    // Per ancestor, its cells at each relative level 0..below: a level's count is the sum of the child
    // counts of the level above, so the walk reads the cells down to relative level below − 1. The walk is
    // a chain of dependent cache misses (each child table is somewhere else in the arena), so several
    // ancestors are walked at once, in turns: each turn reads one table and, on finding a child table,
    // fetches it and lets the next walk go while the memory answers.
    struct Range {
        std::uint32_t next, end;
    };
    struct Walk {
        std::size_t ancestor = 0;
        int m = -1;  // relative level of the range on top; −1: finished
        std::array<Range, MaxOctreeDepth + 2> stack{};
        std::array<std::uint64_t, MaxOctreeDepth + 2> counts{};
    };
    auto countRange = [&](std::size_t from, std::size_t to) {
        constexpr unsigned ways = 12;
        std::array<Walk, ways> walks;
        std::size_t nextAncestor = from;
        auto begin = [&](Walk& w) {
            if (nextAncestor >= to) return false;
            w.ancestor = nextAncestor++;
            w.counts.fill(0);
            w.counts[0] = 1;
            w.stack[0] = {ancestors[w.ancestor], ancestors[w.ancestor] + 1};
            w.m = 0;
            __builtin_prefetch(m_arena.cell(ancestors[w.ancestor]));
            return true;
        };
        unsigned active = 0;
        for (Walk& w : walks) active += begin(w) ? 1u : 0u;
        while (active > 0) {
            for (Walk& w : walks) {
                if (w.m < 0) continue;
                for (;;) {
                    Range& top = w.stack[std::size_t(w.m)];
                    if (top.next == top.end || w.m == below) {
                        if (--w.m >= 0) continue;
                        for (std::size_t j = 0; j < levels.size(); ++j)
                            result[j][w.ancestor] = w.counts[std::size_t(levels[j] - ancestorLevel)];
                        if (!begin(w)) --active;
                        break;
                    }
                    const std::uint8_t* c = m_arena.cell(top.next++);
                    const unsigned k = cell::count(cell::mask(c));
                    w.counts[std::size_t(w.m) + 1] += k;
                    if (k == 0 || w.m + 1 == below) continue;
                    const std::uint32_t table = cell::value(c);
                    w.stack[std::size_t(w.m) + 1] = {table, table + k};
                    ++w.m;
                    __builtin_prefetch(m_arena.cell(table));
                    break;
                }
            }
        }
    };
    // Ancestors are independent: the threads take blocks of them in turn.
    constexpr std::size_t blockAncestors = 4096;
    std::atomic<std::size_t> nextBlock{0};
    auto work = [&] {
        for (;;) {
            const std::size_t from = nextBlock.fetch_add(blockAncestors);
            if (from >= n) return;
            countRange(from, std::min(n, from + blockAncestors));
        }
    };
    std::vector<std::thread> helpers;
    const unsigned threads = n > blockAncestors ? m_threads : 1;
    for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(work);
    work();
    for (std::thread& t : helpers) t.join();
    return result;
}

} // namespace stylos::core::octree
