// The cells of one octree level as the skydome reads them (AoCells.h), on a hand-made .poct.
#include "stylos/core/ao/AoCells.h"
#include "PoctTestSupport.h"
#include "ReferenceOctree.h"

#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <vector>

using namespace stylos::core;
using namespace stylos::core::ao;
using stylos::test::ReferenceOctree;
using stylos::test::TempDir;

namespace {

// Root box origin O = (100, 200, 300), edge 4, depth 2 (leaves of 1 m, level-1 cells of 2 m).
//  A: level-1 cell (0,0,0), all 8 leaves (0..1)³, normals +z   → opacity min(1, 8/4) = 1
//  C: level-1 cell (1,0,0), leaves (2,0,0) and (3,0,0), +x       → 2/4
//  B: level-1 cell (1,1,1), leaf (3,3,3), +y                     → 1/4
// Breadth-first (child slot x | y << 1 | z << 2): level 1 = A, C, B; leaves = A's 8 in slot order,
// then C's two, then B's one. The root: 11 leaves two levels down → 11/16.
constexpr double Ox = 100, Oy = 200, Oz = 300;

ReferenceOctree handMade()
{
    std::vector<double> p;
    std::vector<float> n;
    auto leaf = [&](int x, int y, int z, std::array<float, 3> normal) {
        p.insert(p.end(), {Ox + x + 0.5, Oy + y + 0.5, Oz + z + 0.5});
        n.insert(n.end(), normal.begin(), normal.end());
    };
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x)
                leaf(x, y, z, {0, 0, 1});
    leaf(2, 0, 0, {1, 0, 0});
    leaf(3, 0, 0, {1, 0, 0});
    leaf(3, 3, 3, {0, 1, 0});
    return ReferenceOctree(p, n, {}, 2, octree::NormalCodeKind::Octahedral16, octree::RootBox{{Ox, Oy, Oz}, 4.0});
}

class AoCellsTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_octree = stylos::test::pack(handMade(), m_dir);
        ASSERT_NE(m_octree, nullptr);
    }
    TempDir m_dir;
    std::unique_ptr<octree::PackedOctree> m_octree;
};

void expectNormal(const std::array<float, 3>& got, const std::array<float, 3>& want)
{
    for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(got[a], want[a], 1e-4) << "axis " << a;
}

} // namespace

TEST_F(AoCellsTest, LevelOneHasCoordsNormalsOpacityAndLeafRanges)
{
    auto cells = cellsAtLevel(*m_octree, 1);
    ASSERT_TRUE(cells.ok()) << cells.error().message;
    ASSERT_EQ(cells->size(), 3u);
    EXPECT_EQ(cells->level, 1);
    EXPECT_EQ(cells->edge, 2.0);
    EXPECT_EQ(cells->origin, (std::array<double, 3>{Ox, Oy, Oz}));
    using C = std::array<std::uint32_t, 3>;
    EXPECT_EQ(cells->coords, (std::vector<C>{{0, 0, 0}, {1, 0, 0}, {1, 1, 1}}));
    expectNormal(cells->normals[0], {0, 0, 1});
    expectNormal(cells->normals[1], {1, 0, 0});
    expectNormal(cells->normals[2], {0, 1, 0});
    EXPECT_EQ(cells->opacity, (std::vector<float>{1.0f, 0.5f, 0.25f}));
    EXPECT_EQ(cells->leafBegin, (std::vector<std::uint64_t>{0, 8, 10, 11}));
    EXPECT_EQ(cells->centre(1), (std::array<double, 3>{Ox + 3, Oy + 1, Oz + 1}));
    EXPECT_EQ(cells->centre(2), (std::array<double, 3>{Ox + 3, Oy + 3, Oz + 3}));
}

