// computeLeafSpacing: a flat grid whose every level-(D−4) cell holds exactly 6 × 6 samples gives the grid
// step exactly (the fine level is saturated); a grid of 3 × 3 per cell falls back to the coarse level and
// still gives its step; PackedOctree::leafSpacing reads the stored layer or computes the same values; the
// builder stores the layer.
#include "ViewTestSupport.h"

#include "stylos/core/octree/LeafSpacing.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace stylos::core;
using stylos::test::TempDir;

namespace {

/** A horizontal grid (i + ½) · step, z = ½ + 1/256, normals +z, in the unit root box at depth 7. */
stylos::test::ReferenceOctree grid(double step)
{
    std::vector<double> p;
    std::vector<float> n;
    const int count = int(std::lround(1.0 / step));
    for (int i = 0; i < count; ++i)
        for (int j = 0; j < count; ++j) {
            p.insert(p.end(), {(i + 0.5) * step, (j + 0.5) * step, 0.5 + 1.0 / 256});
            n.insert(n.end(), {0, 0, 1});
        }
    return stylos::test::ReferenceOctree(p, n, {}, 7, octree::NormalCodeKind::Octahedral16,
                                         octree::RootBox{{0, 0, 0}, 1.0});
}

} // namespace

TEST(LeafSpacingTest, SaturatedFineLevelGivesTheGridStepExactly)
{
    const auto tree = grid(1.0 / 48); // 36 samples per level-3 cell, 16 level-5 cells occupied, one sample per leaf
    const std::vector<float> spacing = octree::computeLeafSpacing(tree);
    ASSERT_EQ(spacing.size(), 48u * 48u);
    for (const float h : spacing) ASSERT_FLOAT_EQ(h, 1.0f / 48);
}

TEST(LeafSpacingTest, SparseSamplesUseTheCoarseLevel)
{
    const auto tree = grid(1.0 / 24); // 9 samples per level-3 cell in 9 level-5 cells: not saturated; 4 level-4 cells
    const std::vector<float> spacing = octree::computeLeafSpacing(tree);
    ASSERT_EQ(spacing.size(), 24u * 24u);
    for (const float h : spacing) ASSERT_FLOAT_EQ(h, 1.0f / 24);
}

// An octree far deeper than its samples (a 4 mm scan at depth 12): one sample per 16 leaf edges. The ancestors of
// 16 edges hold one sample in one cell of every level, and the estimate stopped at the coarse cell's edge, half the
// step (1/16 here; plates drawn with splats of that size were see-through). The ancestors then widen until their
// coarse level is saturated (here 64 edges: 16 samples in 4 cells of 1/4) and give the step exactly.
TEST(LeafSpacingTest, SamplesSparserThanTheAncestorsWidenThem)
{
    const auto tree = grid(1.0 / 8); // 1/8 = 16 leaf edges of 1/128
    const std::vector<float> spacing = octree::computeLeafSpacing(tree);
    ASSERT_EQ(spacing.size(), 8u * 8u);
    for (const float h : spacing) ASSERT_FLOAT_EQ(h, 1.0f / 8);
}

TEST(LeafSpacingTest, LayerRoundTripAndComputedOnOpen)
{
    TempDir dir;
    const auto tree = grid(1.0 / 48);
    const auto packed = stylos::test::pack(tree, dir, "plain.poct");
    ASSERT_NE(packed, nullptr);
    EXPECT_FALSE(packed->hasStoredLeafSpacing());
    EXPECT_FLOAT_EQ(packed->leafSpacing(0), 1.0f / 48);
    EXPECT_FLOAT_EQ(packed->leafSpacing(48 * 48 - 1), 1.0f / 48);

    std::vector<float> marked(48 * 48, 0.25f);
    marked[7] = 0.5f;
    ASSERT_TRUE(octree::setPoctAttributeLayer(dir / "plain.poct", octree::leafSpacingLayer(marked)).ok());
    auto reopened = octree::PackedOctree::open(dir / "plain.poct");
    ASSERT_TRUE(reopened.ok());
    EXPECT_TRUE(reopened->hasStoredLeafSpacing());
    EXPECT_EQ(reopened->leafSpacing(7), 0.5f);  // read from the layer, not recomputed
    EXPECT_EQ(reopened->leafSpacing(8), 0.25f);
}

TEST(LeafSpacingTest, TheBuilderStoresTheLayer)
{
    TempDir dir;
    const auto drum = stylos::test::makeDrumOctree(dir.path(), 0.02, 6);
    ASSERT_NE(drum.octree, nullptr);
    EXPECT_TRUE(drum.octree->hasStoredLeafSpacing());
    const auto layer = drum.octree->attribute(octree::LeafSpacingLayerName);
    ASSERT_TRUE(layer.has_value());
    EXPECT_EQ(layer->type, octree::AttributeType::Float32);
    const std::vector<float> computed = octree::computeLeafSpacing(drum.octree->levels());
    ASSERT_EQ(layer->bytes.size(), 4 * computed.size());
    for (std::size_t i = 0; i < computed.size(); i += 97) EXPECT_EQ(drum.octree->leafSpacing(i), computed[i]);
    // The layer the build writes (computed straight into its bytes) is the vector's, byte for byte.
    const octree::AttributeLayer direct = octree::leafSpacingLayer(drum.octree->levels());
    EXPECT_EQ(direct.bytes, octree::leafSpacingLayer(computed).bytes);
    EXPECT_EQ(direct.bytes, std::vector<std::uint8_t>(layer->bytes.begin(), layer->bytes.end()));
    EXPECT_EQ(direct.name, octree::LeafSpacingLayerName);
}
