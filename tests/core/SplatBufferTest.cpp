// makeSplatBuffer: one vertex per cell of a cut, exactly — centre, footprint (edge or spacing), normal, the scan colour and the
// "ambient" layer of the cell's first leaf —, the seeded shuffle, and firstLeafOf.
#include "ViewTestSupport.h"

#include "stylos/core/ao/AoExport.h"
#include "stylos/core/octree/ViewCut.h"
#include "stylos/core/view/SplatBuffer.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace stylos::core;
using stylos::core::view::SplatBuffer;
using stylos::core::view::SplatVertex;
using stylos::test::TempDir;

namespace {

octree::CutResult cutAtLevel(const octree::PackedOctree& tree, int level)
{
    octree::CutCamera camera;
    camera.cullToFrustum = false;
    octree::CutOptions options;
    options.pixelThreshold = 0;
    options.maxLevel = level;
    return octree::computeViewCut(tree, camera, options);
}

bool sameVertex(const SplatVertex& a, const SplatVertex& b)
{
    return a.position == b.position && a.size == b.size && a.normal == b.normal && a.colour == b.colour;
}

} // namespace

TEST(SplatBufferTest, LeavesOfTheFourLeafTreeExactly)
{
    TempDir dir;
    const auto tree = stylos::test::fourLeafOctree(dir);
    ASSERT_NE(tree, nullptr);
    const octree::CutResult cut = cutAtLevel(*tree, -1);
    ASSERT_EQ(cut.cells.size(), 4u);
    const SplatBuffer splats = view::makeSplatBuffer(*tree, cut, 0); // seed 0: the cut's order
    EXPECT_EQ(splats.origin, (std::array<double, 3>{100, 200, 300}));
    EXPECT_TRUE(splats.hasColour);
    EXPECT_FALSE(splats.hasAmbient);
    EXPECT_FALSE(splats.budgetReached);
    EXPECT_EQ(splats.deepestLevel, 2);
    ASSERT_EQ(splats.vertices.size(), 4u);
    // No "spacing" layer (a hand-made tree): computed. Level 1 is not saturated (4 leaves in 4 cells), so the
    // surface is 2 level-1 cells of edge 2 over |u|₁ = √2 (root normal (1, 1, 0)/√2): h = √(8 / √2 / 4).
    EXPECT_NEAR(tree->leafSpacing(0), std::sqrt(2.0 / std::sqrt(2.0)), 2e-3);
    // Per leaf (breadth-first index): centre relative to the origin, normal × 127, colour with alpha 255.
    const std::array<std::array<float, 3>, 4> centres{{{0.5f, 0.5f, 0.5f}, {1.5f, 0.5f, 0.5f}, {2.5f, 2.5f, 2.5f},
                                                       {3.5f, 2.5f, 2.5f}}};
    const std::array<std::array<std::int8_t, 4>, 4> normals{{{0, 0, 127, 0}, {127, 0, 0, 0}, {0, 127, 0, 0},
                                                             {0, 0, -127, 0}}};
    const std::array<std::array<std::uint8_t, 4>, 4> colours{{{10, 20, 30, 255}, {40, 50, 60, 255},
                                                              {70, 80, 90, 255}, {100, 110, 120, 255}}};
    for (std::size_t i = 0; i < 4; ++i) {
        const std::uint64_t leaf = cut.cells[i].index;
        const SplatVertex& v = splats.vertices[i];
        EXPECT_EQ(v.position, centres[leaf]) << "leaf " << leaf;
        EXPECT_EQ(v.position, cut.cells[i].centre);
        EXPECT_EQ(v.size, std::max(1.0f, 2.0f * tree->leafSpacing(leaf))) << "leaf " << leaf; // the larger of edge and spacing
        EXPECT_EQ(v.normal, normals[leaf]) << "leaf " << leaf;
        EXPECT_EQ(v.colour, colours[leaf]) << "leaf " << leaf;
    }
}

