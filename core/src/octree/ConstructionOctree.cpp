#include "stylos/core/octree/ConstructionOctree.h"

#include "ConstructionWalk.h"
#include "SubtreeCells.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstring>
#include <cassert>
#include <thread>

namespace stylos::core::octree {

namespace {

unsigned slotAt(const std::array<std::uint32_t, 3>& coords, int shift)
{
    return childSlot(coords[0] >> shift, coords[1] >> shift, coords[2] >> shift);
}

std::vector<std::uint16_t> buildReencodeTable(NormalCodeKind kind)
{
    const NormalEncoder encode(kind);
    const std::array<float, 3>* decode = normalDecodeTable(kind);
    std::vector<std::uint16_t> table(normalCodeCount(kind));
    for (std::size_t c = 0; c < table.size(); ++c) table[c] = encode(decode[c][0], decode[c][1], decode[c][2]);
    return table;
}

/**
 * encode(decode(code)) for every code: the pull of a cell with one child whose weight w is a power of
 * two. Its sum w · d is then exact in double and in float, and the encoder's rescaling by the largest
 * component divides w out exactly, so the code is encode(d) — bit for bit the general formula.
 */
const std::uint16_t* reencodeTable(NormalCodeKind kind)
{
    if (kind == NormalCodeKind::Paper15) {
        static const std::vector<std::uint16_t> paper = buildReencodeTable(kind);
        return paper.data();
    }
    static const std::vector<std::uint16_t> octahedral = buildReencodeTable(kind);
    return octahedral.data();
}

/** Copies @p count cells (fixed-size copies rather than a call). */
template <unsigned CellBytes>
void copyCells(std::uint8_t* to, const std::uint8_t* from, unsigned count)
{
    for (unsigned i = 0; i < count; ++i) std::memcpy(to + i * CellBytes, from + i * CellBytes, CellBytes);
}

} // namespace

ConstructionOctree::ConstructionOctree(const RootBox& box, int depth, NormalCodeKind kind, bool hasColour,
                                       std::uint64_t memoryLimit)
    : m_arena(hasColour ? CellArena::ColourCellBytes : CellArena::PlainCellBytes, memoryLimit), m_encode(kind)
{
    assert(depth >= MinOctreeDepth && depth <= MaxOctreeDepth && "ConstructionOctree: depth out of range");
    m_description.box = box;
    m_description.depth = depth;
    m_description.normalCode = kind;
    m_description.hasColour = hasColour;
    m_description.cellsPerLevel.assign(std::size_t(depth) + 1, 0);
    m_description.cellsPerLevel[0] = 1;
    m_root = m_arena.allocate(1);
    assert(m_root != CellArena::Exhausted && "ConstructionOctree: memory limit below minimumBytes()");
    std::memset(m_arena.cell(m_root), 0, m_arena.cellBytes());
    m_decode = normalDecodeTable(kind);
    m_reencode = reencodeTable(kind);
    m_codeMask = kind == NormalCodeKind::Paper15 ? 0x7FFF : 0xFFFF;
}

std::uint64_t ConstructionOctree::minimumBytes(bool hasColour)
{
    return CellArena(hasColour ? CellArena::ColourCellBytes : CellArena::PlainCellBytes).bytesWithChunks(1);
}

ConstructionOctree::Path ConstructionOctree::rootPath() const
{
    Path path;
    path.cells[0] = m_root;
    path.levels = 0;
    return path;
}

bool ConstructionOctree::populate(const PreparedPoint& point, Path& path)
{
    return m_arena.cellBytes() == CellArena::PlainCellBytes ? populateCells<CellArena::PlainCellBytes>(point, path)
                                                            : populateCells<CellArena::ColourCellBytes>(point, path);
}

template <unsigned CellBytes>
bool ConstructionOctree::populateCells(const PreparedPoint& point, Path& path)
{
    const int depth = m_description.depth;
    int level = restartLevel(point.coords, path, depth);
    std::uint32_t index = path.cells[std::size_t(level)];
    path.coords = point.coords;
    for (; level < depth; ++level) {
        std::uint8_t* c = m_arena.cellOf<CellBytes>(index);
        const unsigned slot = slotAt(point.coords, depth - level - 1);
        const std::uint8_t mask = cell::mask(c);
        const unsigned before = cell::rank(mask, slot);
        std::uint32_t table = cell::value(c);
        if (!(mask & (1u << slot))) {
            // Grow the child table by one cell: allocate(k + 1), copy around the new cell, release(k).
            const unsigned count = cell::count(mask);
            const std::uint32_t grown = m_arena.allocate(count + 1);
            if (grown == CellArena::Exhausted) {
                path.levels = level;
                return false;
            }
            std::uint8_t* to = m_arena.cellOf<CellBytes>(grown);
            if (count > 0) {
                const std::uint8_t* from = m_arena.cellOf<CellBytes>(table);
                copyCells<CellBytes>(to, from, before);
                copyCells<CellBytes>(to + (before + 1) * CellBytes, from + before * CellBytes, count - before);
                m_arena.release(table, count);
            }
            static constexpr std::uint8_t zero[CellBytes] = {};
            std::memcpy(to + before * CellBytes, zero, CellBytes);
            cell::setValue(c, grown);
            cell::setMask(c, std::uint8_t(mask | (1u << slot)));
            table = grown;
            ++m_description.cellsPerLevel[std::size_t(level) + 1];
        }
        index = table + before;
        path.cells[std::size_t(level) + 1] = index;
    }
    path.levels = depth;
    averageCell<CellBytes>(m_arena.cellOf<CellBytes>(index), point);
    return true;
}

bool ConstructionOctree::mark(const std::array<std::uint32_t, 3>& coords, int level, Path& path)
{
    const int depth = m_description.depth;
    assert(level >= 0 && level < depth && "ConstructionOctree::mark(): level out of range");
    const std::uint32_t diff = (coords[0] ^ path.coords[0]) | (coords[1] ^ path.coords[1]) | (coords[2] ^ path.coords[2]);
    if (path.marked == level && (diff >> (depth - level - 1)) == 0) return true;  // the previous point's bit
    int m = restartLevel(coords, path, level);
    std::uint32_t index = path.cells[std::size_t(m)];
    path.coords = coords;
    path.marked = -1;
    for (; m < level; ++m) {
        const std::uint8_t* c = m_arena.cell(index);
        const unsigned slot = slotAt(coords, depth - m - 1);
        const std::uint8_t mask = cell::mask(c);
        if (!(mask & (1u << slot))) {
            path.levels = m;
            return false;
        }
        index = cell::value(c) + cell::rank(mask, slot);
        path.cells[std::size_t(m) + 1] = index;
    }
    path.levels = level;
    std::atomic_ref<std::uint8_t> mask(m_arena.cell(index)[0]);
    const std::uint8_t bit = std::uint8_t(1u << slotAt(coords, depth - level - 1));
    if (!(mask.load(std::memory_order_relaxed) & bit)) mask.fetch_or(bit, std::memory_order_relaxed);
    path.marked = level;
    return true;
}

std::uint64_t ConstructionOctree::bytesAfterAllocating(int level) const
{
    CellArena::Plan plan = m_arena.plan();
    forEachCellBelow(m_arena, m_root, 0, level, [&](std::uint32_t index) {
        const unsigned count = cell::count(cell::mask(m_arena.cell(index)));
        if (count > 0) plan.allocate(count);
    });
    return m_arena.bytesWithChunks(m_arena.chunks() + plan.newChunks());
}

bool ConstructionOctree::allocateLevel(int level)
{
    assert(level >= 0 && level < m_description.depth && "ConstructionOctree::allocateLevel(): level out of range");
    CellArena::Plan plan = m_arena.plan();
    forEachCellBelow(m_arena, m_root, 0, level, [&](std::uint32_t index) {
        const unsigned count = cell::count(cell::mask(m_arena.cell(index)));
        if (count > 0) plan.allocate(count);
    });
    if (!m_arena.canGrow(plan.newChunks())) return false;
    std::uint64_t added = 0;
    forEachCellBelow(m_arena, m_root, 0, level, [&](std::uint32_t index) {
        std::uint8_t* c = m_arena.cell(index);
        const unsigned count = cell::count(cell::mask(c));
        if (count == 0) return;
        const std::uint32_t table = m_arena.allocate(count);
        assert(table != CellArena::Exhausted && "ConstructionOctree::allocateLevel(): plan and arena disagree");
        std::memset(m_arena.cell(table), 0, std::size_t(count) * m_arena.cellBytes());
        cell::setValue(m_arena.cell(index), table);
        added += count;
    });
    m_description.cellsPerLevel[std::size_t(level) + 1] += added;
    return true;
}

std::uint32_t ConstructionOctree::findLeaf(const std::array<std::uint32_t, 3>& coords, Path& path) const
{
    const int depth = m_description.depth;
    int m = restartLevel(coords, path, depth);
    std::uint32_t index = path.cells[std::size_t(m)];
    path.coords = coords;
    for (; m < depth; ++m) {
        const std::uint8_t* c = m_arena.cell(index);
        const unsigned slot = slotAt(coords, depth - m - 1);
        const std::uint8_t mask = cell::mask(c);
        if (!(mask & (1u << slot))) {
            path.levels = m;
            return CellArena::Exhausted;
        }
        index = cell::value(c) + cell::rank(mask, slot);
        path.cells[std::size_t(m) + 1] = index;
    }
    path.levels = depth;
    return index;
}

void ConstructionOctree::average(std::uint32_t leaf, const PreparedPoint& point)
{
    if (m_arena.cellBytes() == CellArena::PlainCellBytes)
        averageCell<CellArena::PlainCellBytes>(m_arena.cellOf<CellArena::PlainCellBytes>(leaf), point);
    else
        averageCell<CellArena::ColourCellBytes>(m_arena.cellOf<CellArena::ColourCellBytes>(leaf), point);
}

template <unsigned CellBytes>
void ConstructionOctree::averageCell(std::uint8_t* c, const PreparedPoint& point)
{
    const std::uint32_t w = cell::value(c);
    if (w == 0) {
        cell::setNormal(c, point.firstCode);
    } else {
        const std::array<float, 3>& d = m_decode[cell::normal(c) & m_codeMask];
        const float fw = float(w);
        cell::setNormal(c, m_encode(d[0] * fw + point.normal[0], d[1] * fw + point.normal[1], d[2] * fw + point.normal[2]));
    }
    if constexpr (CellBytes == CellArena::ColourCellBytes) {
        std::uint8_t* rgb = cell::colour(c);
        const std::uint64_t w1 = std::uint64_t(w) + 1;
        for (int a = 0; a < 3; ++a)
            rgb[a] = std::uint8_t((std::uint64_t(rgb[a]) * w + point.colour[std::size_t(a)] + w1 / 2) / w1);
    }
    if (w != 0xFFFFFFFFu) cell::setValue(c, w + 1);
    ++m_description.points;
}

// ---- Pull ----

void ConstructionOctree::pullTable(std::uint32_t first, unsigned count, int level, PulledSubtrees* pulled,
                                   std::uint64_t* weights, SubtreeCells* out)
{
    if (pulled && level == pulled->level) {
        for (unsigned i = 0; i < count; ++i) weights[i] = pulled->weights[pulled->next++];
        return;
    }
    if (level == m_description.depth) {
        for (unsigned i = 0; i < count; ++i) weights[i] = cell::value(m_arena.cell(first + i));
        if (out) out->addLeaves(m_arena, first, count);
        return;
    }
    // The table's place in its level's cells (breadth-first order = the order tables are entered here).
    const std::size_t at = out ? out->reserve(level, m_arena, first, count) : 0;
    if (level + 1 < m_description.depth) {
        // The cells' own tables are visited one subtree after another: fetch them all now.
        for (unsigned i = 1; i < count; ++i) __builtin_prefetch(m_arena.cell(cell::value(m_arena.cell(first + i))));
    }
    // Each cell's sum from its children (pulled first); the codes are then encoded together, two at a
    // time, except for a single child of power-of-two weight, whose code is known exactly from a table.
    std::array<std::array<float, 3>, CellArena::MaxTable> sums;
    std::array<std::uint16_t, CellArena::MaxTable> codes;
    std::array<unsigned, CellArena::MaxTable> encoded;
    unsigned toEncode = 0;
    for (unsigned i = 0; i < count; ++i) {
        std::uint8_t* c = m_arena.cell(first + i);
        const std::uint32_t table = cell::value(c);
        const unsigned children = cell::count(cell::mask(c));
        std::array<std::uint64_t, CellArena::MaxTable> childWeights;
        pullTable(table, children, level + 1, pulled, childWeights.data(), out);
        std::uint64_t total = 0;
        if (children == 1 && (childWeights[0] & (childWeights[0] - 1)) == 0) {
            total = childWeights[0];
            cell::setNormal(c, m_reencode[cell::normal(m_arena.cell(table)) & m_codeMask]);
        } else {
            double sum[3] = {0, 0, 0};
            for (unsigned k = 0; k < children; ++k) {
                const std::array<float, 3>& d = m_decode[cell::normal(m_arena.cell(table + k)) & m_codeMask];
                total += childWeights[k];
                for (int a = 0; a < 3; ++a) sum[a] += double(childWeights[k]) * double(d[std::size_t(a)]);
            }
            sums[toEncode] = {float(sum[0]), float(sum[1]), float(sum[2])};
            encoded[toEncode++] = i;
        }
        weights[i] = total;
    }
    m_encode.encode(std::span(sums.data(), toEncode), std::span(codes.data(), toEncode));
    for (unsigned j = 0; j < toEncode; ++j) cell::setNormal(m_arena.cell(first + encoded[j]), codes[j]);
    if (out) out->setNormals(level, at, m_arena, first, count);
}

void ConstructionOctree::pull(unsigned threads)
{
    pullAndVisitLevels(threads, nullptr);
}

} // namespace stylos::core::octree
