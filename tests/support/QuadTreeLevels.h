#pragma once
// A large procedural octree for tests and benchmarks of big .poct files (PackedOctreeTest, FileOpenBenchmark).
#include "stylos/core/octree/OctreeLevels.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace stylos::test {

/**
 * A large procedural tree: every inner cell has 4 children (masks drawn from the 70 four-bit
 * patterns by a hash of the index), so level l has 4^l cells; normals are hashed too.
 */
class QuadTreeLevels final : public core::octree::OctreeLevels {
public:
    explicit QuadTreeLevels(int depth)
    {
        for (unsigned m = 0; m < 256; ++m)
            if (std::popcount(m) == 4) m_patterns.push_back(static_cast<std::uint8_t>(m));
        m_d.depth = depth;
        m_d.box = core::octree::RootBox{{0, 0, 0}, 2.0};
        for (int l = 0; l <= depth; ++l) m_d.cellsPerLevel.push_back(std::uint64_t(1) << (2 * l));
        m_d.points = m_d.cellsPerLevel.back();
    }
    const core::octree::OctreeDescription& description() const override { return m_d; }
    void visitLevel(int level, const std::function<void(const core::octree::CellBlock&)>& sink) const override
    {
        constexpr std::size_t Block = 1 << 15;
        std::vector<std::uint8_t> masks(Block);
        std::vector<std::uint16_t> normals(Block);
        const std::uint64_t n = m_d.cellsPerLevel[static_cast<std::size_t>(level)];
        for (std::uint64_t b = 0; b < n; b += Block) {
            const std::size_t count = static_cast<std::size_t>(std::min<std::uint64_t>(Block, n - b));
            for (std::size_t i = 0; i < count; ++i) {
                const std::uint64_t h = (b + i + 1) * 0x9E3779B97F4A7C15ull;
                masks[i] = m_patterns[(h >> 40) % m_patterns.size()];
                normals[i] = static_cast<std::uint16_t>(h >> 20);
            }
            core::octree::CellBlock block;
            if (level < m_d.depth) block.masks = std::span<const std::uint8_t>(masks.data(), count);
            block.normals = std::span<const std::uint16_t>(normals.data(), count);
            sink(block);
        }
    }

private:
    core::octree::OctreeDescription m_d;
    std::vector<std::uint8_t> m_patterns;
};

} // namespace stylos::test
