// The construction octree's levels in breadth-first order: visitLevel() (the writer's input), cell
// indices and weights per level.
#include "stylos/core/octree/ConstructionOctree.h"

#include "ConstructionWalk.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <mutex>
#include <thread>

namespace stylos::core::octree {

namespace {
/** Largest block visitLevel() hands out, cells. */
constexpr std::size_t blockCells = 16384;
} // namespace


void ConstructionOctree::visitLevel(int level, const std::function<void(const CellBlock&)>& sink) const
{
    assert(level >= 0 && level <= m_description.depth && "ConstructionOctree::visitLevel(): level out of range");
    if (m_arena.cellBytes() == CellArena::PlainCellBytes)
        visitCells<CellArena::PlainCellBytes>(level, sink);
    else
        visitCells<CellArena::ColourCellBytes>(level, sink);
}

/**
 * One level's cells walked by W threads, subtree by subtree: subtree i by thread i mod W, thread 0 being
 * the caller, who also hands every block to the sink in subtree order. The helpers keep a few blocks
 * each (memory stays bounded) and so run at most that far ahead; a subtree's last block is marked.
 */
template <unsigned CellBytes>
class ParallelLevelWalk {
public:
    ParallelLevelWalk(const CellArena& arena, std::vector<std::uint32_t> subtrees, int subtreeLevel, int level,
                      bool inner, bool colour, unsigned threads)
        : m_arena(arena), m_subtrees(std::move(subtrees)), m_subtreeLevel(subtreeLevel), m_level(level),
          m_inner(inner), m_colour(colour), m_lanes(threads)
    {
        for (Lane& lane : m_lanes)
            for (Block& b : lane.blocks) {
                b.masks.resize(inner ? blockCells : 0);
                b.normals.resize(blockCells);
                b.colours.resize(colour ? 3 * blockCells : 0);
                lane.free.push_back(&b);
            }
    }

    void run(const std::function<void(const CellBlock&)>& sink)
    {
        std::vector<std::thread> helpers;
        for (std::size_t w = 1; w < m_lanes.size(); ++w) helpers.emplace_back([this, w] { walkLane(w); });
        Block& own = m_lanes[0].blocks[0];
        for (std::size_t i = 0; i < m_subtrees.size(); ++i) {
            const std::size_t w = i % m_lanes.size();
            if (w == 0) {
                // This thread's turn: walk the subtree into its own block, handing out each full one.
                own.n = 0;
                walkSubtree(i, own, [&] {
                    emit(sink, own);
                    return &own;
                });
                emit(sink, own);
                continue;
            }
            Lane& lane = m_lanes[w];
            for (bool last = false; !last;) {
                Block* b;
                {
                    std::unique_lock lock(lane.mutex);
                    lane.changed.wait(lock, [&] { return !lane.full.empty(); });
                    b = lane.full.front();
                    lane.full.pop_front();
                }
                emit(sink, *b);
                last = b->last;
                {
                    std::lock_guard lock(lane.mutex);
                    lane.free.push_back(b);
                }
                lane.changed.notify_all();
            }
        }
        for (std::thread& t : helpers) t.join();
    }

private:
    struct Block {
        std::vector<std::uint8_t> masks;
        std::vector<std::uint16_t> normals;
        std::vector<std::uint8_t> colours;
        std::size_t n = 0;
        bool last = false;
    };
    struct Lane {
        std::array<Block, 4> blocks;
        std::vector<Block*> free;
        std::deque<Block*> full;
        std::mutex mutex;
        std::condition_variable changed;
    };

    void emit(const std::function<void(const CellBlock&)>& sink, Block& b) const
    {
        if (b.n > 0)
            sink(CellBlock{std::span<const std::uint8_t>(b.masks.data(), m_inner ? b.n : 0),
                           std::span<const std::uint16_t>(b.normals.data(), b.n),
                           std::span<const std::uint8_t>(b.colours.data(), m_colour ? 3 * b.n : 0)});
        b.n = 0;
    }

    /** Appends subtree @p i's cells to @p b; whenever the block is full, full() hands it on and returns
     *  the (empty) block to go on with. */
    template <typename Full>
    void walkSubtree(std::size_t i, Block& b, Full&& full) const
    {
        Block* block = &b;
        forEachRangeBelow(m_arena, m_subtrees[i], m_subtreeLevel, m_level, [&](std::uint32_t first, std::uint32_t count) {
            const std::uint8_t* c = m_arena.cellOf<CellBytes>(first);
            for (std::uint32_t k = 0; k < count; ++k, c += CellBytes) {
                if (block->n == blockCells) block = full();
                if (m_inner) block->masks[block->n] = cell::mask(c);
                block->normals[block->n] = cell::normal(c);
                if (m_colour) std::memcpy(&block->colours[3 * block->n], cell::colour(c), 3);
                ++block->n;
            }
        });
    }

