#include "stylos/core/octree/CellArena.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace stylos::core::octree;

namespace {
constexpr std::uint32_t chunkCells = CellArena::ChunkCells;
}

TEST(CellArena, ExactSizeTablesAreConsecutiveInAChunk)
{
    CellArena arena;
    EXPECT_EQ(arena.bytes(), arena.bytesWithChunks(0));
    EXPECT_EQ(arena.allocate(3), 0u);
    EXPECT_EQ(arena.allocate(8), 3u);
    EXPECT_EQ(arena.allocate(1), 11u);
    EXPECT_EQ(arena.chunks(), 1u);
    EXPECT_EQ(arena.chunkBytes(), 2048u * 7u);
    EXPECT_EQ(arena.bytes(), 2048u * 7u + 64u * sizeof(void*));
    // Cells are 7 bytes apart, 10 with colour.
    EXPECT_EQ(arena.cell(11) - arena.cell(3), 8 * 7);
    CellArena colour(CellArena::ColourCellBytes);
    colour.allocate(5);
    EXPECT_EQ(colour.cell(4) - colour.cell(0), 40);
    EXPECT_EQ(colour.bytes(), 2048u * 10u + 64u * sizeof(void*));
}

TEST(CellArena, ATableNeverSpansChunksAndTheTailGoesToItsFreeList)
{
    CellArena arena;
    for (std::uint32_t i = 0; i < 2045; ++i) ASSERT_EQ(arena.allocate(1), i);
    // 3 cells left: a table of 5 starts the next chunk; the 3-cell tail becomes a free table of 3.
    EXPECT_EQ(arena.allocate(5), chunkCells);
    EXPECT_EQ(arena.chunks(), 2u);
    EXPECT_EQ(arena.freeCells()[3], 3u);
    EXPECT_EQ(arena.allocate(3), 2045u);
    EXPECT_EQ(arena.freeCells()[3], 0u);
    EXPECT_EQ(arena.allocate(3), chunkCells + 5);
    // A table that exactly fills a chunk leaves no tail.
    CellArena exact;
    for (std::uint32_t i = 0; i < chunkCells / 8; ++i) ASSERT_EQ(exact.allocate(8), 8 * i);
    EXPECT_EQ(exact.allocate(8), chunkCells);
    for (unsigned k = 1; k <= 8; ++k) EXPECT_EQ(exact.freeCells()[k], 0u) << k;
}

TEST(CellArena, ReleasedTablesAreReusedPerSizeLastInFirstOut)
{
    CellArena arena;
    const std::uint32_t a = arena.allocate(2), b = arena.allocate(2), c = arena.allocate(4);
    arena.release(a, 2);
    arena.release(b, 2);
    arena.release(c, 4);
    EXPECT_EQ(arena.freeCells()[2], 4u);
    EXPECT_EQ(arena.freeCells()[4], 4u);
    EXPECT_EQ(arena.allocate(3), 8u);   // no free table of 3: from the chunk
    EXPECT_EQ(arena.allocate(2), b);
    EXPECT_EQ(arena.allocate(2), a);
    EXPECT_EQ(arena.allocate(2), 11u);  // list empty again
    EXPECT_EQ(arena.allocate(4), c);
    EXPECT_EQ(arena.freeCells()[2] + arena.freeCells()[4], 0u);
}

TEST(CellArena, RandomGrowthReusesMemory)
{
    // Tables grown one cell at a time in random order while new one-cell tables keep appearing (what
    // Streaming does as points arrive): released tables are taken again, so almost nothing is lost.
    CellArena arena;
    std::mt19937 random(3);
    struct Table {
        std::uint32_t first;
        unsigned size;
    };
    std::vector<Table> tables;
    for (int i = 0; i < 20000; ++i) tables.push_back({arena.allocate(1), 1});
    std::uint64_t used = 20000;
    for (int step = 0; step < 100000; ++step) {
        if (random() % 5 < 2) {
            tables.push_back({arena.allocate(1), 1});
            ++used;
            continue;
        }
        Table& t = tables[random() % tables.size()];
        if (t.size == 8) continue;
        const std::uint32_t grown = arena.allocate(t.size + 1);
        std::memcpy(arena.cell(grown), arena.cell(t.first), t.size * 7u);
        arena.release(t.first, t.size);
        t = {grown, t.size + 1};
        ++used;
    }
    std::uint64_t freeCells = 0;
    for (unsigned k = 1; k <= 8; ++k) freeCells += arena.freeCells()[k];
    const std::uint64_t total = arena.chunks() * chunkCells;
    EXPECT_LE(total, used + freeCells + chunkCells);
    EXPECT_LT(double(freeCells), 0.01 * double(used));
    // Every live table is distinct memory.
    std::set<std::uint32_t> cells;
    for (const Table& t : tables)
        for (unsigned i = 0; i < t.size; ++i) ASSERT_TRUE(cells.insert(t.first + i).second);
}

TEST(CellArena, LimitIsNeverPassed)
{
    CellArena arena(CellArena::PlainCellBytes, CellArena().bytesWithChunks(2));
    for (std::uint32_t i = 0; i < 2 * chunkCells / 8; ++i) ASSERT_NE(arena.allocate(8), CellArena::Exhausted);
    EXPECT_EQ(arena.chunks(), 2u);
    EXPECT_FALSE(arena.canGrow(1));
    EXPECT_TRUE(arena.canGrow(0));
    EXPECT_EQ(arena.allocate(1), CellArena::Exhausted);
    EXPECT_EQ(arena.chunks(), 2u);
    EXPECT_LE(arena.bytes(), arena.limitBytes());
    // Freed tables can still be handed out.
    arena.release(8, 8);
    EXPECT_EQ(arena.allocate(8), 8u);
    // A limit below one chunk refuses the first table.
    CellArena tiny(CellArena::PlainCellBytes, 1000);
    EXPECT_EQ(tiny.allocate(1), CellArena::Exhausted);
    EXPECT_EQ(tiny.bytes(), tiny.bytesWithChunks(0));
}

TEST(CellArena, PlanPredictsTheChunksExactly)
{
    std::mt19937 random(11);
    CellArena arena;
    for (int round = 0; round < 20; ++round) {
        std::vector<unsigned> sizes(1 + random() % 3000);
        for (unsigned& s : sizes) s = 1 + random() % 8;
        CellArena::Plan plan = arena.plan();
        for (unsigned s : sizes) plan.allocate(s);
        const std::uint64_t before = arena.chunks();
        for (unsigned s : sizes) ASSERT_NE(arena.allocate(s), CellArena::Exhausted);
        EXPECT_EQ(arena.chunks() - before, plan.newChunks()) << "round " << round;
        // Some releases between rounds, so the plan must count the free lists too.
        for (int r = 0; r < 50; ++r) {
            const unsigned s = 1 + random() % 8;
            arena.release(arena.allocate(s), s);
        }
    }
}

TEST(CellArena, ChunkTableGrowsByDoubling)
{
    CellArena arena;
    EXPECT_EQ(arena.bytesWithChunks(64) - 64 * arena.chunkBytes(), 64 * sizeof(void*));
    EXPECT_EQ(arena.bytesWithChunks(65) - 65 * arena.chunkBytes(), 128 * sizeof(void*));
    EXPECT_EQ(arena.bytesWithChunks(1000) - 1000 * arena.chunkBytes(), 1024 * sizeof(void*));
}