TEST_F(AoCellsTest, LeavesAreOpaqueAndEachItsOwnRange)
{
    auto cells = cellsAtLevel(*m_octree, 2);
    ASSERT_TRUE(cells.ok()) << cells.error().message;
    ASSERT_EQ(cells->size(), 11u);
    EXPECT_EQ(cells->edge, 1.0);
    EXPECT_EQ(cells->coords[0], (std::array<std::uint32_t, 3>{0, 0, 0}));
    EXPECT_EQ(cells->coords[1], (std::array<std::uint32_t, 3>{1, 0, 0}));
    EXPECT_EQ(cells->coords[2], (std::array<std::uint32_t, 3>{0, 1, 0}));
    EXPECT_EQ(cells->coords[4], (std::array<std::uint32_t, 3>{0, 0, 1}));
    EXPECT_EQ(cells->coords[8], (std::array<std::uint32_t, 3>{2, 0, 0}));
    EXPECT_EQ(cells->coords[9], (std::array<std::uint32_t, 3>{3, 0, 0}));
    EXPECT_EQ(cells->coords[10], (std::array<std::uint32_t, 3>{3, 3, 3}));
    EXPECT_EQ(cells->opacity, std::vector<float>(11, 1.0f));
    for (std::uint64_t i = 0; i <= 11; ++i)
        EXPECT_EQ(cells->leafBegin[i], i);
    expectNormal(cells->normals[9], {1, 0, 0});
    EXPECT_EQ(cells->centre(10), (std::array<double, 3>{Ox + 3.5, Oy + 3.5, Oz + 3.5}));
}

TEST_F(AoCellsTest, RootCoversEveryLeaf)
{
    auto cells = cellsAtLevel(*m_octree, 0);
    ASSERT_TRUE(cells.ok()) << cells.error().message;
    ASSERT_EQ(cells->size(), 1u);
    EXPECT_EQ(cells->edge, 4.0);
    EXPECT_EQ(cells->coords[0], (std::array<std::uint32_t, 3>{0, 0, 0}));
    EXPECT_EQ(cells->opacity[0], 11.0f / 16.0f);
    EXPECT_EQ(cells->leafBegin, (std::vector<std::uint64_t>{0, 11}));
}

TEST_F(AoCellsTest, ValuesSpreadToTheLeavesUnderEachCell)
{
    auto cells = cellsAtLevel(*m_octree, 1);
    ASSERT_TRUE(cells.ok());
    const std::vector<float> values{0.25f, 0.5f, 0.75f};
    std::vector<float> want(8, 0.25f);
    want.insert(want.end(), {0.5f, 0.5f, 0.75f});
    EXPECT_EQ(valuesPerLeaf(*cells, values), want);

    auto leaves = cellsAtLevel(*m_octree, 2);
    ASSERT_TRUE(leaves.ok());
    std::vector<float> own(11);
    for (std::size_t i = 0; i < own.size(); ++i)
        own[i] = float(i) / 16.0f;
    EXPECT_EQ(valuesPerLeaf(*leaves, own), own);
}

TEST_F(AoCellsTest, LevelOutsideTheOctreeIsRefusedNamingTheFile)
{
    for (int level : {-1, 3}) {
        auto cells = cellsAtLevel(*m_octree, level);
        ASSERT_FALSE(cells.ok()) << level;
        EXPECT_EQ(cells.error().code, ErrorCode::InvalidArgument);
        EXPECT_NE(cells.error().message.find((m_dir / "t.poct").string()), std::string::npos) << cells.error().message;
        EXPECT_NE(cells.error().message.find(std::to_string(level)), std::string::npos) << cells.error().message;
    }
}

TEST_F(AoCellsTest, ReportsProgressAndHonoursCancel)
{
    SilentProgress progress;
    ASSERT_TRUE(cellsAtLevel(*m_octree, 2, &progress).ok());
    EXPECT_EQ(progress.last(), 1.0);

    SilentProgress cancelled;
    cancelled.cancel();
    auto cells = cellsAtLevel(*m_octree, 2, &cancelled);
    ASSERT_FALSE(cells.ok());
    EXPECT_EQ(cells.error().code, ErrorCode::Cancelled);
}
