#pragma once
/** @file
 * @brief The memory layer of the construction octree (Duguet et al., VAST 2004, section 3): cells packed
 *        7 bytes each (10 with colour) in chunks of 2,048 cells, handing out child tables of exactly 1..8
 *        cells. A table never spans two chunks, so its cells have consecutive global indices. The overhead
 *        is per chunk (one pointer), never per cell or per table.
 *
 * Cell layout (native byte order, unaligned): byte 0 the child mask, bytes 1–2 the normal code, bytes 3–6
 * the value (child-table index of an inner cell, weight of a leaf), bytes 7–9 the leaf's average RGB
 * when the octree has colour.
 *
 * Released tables go to a free list of their size, linked through their own first four bytes, and are
 * handed out again first, so re-allocation in random order reuses memory. When the current chunk's tail
 * is too short for a table, the tail goes to the free list of its size and a new chunk is started.
 *
 * Memory: bytes() counts the chunks and the chunk table; allocate() refuses (returns Exhausted) rather than
 * exceed the limit or the 32-bit index space. Chunks are never returned before the arena dies. On Linux
 * the chunks lie one after another in one reserved address range, made usable 2 MiB at a time and
 * advised for transparent huge pages: a cell's address is then base + index · cell size (no chunk table
 * look-up), and the random walks of construction, pull and listing miss the TLB far less. bytes()
 * counts chunks; the resident memory can exceed it by the unused rest of the last 2 MiB (a huge page is
 * resident as a whole). Elsewhere chunks come from new[].
 * Thread-safety: allocate/release are not thread-safe; concurrent reads, and concurrent writes to
 * distinct cells, are safe once the cells exist.
 */
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace stylos::core::octree {

class CellArena {
public:
    static constexpr unsigned ChunkShift = 11;
    static constexpr std::uint32_t ChunkCells = 1u << ChunkShift;  ///< cells per chunk
    static constexpr unsigned MaxTable = 8;                           ///< largest table, cells
    static constexpr std::uint32_t Exhausted = 0xFFFFFFFFu;           ///< allocate() could not
    static constexpr unsigned PlainCellBytes = 7;
    static constexpr unsigned ColourCellBytes = 10;

    /** @brief Plans the chunks a sequence of allocations would add, without allocating (exact). */
    class Plan {
    public:
        /** @brief Counts one allocate(@p cells). */
        void allocate(unsigned cells);
        /** @brief Chunks the planned allocations start. */
        std::uint64_t newChunks() const { return m_newChunks; }

    private:
        friend class CellArena;
        std::array<std::uint64_t, MaxTable + 1> m_free{};
        std::uint32_t m_used = ChunkCells;
        std::uint64_t m_newChunks = 0;
    };

    /**
     * @brief An empty arena of cells of @p cellBytes (7, or 10 with colour) that never grows beyond
     *        @p limitBytes (0: no limit but the 32-bit index space).
     */
    explicit CellArena(unsigned cellBytes = PlainCellBytes, std::uint64_t limitBytes = 0);
    ~CellArena();
    CellArena(const CellArena&) = delete;
    CellArena& operator=(const CellArena&) = delete;
    /** @brief Takes @p other's chunks; @p other is left empty. */
    CellArena(CellArena&& other) noexcept;
    CellArena& operator=(CellArena&& other) noexcept;

    /**
     * @brief A table of @p cells (1..8) consecutive cells, NOT initialised; its first cell's global index.
     *        Exhausted (and nothing changes) if a new chunk would pass the limit or the index space.
     */
    std::uint32_t allocate(unsigned cells)
    {
        const std::uint32_t head = m_freeHead[cells];
        if (head != NoTable) {
            std::memcpy(&m_freeHead[cells], cell(head), sizeof(std::uint32_t));
            --m_freeCount[cells];
            return head;
        }
        if (m_used + cells <= ChunkCells) {
            const std::uint32_t first = m_lastChunkBase + m_used;
            m_used += cells;
            return first;
        }
        return allocateInNewChunk(cells);
    }
    /** @brief Returns the table at @p first of @p cells cells (as allocated) to the free list of its size. */
    void release(std::uint32_t first, unsigned cells)
    {
        std::memcpy(cell(first), &m_freeHead[cells], sizeof(std::uint32_t));
        m_freeHead[cells] = first;
        ++m_freeCount[cells];
    }

    /** @brief Address of cell @p index (a valid, allocated index). */
    std::uint8_t* cell(std::uint32_t index) const
    {
        if (m_base) return m_base + std::size_t(index) * m_cellBytes;
        return m_chunks[index >> ChunkShift] + std::size_t(index & (ChunkCells - 1)) * m_cellBytes;
    }
    /** @brief cell() for a cell size known at compile time (== cellBytes()). */
    template <unsigned CellBytes>
    std::uint8_t* cellOf(std::uint32_t index) const
    {
        if (m_base) return m_base + std::size_t(index) * CellBytes;
        return m_chunks[index >> ChunkShift] + std::size_t(index & (ChunkCells - 1)) * CellBytes;
    }

    unsigned cellBytes() const { return m_cellBytes; }
    std::uint64_t limitBytes() const { return m_limit; }
    std::uint64_t chunkBytes() const { return std::uint64_t(ChunkCells) * m_cellBytes; }
    std::uint64_t chunks() const { return m_chunks.size(); }
    /** @brief Bytes held now: chunks plus the chunk table. Never shrinks, so it is also the peak. */
    std::uint64_t bytes() const { return bytesWithChunks(m_chunks.size()); }
    /** @brief Bytes the arena would hold with @p chunks chunks. */
    std::uint64_t bytesWithChunks(std::uint64_t chunks) const;
    /** @brief Whether @p extraChunks more chunks fit the limit and the index space. */
    bool canGrow(std::uint64_t extraChunks) const;
    /** @brief Cells currently on free lists, per table size (index 1..8). */
    std::array<std::uint64_t, MaxTable + 1> freeCells() const;
    /** @brief A plan starting from the arena's current state. */
    Plan plan() const;

private:
    static constexpr std::uint32_t NoTable = 0xFFFFFFFFu;
    std::uint32_t allocateInNewChunk(unsigned cells);
    std::uint8_t* newChunkMemory();

    std::vector<std::uint8_t*> m_chunks;        ///< chunk addresses
    std::uint8_t* m_base = nullptr;             ///< Linux: chunk k at m_base + k · chunkBytes() (else null)
    std::vector<std::uint8_t*> m_ownedChunks;   ///< elsewhere: chunks from new[]
    void* m_mapping = nullptr;                  ///< the reserved address range (munmap'ed at the end)
    std::size_t m_mappingBytes = 0;
    std::size_t m_reserved = 0;                 ///< bytes from m_base that may become chunks
    std::size_t m_committed = 0;                ///< bytes from m_base made usable so far
    std::array<std::uint32_t, MaxTable + 1> m_freeHead;
    std::array<std::uint64_t, MaxTable + 1> m_freeCount{};
    std::uint32_t m_used = ChunkCells;   ///< cells used in the last chunk
    std::uint32_t m_lastChunkBase = 0;   ///< global index of the last chunk's first cell
    unsigned m_cellBytes;
    std::uint64_t m_limit;
};

/** @brief Field access on a packed cell (see the layout in the file comment). */
namespace cell {
inline std::uint8_t mask(const std::uint8_t* c) { return c[0]; }
inline void setMask(std::uint8_t* c, std::uint8_t m) { c[0] = m; }
inline std::uint16_t normal(const std::uint8_t* c)
{
    std::uint16_t v;
    std::memcpy(&v, c + 1, 2);
    return v;
}
inline void setNormal(std::uint8_t* c, std::uint16_t v) { std::memcpy(c + 1, &v, 2); }
inline std::uint32_t value(const std::uint8_t* c)
{
    std::uint32_t v;
    std::memcpy(&v, c + 3, 4);
    return v;
}
inline void setValue(std::uint8_t* c, std::uint32_t v) { std::memcpy(c + 3, &v, 4); }
inline std::uint8_t* colour(std::uint8_t* c) { return c + 7; }
/** @brief Number of set bits of a mask (a table: the baseline x86-64 target has no popcount instruction). */
inline unsigned count(std::uint8_t mask)
{
    static constexpr auto table = [] {
        std::array<std::uint8_t, 256> t{};
        for (unsigned m = 0; m < 256; ++m)
            for (unsigned b = m; b; b >>= 1) t[m] = std::uint8_t(t[m] + (b & 1u));
        return t;
    }();
    return table[mask];
}
/** @brief Position of the child in @p slot within the table of a cell with @p mask (children before it). */
inline unsigned rank(std::uint8_t mask, unsigned slot) { return count(std::uint8_t(mask & ((1u << slot) - 1))); }
inline const std::uint8_t* colour(const std::uint8_t* c) { return c + 7; }
} // namespace cell

} // namespace stylos::core::octree
