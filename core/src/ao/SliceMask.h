#pragma once
// Internal to core/ao: the Slices kernel's occlusion mask, sparse, in the light's frame.
#include <cassert>
#include <cstdint>
#include <vector>

namespace stylos::core::ao::detail {

/**
 * A 2D grid of mask cells holding the light's transmittance T = 1 − o along each ray, stored in tiles
 * of 32 × 32 mask cells that are allocated (and set to T = 1) when first written: memory and reset cost
 * grow with the area the cells' shadows cover, never with the grid's box. The tiles are found through a
 * dense directory (4 bytes per tile of the box) up to 4 Mi tiles, a hash table beyond (deep levels).
 *
 * Slices are composed one step at a time (k = 0, 1, ... from the sky), each mask cell at most once per
 * step with the slice's total coverage c of it: T ← T · (1 − c), i.e. o ← 1 − (1 − o)(1 − c).
 *
 * For the self-shadowing tolerance every mask cell also remembers where its current burst began — a
 * burst is a run of steps at most `gap` apart that wrote to it, i.e. one surface crossed by the ray —
 * and T before it. A reader that ignores the steps ≥ firstIgnored (too near it along the ray) reads T
 * before the burst when the burst began there, else T (a burst that began before counts whole).
 * Not thread-safe: one per kernel.
 */
class SliceMask {
public:
    static constexpr int TileBits = 5;
    static constexpr int TileSide = 1 << TileBits;

    /** Empties the mask and sizes it to @p width × @p height mask cells; @p gap ≥ 1: see above. */
    void reset(int width, int height, int gap);

    /** Transmittance at (x, y) for a reader that ignores the steps ≥ @p firstIgnored. */
    float visible(int x, int y, std::int64_t firstIgnored) const
    {
        assert(x >= 0 && y >= 0 && x < m_width && y < m_height && "SliceMask::visible(): outside the mask");
        const std::int32_t tile = m_dense ? m_directory[tileOf(x, y)] : findTile(tileKey(x, y));
        if (tile < 0) return 1.0f;
        const Cell& c = m_cells[std::size_t(tile) * TileSide * TileSide + inTile(x, y)];
        return std::int64_t(c.burst) - 1 >= firstIgnored ? c.before : c.t;
    }

    /** Composes coverage @p coverage (clamped to [0, 1]) of (x, y) by step @p step (never decreasing). */
    void compose(int x, int y, float coverage, std::uint32_t step)
    {
        assert(x >= 0 && y >= 0 && x < m_width && y < m_height && "SliceMask::compose(): outside the mask");
        std::int32_t tile;
        if (m_dense) {
            std::int32_t& entry = m_directory[tileOf(x, y)];
            if (entry < 0) entry = allocateTile();
            tile = entry;
        } else {
            tile = findOrAddTile(tileKey(x, y));
        }
        Cell& c = m_cells[std::size_t(tile) * TileSide * TileSide + inTile(x, y)];
        const std::uint32_t stamp = step + 1;
        if (c.last == 0 || stamp - c.last > m_gap) {
            c.before = c.t;
            c.burst = stamp;
        }
        c.last = stamp;
        c.t *= coverage < 1.0f ? 1.0f - coverage : 0.0f;
    }

    int width() const { return m_width; }
    int height() const { return m_height; }
    /** Tiles written since the last reset. */
    int tilesUsed() const { return m_tilesUsed; }
    /** Bytes held (tiles kept between directions, the directory). */
    std::size_t bytes() const
    {
        return m_cells.capacity() * sizeof(Cell) + m_directory.capacity() * 4 + m_hashKeys.capacity() * 12;
    }

private:
    struct Cell {
        float t;             ///< transmittance
        float before;        ///< t before the current burst
        std::uint32_t last;  ///< 1 + the last step that wrote here; 0: never
        std::uint32_t burst; ///< 1 + the first step of the current burst
    };

    std::size_t tileOf(int x, int y) const
    {
        return std::size_t(y >> TileBits) * std::size_t(m_tileColumns) + std::size_t(x >> TileBits);
    }
    static std::size_t inTile(int x, int y)
    {
        return std::size_t(((y & (TileSide - 1)) << TileBits) | (x & (TileSide - 1)));
    }
    std::uint64_t tileKey(int x, int y) const
    {
        return (std::uint64_t(std::uint32_t(y >> TileBits)) << 32) | std::uint32_t(x >> TileBits);
    }
    std::int32_t allocateTile();
    std::int32_t findTile(std::uint64_t key) const;
    std::int32_t findOrAddTile(std::uint64_t key);

    bool m_dense = true;
    std::vector<std::int32_t> m_directory; ///< dense: per tile of the box, its index in m_cells, or −1
    std::vector<std::uint64_t> m_hashKeys; ///< sparse: open addressing (linear probing), EmptyKey when free
    std::vector<std::int32_t> m_hashTiles; ///< sparse: the tile of each key
    std::vector<Cell> m_cells;             ///< the tiles, TileSide² cells each, reused between resets
    int m_width = 0, m_height = 0, m_tileColumns = 0, m_tilesUsed = 0;
    std::uint32_t m_gap = 1;
};

} // namespace stylos::core::ao::detail