    Block* take(Lane& lane)
    {
        std::unique_lock lock(lane.mutex);
        lane.changed.wait(lock, [&] { return !lane.free.empty(); });
        Block* b = lane.free.back();
        lane.free.pop_back();
        b->n = 0;
        b->last = false;
        return b;
    }
    void hand(Lane& lane, Block* b)
    {
        {
            std::lock_guard lock(lane.mutex);
            lane.full.push_back(b);
        }
        lane.changed.notify_all();
    }

    void walkLane(std::size_t w)
    {
        Lane& lane = m_lanes[w];
        for (std::size_t i = w; i < m_subtrees.size(); i += m_lanes.size()) {
            Block* b = take(lane);
            walkSubtree(i, *b, [&] {
                hand(lane, b);
                b = take(lane);
                return b;
            });
            b->last = true;
            hand(lane, b);
        }
    }

    const CellArena& m_arena;
    std::vector<std::uint32_t> m_subtrees;
    int m_subtreeLevel;
    int m_level;
    bool m_inner;
    bool m_colour;
    std::vector<Lane> m_lanes;
};

template <unsigned CellBytes>
void ConstructionOctree::visitCells(int level, const std::function<void(const CellBlock&)>& sink) const
{
    const bool inner = level < m_description.depth;
    const bool colour = !inner && CellBytes == CellArena::ColourCellBytes;
    // Large levels are walked by m_threads threads, split into the subtrees of the first level whose
    // cells have about a quarter block each below them: the walkers then take turns subtree by subtree,
    // each a few blocks ahead of the sink at most.
    const std::uint64_t cells = m_description.cellsPerLevel[std::size_t(level)];
    if (m_threads > 1 && cells > blockCells) {
        const std::uint64_t subtrees = std::max<std::uint64_t>(16u * m_threads, cells / (blockCells / 4));
        int split = 1;
        while (split < level && m_description.cellsPerLevel[std::size_t(split)] < subtrees) ++split;
        if (split < level) {
            ParallelLevelWalk<CellBytes> walk(m_arena, cellIndices(split), split, level, inner, colour, m_threads);
            walk.run(sink);
            return;
        }
    }
    std::vector<std::uint8_t> masks(inner ? blockCells : 0);
    std::vector<std::uint16_t> normals(blockCells);
    std::vector<std::uint8_t> colours(colour ? 3 * blockCells : 0);
    std::size_t n = 0;
    auto flush = [&] {
        if (n == 0) return;
        sink(CellBlock{std::span<const std::uint8_t>(masks.data(), inner ? n : 0),
                       std::span<const std::uint16_t>(normals.data(), n),
                       std::span<const std::uint8_t>(colours.data(), colour ? 3 * n : 0)});
        n = 0;
    };
    forEachRangeBelow(m_arena, m_root, 0, level, [&](std::uint32_t first, std::uint32_t count) {
        const std::uint8_t* c = m_arena.cellOf<CellBytes>(first);  // a table: consecutive in one chunk
        for (std::uint32_t i = 0; i < count; ++i, c += CellBytes) {
            if (inner) masks[n] = cell::mask(c);
            normals[n] = cell::normal(c);
            if (colour) std::memcpy(&colours[3 * n], cell::colour(c), 3);
            if (++n == blockCells) flush();
        }
    });
    flush();
}

std::vector<std::uint32_t> ConstructionOctree::cellIndices(int level) const
{
    std::vector<std::uint32_t> indices;
    forEachCellBelow(m_arena, m_root, 0, level, [&](std::uint32_t index) { indices.push_back(index); });
    return indices;
}

std::vector<std::uint64_t> ConstructionOctree::weights(int level) const
{
    const int depth = m_description.depth;
    std::function<std::uint64_t(std::uint32_t, int)> weight = [&](std::uint32_t index, int l) -> std::uint64_t {
        const std::uint8_t* c = m_arena.cell(index);
        if (l == depth) return cell::value(c);
        std::uint64_t total = 0;
        const unsigned count = cell::count(cell::mask(c));
        for (unsigned i = 0; i < count; ++i) total += weight(cell::value(c) + i, l + 1);
        return total;
    };
    std::vector<std::uint64_t> out;
    forEachCellBelow(m_arena, m_root, 0, level, [&](std::uint32_t index) { out.push_back(weight(index, level)); });
    return out;
}

} // namespace stylos::core::octree