TEST(SplatBufferTest, InnerCellsTakeTheirFirstLeafAndTheShuffleIsAPermutation)
{
    TempDir dir;
    const auto tree = stylos::test::fourLeafOctree(dir);
    ASSERT_NE(tree, nullptr);
    EXPECT_EQ(view::firstLeafOf(*tree, 0, 0), 0u);
    EXPECT_EQ(view::firstLeafOf(*tree, 1, 0), 0u);
    EXPECT_EQ(view::firstLeafOf(*tree, 1, 1), 2u);
    EXPECT_EQ(view::firstLeafOf(*tree, 2, 3), 3u);

    const octree::CutResult level1 = cutAtLevel(*tree, 1);
    const SplatBuffer inner = view::makeSplatBuffer(*tree, level1, 0);
    ASSERT_EQ(inner.vertices.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        const SplatVertex& v = inner.vertices[i];
        EXPECT_EQ(v.size, std::max(2.0f, 2.0f * tree->leafSpacing(view::firstLeafOf(*tree, 1, level1.cells[i].index))));
        EXPECT_EQ(v.position, level1.cells[i].centre);
        const auto expected = level1.cells[i].index == 0 ? std::array<std::uint8_t, 4>{10, 20, 30, 255}
                                                         : std::array<std::uint8_t, 4>{70, 80, 90, 255};
        EXPECT_EQ(v.colour, expected);
    }

    const octree::CutResult leaves = cutAtLevel(*tree, -1);
    const SplatBuffer ordered = view::makeSplatBuffer(*tree, leaves, 0);
    const SplatBuffer a = view::makeSplatBuffer(*tree, leaves, 5), b = view::makeSplatBuffer(*tree, leaves, 5);
    ASSERT_EQ(a.vertices.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_TRUE(sameVertex(a.vertices[i], b.vertices[i])); // deterministic
    for (const SplatVertex& v : ordered.vertices) // each vertex once
        EXPECT_EQ(std::count_if(a.vertices.begin(), a.vertices.end(), [&](const SplatVertex& w) { return sameVertex(v, w); }), 1);
}

TEST(SplatBufferTest, SplatsCarryTheAmbientLayer)
{
    // Every leaf gets its own value; an inner cell of a cut takes its first leaf's.
    TempDir dir;
    const auto drum = stylos::test::makeDrumOctree(dir.path(), 0.01, 6);
    ASSERT_NE(drum.octree, nullptr);
    const auto& tree = *drum.octree;
    const std::uint64_t leafCount = tree.cellCount(tree.depth());
    std::vector<float> ambient(leafCount);
    for (std::uint64_t i = 0; i < leafCount; ++i) ambient[i] = float(i % 256) / 255.0f;
    const std::filesystem::path path = dir / "ambient.poct";
    ASSERT_TRUE(ao::writeAmbientPoct(tree, ambient, path).ok());
    auto opened = octree::PackedOctree::open(path);
    ASSERT_TRUE(opened.ok());
    const auto& withAmbient = *opened;

    const octree::CutResult cut = cutAtLevel(withAmbient, 3);
    ASSERT_EQ(std::uint64_t(cut.cells.size()), withAmbient.cellCount(3));
    const SplatBuffer splats = view::makeSplatBuffer(withAmbient, cut, 0);
    EXPECT_TRUE(splats.hasAmbient);
    EXPECT_FALSE(splats.hasColour);
    ASSERT_EQ(splats.vertices.size(), cut.cells.size());
    for (std::size_t i = 0; i < cut.cells.size(); ++i) {
        const auto& c = cut.cells[i];
        const std::uint64_t first = view::firstLeafOf(withAmbient, c.level, c.index);
        EXPECT_EQ(int(splats.vertices[i].colour[3]), int(first % 256));
        EXPECT_EQ(splats.vertices[i].position, c.centre);
        EXPECT_EQ(splats.vertices[i].colour[0], std::uint8_t(255)); // no scan colour
        // The first leaf lies inside the cell.
        bool inside = false;
        withAmbient.forEachCell(withAmbient.depth(), [&](const octree::CellView& l) {
            if (l.index != first) return true;
            for (int a = 0; a < 3; ++a) {
                const double rel = l.centre[std::size_t(a)] - withAmbient.box().origin[std::size_t(a)];
                if (std::abs(rel - c.centre[std::size_t(a)]) > 0.5 * c.size) return false;
            }
            inside = true;
            return false;
        });
        EXPECT_TRUE(inside) << "cell " << i;
        if (i > 40) break; // the leaf walk is linear: a sample is enough
    }
    EXPECT_EQ(view::firstLeafOf(withAmbient, withAmbient.depth(), 5), 5u);
    EXPECT_EQ(view::firstLeafOf(withAmbient, 0, 0), 0u);
}
