#pragma once
// Test helpers implementing octree::OctreeLevels without any of the production code paths:
//  - ReferenceOctree: a brute-force octree built from points in memory, following the shared
//    definitions of the packed octree (leaf averaging in input order, pull) literally. Builders
//    must produce exactly its cells; writePoct of it must equal their files byte for byte.
//    Clarity over speed: a hash map from the leaf's Morton key to its accumulator, then levels by
//    sorting keys. Fine up to ~1 M points.
//  - ManualOctree: cells given by hand, level by level (no consistency checks, so tests can also
//    hand the writer inconsistent trees).
#include "stylos/core/io/PointBatch.h"
#include "stylos/core/octree/NormalCode.h"
#include "stylos/core/octree/OctreeLevels.h"
#include "stylos/core/octree/RootBox.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

namespace stylos::test {

/**
 * The Morton key of a cell: for each level from the top, its 3-bit child slot (x bit 0, y bit 1,
 * z bit 2), the top level's slot in the most significant position. Sorting the cells of one level by
 * key gives breadth-first order; key >> 3 is the parent's key.
 */
inline std::uint64_t mortonKey(std::uint32_t ix, std::uint32_t iy, std::uint32_t iz, int level)
{
    std::uint64_t key = 0;
    for (int b = level - 1; b >= 0; --b) {
        const unsigned slot = ((ix >> b) & 1u) | (((iy >> b) & 1u) << 1) | (((iz >> b) & 1u) << 2);
        key = (key << 3) | slot;
    }
    return key;
}

/** Integer coordinates of a Morton key at @p level (inverse of mortonKey). */
inline std::array<std::uint32_t, 3> mortonCoords(std::uint64_t key, int level)
{
    std::array<std::uint32_t, 3> c{0, 0, 0};
    for (int b = 0; b < level; ++b) {
        const unsigned slot = static_cast<unsigned>((key >> (3 * b)) & 7u);
        c[0] |= (slot & 1u) << b;
        c[1] |= ((slot >> 1) & 1u) << b;
        c[2] |= ((slot >> 2) & 1u) << b;
    }
    return c;
}

/**
 * The input normal as the leaf averaging uses it: normalised in float (length = sqrt((x·x + y·y) +
 * z·z) in float, each component divided by it); (0,0,0) when the length is 0 or not finite.
 */
inline std::array<float, 3> referenceUnitNormal(float x, float y, float z)
{
    const float len = std::sqrt(x * x + y * y + z * z);
    if (!(len > 0.0f) || !std::isfinite(len)) return {0.0f, 0.0f, 0.0f};
    return {x / len, y / len, z / len};
}

/** Brute-force octree of points in memory (see the file comment). */
class ReferenceOctree final : public core::octree::OctreeLevels {
public:
    /**
     * @p positions x y z interleaved (3n), @p normals 3n, @p colours r g b (3n, or empty: no colour).
     * Points with a non-finite position are skipped (as the readers do). @p box defaults to
     * RootBox::enclosing of the finite points' bounds. @p blockCells: largest block visitLevel() hands
     * out (small values exercise the writer's block handling).
     */
    ReferenceOctree(std::span<const double> positions, std::span<const float> normals,
                    std::span<const std::uint8_t> colours, int depth,
                    core::octree::NormalCodeKind kind = core::octree::NormalCodeKind::Octahedral16,
                    std::optional<core::octree::RootBox> box = std::nullopt, std::size_t blockCells = 4096)
        : m_blockCells(blockCells)
    {
        assert(positions.size() % 3 == 0 && "ReferenceOctree: positions not x y z triples");
        assert(normals.size() == positions.size() && "ReferenceOctree: one normal per point needed");
        assert((colours.empty() || colours.size() == positions.size()) && "ReferenceOctree: colours size");
        assert(depth >= core::octree::MinOctreeDepth && depth <= core::octree::MaxOctreeDepth);
        const std::size_t n = positions.size() / 3;
        auto finite = [&](std::size_t i) {
            return std::isfinite(positions[3 * i]) && std::isfinite(positions[3 * i + 1]) &&
                   std::isfinite(positions[3 * i + 2]);
        };
        if (!box) {
            std::array<double, 6> b{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
            for (std::size_t i = 0; i < n; ++i) {
                if (!finite(i)) continue;
                for (int a = 0; a < 3; ++a) {
                    b[a] = std::min(b[a], positions[3 * i + a]);
                    b[3 + a] = std::max(b[3 + a], positions[3 * i + a]);
                }
            }
            assert(b[0] <= b[3] && "ReferenceOctree: no finite point");
            box = core::octree::RootBox::enclosing(b);
        }
        m_description.box = *box;
        m_description.depth = depth;
        m_description.normalCode = kind;
        m_description.hasColour = !colours.empty();

        // Leaf averaging, in input order.
        struct Leaf {
            std::uint32_t weight = 0;
            std::uint16_t code = 0;
            std::array<std::uint8_t, 3> colour{0, 0, 0};
        };
        std::unordered_map<std::uint64_t, Leaf> leaves;
        for (std::size_t i = 0; i < n; ++i) {
            if (!finite(i)) continue;
            ++m_description.points;
            const auto c = box->quantise(&positions[3 * i], depth);
            Leaf& leaf = leaves[mortonKey(c[0], c[1], c[2], depth)];
            const auto u = referenceUnitNormal(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
            const std::uint32_t w = leaf.weight;
            if (w == 0) {
                leaf.code = core::octree::encodeNormal(kind, u[0], u[1], u[2]);
            } else {
                const auto d = core::octree::decodeNormal(kind, leaf.code);
                const float fw = static_cast<float>(w);
                const float vx = d[0] * fw + u[0];
                const float vy = d[1] * fw + u[1];
                const float vz = d[2] * fw + u[2];
                leaf.code = core::octree::encodeNormal(kind, vx, vy, vz);
            }
            if (!colours.empty()) {
                for (int a = 0; a < 3; ++a) {
                    const std::uint64_t oldC = leaf.colour[a];
                    const std::uint64_t newC = colours[3 * i + a];
                    const std::uint64_t w1 = std::uint64_t(w) + 1;
                    leaf.colour[a] = static_cast<std::uint8_t>((oldC * w + newC + w1 / 2) / w1);
                }
            }
            if (leaf.weight != 0xFFFFFFFFu) ++leaf.weight;
        }
        assert(!leaves.empty() && "ReferenceOctree: no finite point");

        // Levels, leaves first, by sorting keys.
        m_levels.resize(static_cast<std::size_t>(depth) + 1);
        Level& leafLevel = m_levels[static_cast<std::size_t>(depth)];
        for (const auto& [key, leaf] : leaves) leafLevel.keys.push_back(key);
        std::sort(leafLevel.keys.begin(), leafLevel.keys.end());
        for (std::uint64_t key : leafLevel.keys) {
            const Leaf& leaf = leaves.at(key);
            leafLevel.normals.push_back(leaf.code);
            leafLevel.weights.push_back(leaf.weight);
            if (m_description.hasColour)
                leafLevel.colours.insert(leafLevel.colours.end(), leaf.colour.begin(), leaf.colour.end());
        }

        // Pull, bottom up: children of a parent are consecutive in the sorted child level.
        for (int l = depth - 1; l >= 0; --l) {
            const Level& child = m_levels[static_cast<std::size_t>(l) + 1];
            Level& level = m_levels[static_cast<std::size_t>(l)];
            std::size_t i = 0;
            while (i < child.keys.size()) {
                const std::uint64_t parent = child.keys[i] >> 3;
                std::uint8_t mask = 0;
                std::uint64_t weight = 0;
                double sum[3] = {0, 0, 0};
                for (; i < child.keys.size() && (child.keys[i] >> 3) == parent; ++i) {
                    mask = static_cast<std::uint8_t>(mask | (1u << (child.keys[i] & 7u)));
                    weight += child.weights[i];
                    const auto d = core::octree::decodeNormal(kind, child.normals[i]);
                    for (int a = 0; a < 3; ++a) sum[a] += static_cast<double>(child.weights[i]) * double(d[a]);
                }
                level.keys.push_back(parent);
                level.masks.push_back(mask);
                level.weights.push_back(weight);
                level.normals.push_back(core::octree::encodeNormal(kind, static_cast<float>(sum[0]),
                                                                   static_cast<float>(sum[1]),
                                                                   static_cast<float>(sum[2])));
            }
        }
        for (const Level& level : m_levels) m_description.cellsPerLevel.push_back(level.keys.size());
    }

    /** From a reader's batch (normals required; colours used when present). */
    static ReferenceOctree fromBatch(const core::io::PointBatch& batch, int depth,
                                     core::octree::NormalCodeKind kind = core::octree::NormalCodeKind::Octahedral16,
                                     std::optional<core::octree::RootBox> box = std::nullopt,
                                     std::size_t blockCells = 4096)
    {
        return ReferenceOctree(batch.positions, batch.normals, batch.colors, depth, kind, box, blockCells);
    }

    const core::octree::OctreeDescription& description() const override { return m_description; }

    void visitLevel(int level, const std::function<void(const core::octree::CellBlock&)>& sink) const override
    {
        assert(level >= 0 && level <= m_description.depth && "ReferenceOctree::visitLevel(): level out of range");
        const Level& l = m_levels[static_cast<std::size_t>(level)];
        const std::size_t n = l.keys.size();
        for (std::size_t begin = 0; begin < n; begin += m_blockCells) {
            const std::size_t count = std::min(m_blockCells, n - begin);
            core::octree::CellBlock block;
            if (!l.masks.empty()) block.masks = std::span<const std::uint8_t>(l.masks).subspan(begin, count);
            block.normals = std::span<const std::uint16_t>(l.normals).subspan(begin, count);
            if (!l.colours.empty())
                block.colours = std::span<const std::uint8_t>(l.colours).subspan(3 * begin, 3 * count);
            sink(block);
        }
    }

    std::size_t cellCount(int level) const { return m_levels[static_cast<std::size_t>(level)].keys.size(); }
    /** Morton keys of a level's cells, in breadth-first order. */
    const std::vector<std::uint64_t>& keys(int level) const { return m_levels[static_cast<std::size_t>(level)].keys; }
    /** Child masks of an inner level (empty at the leaf level). */
    const std::vector<std::uint8_t>& masks(int level) const { return m_levels[static_cast<std::size_t>(level)].masks; }
    const std::vector<std::uint16_t>& normals(int level) const
    {
        return m_levels[static_cast<std::size_t>(level)].normals;
    }
    /** Weights: points averaged into the cell (leaves saturate at 2^32 − 1; inner cells sum their children). */
    const std::vector<std::uint64_t>& weights(int level) const
    {
        return m_levels[static_cast<std::size_t>(level)].weights;
    }
    /** Leaf colours r g b (empty without colour). */
    const std::vector<std::uint8_t>& colours() const { return m_levels.back().colours; }
    /** Integer coordinates of cell @p index of @p level. */
    std::array<std::uint32_t, 3> coords(int level, std::size_t index) const
    {
        return mortonCoords(keys(level)[index], level);
    }
    /** Breadth-first index at level + 1 of the first child of cell @p index (by binary search). */
    std::uint64_t firstChild(int level, std::size_t index) const
    {
        const auto& child = keys(level + 1);
        const std::uint64_t k = keys(level)[index] << 3;
        return static_cast<std::uint64_t>(std::lower_bound(child.begin(), child.end(), k) - child.begin());
    }

private:
    struct Level {
        std::vector<std::uint64_t> keys;
        std::vector<std::uint8_t> masks;
        std::vector<std::uint16_t> normals;
        std::vector<std::uint64_t> weights;
        std::vector<std::uint8_t> colours;
    };
    core::octree::OctreeDescription m_description;
    std::vector<Level> m_levels;
    std::size_t m_blockCells;
};

/**
 * An octree given cell by cell: per level its masks (empty for the leaf level), normal codes and, at
 * the leaf level, colours. description().cellsPerLevel is taken from the normals' sizes. Nothing is
 * checked, so it can describe broken trees too.
 */
class ManualOctree final : public core::octree::OctreeLevels {
public:
    struct Level {
        std::vector<std::uint8_t> masks;
        std::vector<std::uint16_t> normals;
        std::vector<std::uint8_t> colours;
    };

    ManualOctree(core::octree::OctreeDescription description, std::vector<Level> levels, std::size_t blockCells = 4096)
        : m_description(std::move(description)), m_levels(std::move(levels)), m_blockCells(blockCells)
    {
        m_description.depth = static_cast<int>(m_levels.size()) - 1;
        m_description.cellsPerLevel.clear();
        for (const Level& l : m_levels) m_description.cellsPerLevel.push_back(l.normals.size());
    }

    /** The smallest tree: a root with the children in @p rootMask, all leaves at level 1. */
    static ManualOctree twoLevels(std::uint8_t rootMask, bool colour = false)
    {
        core::octree::OctreeDescription d;
        d.box = core::octree::RootBox{{0, 0, 0}, 1.0};
        d.hasColour = colour;
        std::vector<Level> levels(2);
        levels[0].masks = {rootMask};
        levels[0].normals = {core::octree::encodeNormal(d.normalCode, 0, 0, 1)};
        for (unsigned s = 0; s < 8; ++s) {
            if (!(rootMask & (1u << s))) continue;
            levels[1].normals.push_back(core::octree::encodeNormal(d.normalCode, (s & 1) ? 1.f : -1.f,
                                                                   (s & 2) ? 1.f : -1.f, (s & 4) ? 1.f : -1.f));
            if (colour)
                levels[1].colours.insert(levels[1].colours.end(), {std::uint8_t(10 * s), std::uint8_t(20 * s), 200});
            ++d.points;
        }
        return ManualOctree(std::move(d), std::move(levels));
    }

    const core::octree::OctreeDescription& description() const override { return m_description; }
    core::octree::OctreeDescription& mutableDescription() { return m_description; }

    void visitLevel(int level, const std::function<void(const core::octree::CellBlock&)>& sink) const override
    {
        const Level& l = m_levels[static_cast<std::size_t>(level)];
        const std::size_t n = l.normals.size();
        for (std::size_t begin = 0; begin < n; begin += m_blockCells) {
            const std::size_t count = std::min(m_blockCells, n - begin);
            core::octree::CellBlock block;
            // Short mask or colour arrays give short blocks (broken trees for the writer's checks).
            const std::size_t mb = std::min(begin, l.masks.size());
            const std::size_t cb = std::min(3 * begin, l.colours.size());
            if (!l.masks.empty())
                block.masks = std::span<const std::uint8_t>(l.masks).subspan(mb, std::min(count, l.masks.size() - mb));
            block.normals = std::span<const std::uint16_t>(l.normals).subspan(begin, count);
            if (!l.colours.empty())
                block.colours =
                    std::span<const std::uint8_t>(l.colours).subspan(cb, std::min(3 * count, l.colours.size() - cb));
            sink(block);
        }
    }

private:
    core::octree::OctreeDescription m_description;
    std::vector<Level> m_levels;
    std::size_t m_blockCells;
};

} // namespace stylos::test
