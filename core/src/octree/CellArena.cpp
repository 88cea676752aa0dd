#include "stylos/core/octree/CellArena.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstdint>
#include <new>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace stylos::core::octree {

namespace {

/** Most chunks a 32-bit cell index can address (Exhausted stays free as a marker). */
constexpr std::uint64_t maxChunks = (std::uint64_t(1) << (32 - CellArena::ChunkShift)) - 1;

/** Granule of the reserved region that is made usable at a time (one transparent huge page). */
constexpr std::size_t hugePage = std::size_t(2) << 20;

std::size_t roundUp(std::size_t bytes, std::size_t granule)
{
    return (bytes + granule - 1) / granule * granule;
}

/** Capacity of the chunk table holding @p chunks chunks (it grows by doubling from 64). */
std::uint64_t tableCapacity(std::uint64_t chunks)
{
    return chunks <= 64 ? 64 : std::bit_ceil(chunks);
}

} // namespace

void CellArena::Plan::allocate(unsigned cells)
{
    assert(cells >= 1 && cells <= MaxTable && "CellArena::Plan::allocate(): table size out of range");
    if (m_free[cells] > 0) {
        --m_free[cells];
        return;
    }
    if (m_used + cells > ChunkCells) {
        if (m_used < ChunkCells) ++m_free[ChunkCells - m_used];
        ++m_newChunks;
        m_used = 0;
    }
    m_used += cells;
}

CellArena::CellArena(unsigned cellBytes, std::uint64_t limitBytes) : m_cellBytes(cellBytes), m_limit(limitBytes)
{
    assert((cellBytes == PlainCellBytes || cellBytes == ColourCellBytes) && "CellArena::CellArena(): cell size");
    m_freeHead.fill(NoTable);
}

CellArena::CellArena(CellArena&& other) noexcept
    : m_chunks(std::exchange(other.m_chunks, {})), m_base(std::exchange(other.m_base, nullptr)),
      m_ownedChunks(std::exchange(other.m_ownedChunks, {})), m_mapping(std::exchange(other.m_mapping, nullptr)),
      m_mappingBytes(std::exchange(other.m_mappingBytes, 0)), m_reserved(std::exchange(other.m_reserved, 0)),
      m_committed(std::exchange(other.m_committed, 0)), m_freeHead(other.m_freeHead), m_freeCount(other.m_freeCount),
      m_used(std::exchange(other.m_used, ChunkCells)), m_lastChunkBase(other.m_lastChunkBase),
      m_cellBytes(other.m_cellBytes), m_limit(other.m_limit)
{
    other.m_freeHead.fill(NoTable);
    other.m_freeCount = {};
}

CellArena& CellArena::operator=(CellArena&& other) noexcept
{
    if (this != &other) {
        this->~CellArena();
        new (this) CellArena(std::move(other));
    }
    return *this;
}

CellArena::~CellArena()
{
#if defined(__linux__)
    if (m_mapping) munmap(m_mapping, m_mappingBytes);
#endif
    for (std::uint8_t* chunk : m_ownedChunks) delete[] chunk;
}

std::uint8_t* CellArena::newChunkMemory()
{
    const std::size_t bytes = std::size_t(chunkBytes());
#if defined(__linux__)
    if (!m_mapping && m_chunks.empty()) {
        // Reserve address space for every chunk the limit (or the index space) allows, without memory:
        // chunk k then lies at m_base + k · chunkBytes, so a cell's address is one multiplication away.
        const std::uint64_t chunks = m_limit ? std::min(maxChunks, m_limit / bytes + 1) : maxChunks;
        const std::size_t reserve = roundUp(std::size_t(chunks) * bytes, hugePage);
        void* p = mmap(nullptr, reserve + hugePage, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
        if (p != MAP_FAILED) {
            m_mapping = p;
            m_mappingBytes = reserve + hugePage;
            m_base = reinterpret_cast<std::uint8_t*>(roundUp(reinterpret_cast<std::uintptr_t>(p), hugePage));
            m_reserved = reserve;
        }
    }
    if (m_base) {
        const std::size_t end = (m_chunks.size() + 1) * bytes;
        if (end > m_committed) {
            // Made usable 2 MiB at a time, advised for transparent huge pages: the random walks over
            // hundreds of MiB of cells then miss the TLB far less.
            const std::size_t grow = roundUp(end - m_committed, hugePage);
            if (m_committed + grow > m_reserved) return nullptr;
            if (mprotect(m_base + m_committed, grow, PROT_READ | PROT_WRITE) != 0) return nullptr;
            madvise(m_base + m_committed, grow, MADV_HUGEPAGE);
            m_committed += grow;
        }
        return m_base + m_chunks.size() * bytes;
    }
#endif
    m_ownedChunks.push_back(new std::uint8_t[bytes]);
    return m_ownedChunks.back();
}

std::uint64_t CellArena::bytesWithChunks(std::uint64_t chunks) const
{
    return chunks * chunkBytes() + tableCapacity(chunks) * sizeof(void*);
}

bool CellArena::canGrow(std::uint64_t extraChunks) const
{
    const std::uint64_t total = m_chunks.size() + extraChunks;
    if (total > maxChunks) return false;
    return m_limit == 0 || bytesWithChunks(total) <= m_limit;
}

std::uint32_t CellArena::allocateInNewChunk(unsigned cells)
{
    assert(cells >= 1 && cells <= MaxTable && "CellArena::allocate(): table size out of range");
    if (!canGrow(1)) return Exhausted;
    if (m_chunks.size() == m_chunks.capacity()) m_chunks.reserve(tableCapacity(m_chunks.size() + 1));
    std::uint8_t* memory = newChunkMemory();
    if (!memory) return Exhausted;
    m_chunks.push_back(memory);
    // The old chunk's tail, too short for this table, is a table of its own size for later.
    if (m_used < ChunkCells) release(m_lastChunkBase + m_used, ChunkCells - m_used);
    m_lastChunkBase = std::uint32_t(m_chunks.size() - 1) << ChunkShift;
    m_used = cells;
    return m_lastChunkBase;
}

std::array<std::uint64_t, CellArena::MaxTable + 1> CellArena::freeCells() const
{
    std::array<std::uint64_t, MaxTable + 1> cells{};
    for (unsigned k = 1; k <= MaxTable; ++k) cells[k] = m_freeCount[k] * k;
    return cells;
}

CellArena::Plan CellArena::plan() const
{
    Plan p;
    p.m_free = m_freeCount;
    p.m_used = m_used;
    return p;
}

} // namespace stylos::core::octree
