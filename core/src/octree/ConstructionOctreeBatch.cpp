// Batched read-only descents for the Optimal passes: points far from the previous one descend in
// groups, one level per round for every member, each next cell prefetched, so that the cache misses of
// a random input overlap instead of following one another. Points near the previous one go through the
// path cache as before.
#include "stylos/core/octree/ConstructionOctree.h"

#include <atomic>

namespace stylos::core::octree {

namespace {

/** Points descending together. */
constexpr unsigned groupSize = 16;

unsigned slotOf(const std::array<std::uint32_t, 3>& coords, int shift)
{
    return childSlot(coords[0] >> shift, coords[1] >> shift, coords[2] >> shift);
}

} // namespace

/** One point of a group: where it is, and the cells it went through (to hand its path on). */
struct ConstructionOctree::Probe {
    std::array<std::uint32_t, 3> coords{};
    std::array<std::uint32_t, MaxOctreeDepth + 1> cells{};
    int level = 0;
    std::size_t position = 0;  ///< index of the point in the caller's span
    bool missing = false;
};

void ConstructionOctree::descendGroup(Probe* probes, unsigned count, int target) const
{
    const int depth = m_description.depth;
    for (bool moving = true; moving;) {
        moving = false;
        for (unsigned j = 0; j < count; ++j) {
            Probe& p = probes[j];
            if (p.level >= target || p.missing) continue;
            const std::uint8_t* c = m_arena.cell(p.cells[std::size_t(p.level)]);
            const unsigned slot = slotOf(p.coords, depth - p.level - 1);
            const std::uint8_t mask = cell::mask(c);
            if (!(mask & (1u << slot))) {
                p.missing = true;
                continue;
            }
            const std::uint32_t next = cell::value(c) + cell::rank(mask, slot);
            p.cells[std::size_t(++p.level)] = next;
            __builtin_prefetch(m_arena.cell(next));
            moving = true;
        }
    }
}

bool ConstructionOctree::markAll(std::span<const PreparedPoint> points, int level, Path& path)
{
    const int depth = m_description.depth;
    const int shift = depth - level - 1;
    std::array<Probe, groupSize> group;
    unsigned n = 0;
    bool ok = true;
    auto flush = [&] {
        descendGroup(group.data(), n, level);
        for (unsigned j = 0; j < n; ++j) {
            const Probe& p = group[j];
            if (p.missing) {
                ok = false;
                continue;
            }
            std::atomic_ref<std::uint8_t> mask(m_arena.cell(p.cells[std::size_t(level)])[0]);
            const std::uint8_t bit = std::uint8_t(1u << slotOf(p.coords, shift));
            if (!(mask.load(std::memory_order_relaxed) & bit)) mask.fetch_or(bit, std::memory_order_relaxed);
        }
        if (n > 0 && !group[n - 1].missing) {
            path.coords = group[n - 1].coords;
            path.cells = group[n - 1].cells;
            path.levels = level;
            path.marked = level;
        }
        n = 0;
    };
    std::array<std::uint32_t, 3> previous{};
    bool hasPrevious = false;
    for (const PreparedPoint& point : points) {
        const auto& c = point.coords;
        // The same cell at level + 1 as the point before: its bit is set, or will be with its group.
        const std::uint32_t diff = (c[0] ^ previous[0]) | (c[1] ^ previous[1]) | (c[2] ^ previous[2]);
        if (hasPrevious && (diff >> shift) == 0) continue;
        previous = c;
        hasPrevious = true;
        const int restart = restartLevel(c, path, level);
        if (restart >= level - 3) {
            ok &= mark(c, level, path);
            continue;
        }
        Probe& p = group[n++];
        p.coords = c;
        for (int l = 0; l <= restart; ++l) p.cells[std::size_t(l)] = path.cells[std::size_t(l)];
        p.level = restart;
        p.missing = false;
        if (n == groupSize) flush();
    }
    flush();
    return ok;
}

void ConstructionOctree::findLeaves(std::span<const PreparedPoint> points, std::span<std::uint32_t> leaves,
                                    Path& path) const
{
    const int depth = m_description.depth;
    std::array<Probe, groupSize> group;
    unsigned n = 0;
    auto flush = [&] {
        descendGroup(group.data(), n, depth);
        for (unsigned j = 0; j < n; ++j)
            leaves[group[j].position] = group[j].missing ? CellArena::Exhausted : group[j].cells[std::size_t(depth)];
        if (n > 0 && !group[n - 1].missing) {
            path.coords = group[n - 1].coords;
            path.cells = group[n - 1].cells;
            path.levels = depth;
        }
        n = 0;
    };
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto& c = points[i].coords;
        const int restart = restartLevel(c, path, depth);
        if (restart >= depth - 3) {
            leaves[i] = findLeaf(c, path);
            continue;
        }
        Probe& p = group[n++];
        p.coords = c;
        for (int l = 0; l <= restart; ++l) p.cells[std::size_t(l)] = path.cells[std::size_t(l)];
        p.level = restart;
        p.position = i;
        p.missing = false;
        if (n == groupSize) flush();
    }
    flush();
}

} // namespace stylos::core::octree
