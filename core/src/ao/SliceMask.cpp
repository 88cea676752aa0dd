#include "SliceMask.h"

#include <algorithm>

namespace stylos::core::ao::detail {

namespace {

constexpr std::uint64_t EmptyKey = ~std::uint64_t{0};
constexpr std::size_t DenseTiles = std::size_t{1} << 22;

std::size_t hashOf(std::uint64_t key)
{
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdULL;
    key ^= key >> 33;
    return std::size_t(key);
}

} // namespace

void SliceMask::reset(int width, int height, int gap)
{
    assert(width >= 0 && height >= 0 && "SliceMask::reset(): negative size");
    m_gap = std::uint32_t(std::max(1, gap));
    m_width = width;
    m_height = height;
    m_tileColumns = (width + TileSide - 1) >> TileBits;
    const int tileRows = (height + TileSide - 1) >> TileBits;
    const std::size_t tiles = std::size_t(m_tileColumns) * std::size_t(tileRows);
    m_dense = tiles <= DenseTiles;
    if (m_dense) {
        m_directory.assign(tiles, -1);
    } else {
        m_directory.clear();
        m_hashKeys.assign(std::max<std::size_t>(m_hashKeys.size(), 1024), EmptyKey);
        m_hashTiles.resize(m_hashKeys.size());
    }
    m_tilesUsed = 0;
}

std::int32_t SliceMask::allocateTile()
{
    constexpr std::size_t cellsPerTile = std::size_t(TileSide) * TileSide;
    const std::size_t first = std::size_t(m_tilesUsed) * cellsPerTile;
    if (m_cells.size() < first + cellsPerTile) m_cells.resize(first + cellsPerTile);
    std::fill(m_cells.begin() + std::ptrdiff_t(first), m_cells.begin() + std::ptrdiff_t(first + cellsPerTile),
              Cell{1.0f, 1.0f, 0u, 0u});
    return m_tilesUsed++;
}

std::int32_t SliceMask::findTile(std::uint64_t key) const
{
    const std::size_t mask = m_hashKeys.size() - 1;
    for (std::size_t s = hashOf(key) & mask;; s = (s + 1) & mask) {
        if (m_hashKeys[s] == key) return m_hashTiles[s];
        if (m_hashKeys[s] == EmptyKey) return -1;
    }
}

std::int32_t SliceMask::findOrAddTile(std::uint64_t key)
{
    if (2 * std::size_t(m_tilesUsed + 1) > m_hashKeys.size()) { // keep the load ≤ ½: grow and re-insert
        std::vector<std::uint64_t> keys(2 * m_hashKeys.size(), EmptyKey);
        std::vector<std::int32_t> tiles(keys.size());
        for (std::size_t s = 0; s < m_hashKeys.size(); ++s) {
            if (m_hashKeys[s] == EmptyKey) continue;
            std::size_t t = hashOf(m_hashKeys[s]) & (keys.size() - 1);
            while (keys[t] != EmptyKey) t = (t + 1) & (keys.size() - 1);
            keys[t] = m_hashKeys[s];
            tiles[t] = m_hashTiles[s];
        }
        m_hashKeys.swap(keys);
        m_hashTiles.swap(tiles);
    }
    const std::size_t mask = m_hashKeys.size() - 1;
    std::size_t s = hashOf(key) & mask;
    for (; m_hashKeys[s] != EmptyKey; s = (s + 1) & mask)
        if (m_hashKeys[s] == key) return m_hashTiles[s];
    m_hashKeys[s] = key;
    m_hashTiles[s] = allocateTile();
    return m_hashTiles[s];
}

} // namespace stylos::core::ao::detail
