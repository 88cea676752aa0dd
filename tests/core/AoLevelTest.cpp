// The default level of the 3D skydome: the deepest level whose cells still form a closed surface.
#include "PoctTestSupport.h"
#include "ReferenceOctree.h"
#include "stylos/core/ao/AoCells.h"

#include <gtest/gtest.h>

#include <vector>

using namespace stylos::core;
using stylos::test::ReferenceOctree;
using stylos::test::TempDir;

namespace {

/** An @p n × @p n sheet of points @p spacing apart at z = 0.5 in a root cube of edge 8 m, at @p depth. */
std::unique_ptr<octree::PackedOctree> sheet(int n, double spacing, int depth, const TempDir& dir)
{
    std::vector<double> p;
    std::vector<float> normals;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            p.insert(p.end(), {(i + 0.5) * spacing, (j + 0.5) * spacing, 0.5});
            normals.insert(normals.end(), {0.0f, 0.0f, 1.0f});
        }
    return stylos::test::pack(
        ReferenceOctree(p, normals, {}, depth, octree::NormalCodeKind::Octahedral16, octree::RootBox{{0, 0, 0}, 8.0}),
        dir);
}

} // namespace

TEST(AoLevelTest, StopsWhereTheCellsOutgrowTheSampling)
{
    // Points 1 m apart, leaves of 0.25 m (depth 5): levels 0..5 hold 1, 4, 16, 64, 64, 64 cells; level 3
    // (1 m cells) is the last where the sheet still fills its cells, 4 times the cells of level 2.
    TempDir dir;
    const auto octree = sheet(8, 1.0, 5, dir);
    ASSERT_NE(octree, nullptr);
    ASSERT_EQ(octree->cellCount(3), 64u);
    ASSERT_EQ(octree->cellCount(5), 64u);
    EXPECT_EQ(ao::closedSurfaceLevel(*octree), 3);
}

TEST(AoLevelTest, ADenseSheetIsClosedDownToItsLeaves)
{
    // 32 × 32 points 0.25 m apart, leaves of 0.25 m: 1, 4, 16, 64, 256, 1024 cells.
    TempDir dir;
    const auto octree = sheet(32, 0.25, 5, dir);
    ASSERT_NE(octree, nullptr);
    ASSERT_EQ(octree->cellCount(5), 1024u);
    EXPECT_EQ(ao::closedSurfaceLevel(*octree), 5);
}

TEST(AoLevelTest, ALoneLineFallsBackToTheLeaves)
{
    // Points along a line double per level at best (ratio 2 < 3 everywhere): the leaf level.
    TempDir dir;
    std::vector<double> p;
    std::vector<float> normals;
    for (int i = 0; i < 32; ++i) {
        p.insert(p.end(), {(i + 0.5) * 0.25, 0.5, 0.5});
        normals.insert(normals.end(), {0.0f, 0.0f, 1.0f});
    }
    const auto octree = stylos::test::pack(
        ReferenceOctree(p, normals, {}, 5, octree::NormalCodeKind::Octahedral16, octree::RootBox{{0, 0, 0}, 8.0}), dir);
    ASSERT_NE(octree, nullptr);
    EXPECT_EQ(ao::closedSurfaceLevel(*octree), 5);
}
