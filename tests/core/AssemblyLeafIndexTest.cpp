// The pixel ↔ leaf index of an assembly's développée: posedLeafPixels() against leafPixels() (identity: the same
// pixels; a turn about the axis by k pixels' angle: the same rows, k columns on), and the per-piece index on a
// hand-made grid (each piece keeps only the leaves on the pixels it shows; split, leaves, pixels and the majority
// label exactly).
#include "AnnotationTestSupport.h"

#include "stylos/core/annotation/AssemblyLeafIndex.h"

#include <gtest/gtest.h>

namespace stylos::core::annotation {
namespace {

TEST(AssemblyLeafIndexTest, IdentityPoseGivesTheLeafPixels)
{
    const auto& drum = test::annotatedDrum();
    ASSERT_TRUE(drum.map.has_value());
    auto octree = octree::PackedOctree::open(drum.poct);
    ASSERT_TRUE(octree.ok());
    auto plain = leafPixels(*octree, *drum.map);
    auto posed = posedLeafPixels(*octree, Eigen::Isometry3d::Identity(), *drum.map);
    ASSERT_TRUE(plain.ok() && posed.ok());
    ASSERT_EQ(posed->size(), octree->cellCount(octree->depth()));
    EXPECT_EQ(*posed, *plain);
    EXPECT_GT(std::count_if(plain->begin(), plain->end(), [](std::int64_t p) { return p >= 0; }), 1000);
}

TEST(AssemblyLeafIndexTest, APoseAboutTheAxisMovesTheColumns)
{
    const auto& drum = test::annotatedDrum();
    ASSERT_TRUE(drum.map.has_value());
    auto octree = octree::PackedOctree::open(drum.poct);
    ASSERT_TRUE(octree.ok());
    const auto& map = *drum.map;
    constexpr int k = 5;
    const double angle = k * map.pixelSize() / map.surface().referenceRadius();
    const auto& axis = map.surface().axis();
    const Eigen::Isometry3d turn(Eigen::Translation3d(axis.point) * Eigen::AngleAxisd(angle, axis.direction) *
                                 Eigen::Translation3d(-axis.point));
    auto plain = leafPixels(*octree, map);
    auto posed = posedLeafPixels(*octree, turn, map);
    ASSERT_TRUE(plain.ok() && posed.ok());
    std::size_t compared = 0, moved = 0;
    for (std::size_t l = 0; l < plain->size(); ++l) {
        const std::int64_t p = (*plain)[l];
        if (p < 0 || p % map.width() + k + 1 >= map.width() || p % map.width() < 1) continue; // away from the cut
        ++compared;
        moved += (*posed)[l] == p + k;
    }
    ASSERT_GT(compared, 1000u);
    EXPECT_GT(double(moved) / double(compared), 0.98) << moved << " of " << compared; // pixel borders may round
}

/**
 * A 6 × 4 image: piece 7 shows columns 2..3 of rows 1..2, the drum (0) the rest. The drum has one leaf per pixel
 * (leaf = pixel) plus leaf 24 off the image; piece 7 has leaves 0..5 at pixels 8, 9, 14, 15, 15, 3 (the last on a
 * drum pixel: hidden, dropped).
 */
AssemblyLeafIndex handMade()
{
    auto at = std::make_shared<std::vector<std::uint64_t>>(24, 0);
    for (std::uint32_t p : {8u, 9u, 14u, 15u}) (*at)[p] = 7;
    std::vector<std::int64_t> drum(25);
    for (int l = 0; l < 24; ++l) drum[std::size_t(l)] = l;
    drum[24] = -1;
    return AssemblyLeafIndex::build(6, 4, at, {{0, drum, Eigen::Isometry3d::Identity(), "drum"},
                                                    {7, {8, 9, 14, 15, 15, 3}, Eigen::Isometry3d::Identity(), "fragment"}});
}

TEST(AssemblyLeafIndexTest, EachPieceKeepsTheLeavesOfThePixelsItShows)
{
    const AssemblyLeafIndex index = handMade();
    ASSERT_EQ(index.pieces().size(), 2u);
    const auto* fragment = index.find(7);
    ASSERT_NE(fragment, nullptr);
    EXPECT_EQ(fragment->left, 2);
    EXPECT_EQ(fragment->top, 1);
    EXPECT_EQ(fragment->index.width(), 2);
    EXPECT_EQ(fragment->index.height(), 2);
    EXPECT_EQ(fragment->index.leafCount(), 6u);
    EXPECT_EQ(fragment->index.mappedLeafCount(), 5u); // leaf 5 (pixel 3) is under the drum's pixel
    EXPECT_EQ(index.find(0)->index.mappedLeafCount(), 20u); // the 4 drum leaves under the fragment are hidden
    EXPECT_EQ(index.find(3), nullptr);
    EXPECT_EQ(fragment->source, "fragment");

    const std::vector<std::uint32_t> stroke{2, 3, 8, 9, 9, 10};
    const auto groups = index.split(stroke);
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0].first, 0u);
    EXPECT_EQ(groups[0].second, (std::vector<std::uint32_t>{2, 3, 10}));
    EXPECT_EQ(groups[1].first, 7u);
    EXPECT_EQ(groups[1].second, (std::vector<std::uint32_t>{8, 9}));
    EXPECT_EQ(index.leavesOf(0, stroke), (std::vector<std::uint32_t>{2, 3, 10})); // not 8, 9: hidden
    EXPECT_EQ(index.leavesOf(7, stroke), (std::vector<std::uint32_t>{0, 1}));     // not 5 (on pixel 3)
    EXPECT_EQ(index.leavesOf(7, std::vector<std::uint32_t>{14, 15, 23}), (std::vector<std::uint32_t>{2, 3, 4}));
    EXPECT_TRUE(index.leavesOf(9, stroke).empty());

    EXPECT_EQ(index.pixelsOf(7, std::vector<std::uint32_t>{4, 0, 5}), (std::vector<std::uint32_t>{8, 15}));
    EXPECT_EQ(index.pixelsOf(0, std::vector<std::uint32_t>{9, 23, 24}), (std::vector<std::uint32_t>{23}));
}

TEST(AssemblyLeafIndexTest, APixelShowsItsPiecesMajority)
{
    const AssemblyLeafIndex index = handMade();
    const std::vector<std::uint8_t> drum(25, 1);
    const std::vector<std::uint8_t> fragment{2, 0, 3, 4, 4, 9};
    const auto labelsOf = [&](std::uint64_t id) {
        return id == 0 ? std::span<const std::uint8_t>(drum) : std::span<const std::uint8_t>(fragment);
    };
    EXPECT_EQ(index.majorityLabel(0, labelsOf), 1);
    EXPECT_EQ(index.majorityLabel(8, labelsOf), 2);
    EXPECT_EQ(index.majorityLabel(9, labelsOf), 0);
    EXPECT_EQ(index.majorityLabel(14, labelsOf), 3);
    EXPECT_EQ(index.majorityLabel(15, labelsOf), 4); // leaves 3 and 4
    EXPECT_EQ(index.majorityLabel(3, labelsOf), 1);  // the drum's, not the hidden leaf 5's 9
    // Labels of the wrong size (an octree that changed): nothing shown.
    const std::vector<std::uint8_t> stale(5, 6);
    EXPECT_EQ(index.majorityLabel(8, [&](std::uint64_t) { return std::span<const std::uint8_t>(stale); }), 0);
}

// With the field's states, each piece lends its leaves to the pixels it shows with a height but no leaf (filled),
// through its own pixels only: before, such pixels showed no class on an assembly's développée (specks in a painted
// region), while a fragment's own développée lent them.
TEST(AssemblyLeafIndexTest, APieceLendsItsLeavesToItsFilledPixelsOnly)
{
    // 6 × 4: piece 7 shows columns 2..4 of rows 1..2 (8, 9, 10, 14, 15, 16) and has leaves at 8 and 9 only; the drum
    // has leaves at every pixel but 0, 1 (filled) and 23 (no height), and those under the piece.
    using shading::PixelState;
    auto at = std::make_shared<std::vector<std::uint64_t>>(24, 0);
    for (std::uint32_t p : {8u, 9u, 10u, 14u, 15u, 16u}) (*at)[p] = 7;
    std::vector<PixelState> states(24, PixelState::Measured);
    for (std::uint32_t p : {0u, 1u, 10u, 14u, 15u, 16u}) states[p] = PixelState::Filled;
    states[23] = PixelState::Empty;
    std::vector<std::int64_t> drum;
    for (std::int64_t p = 2; p < 23; ++p) drum.push_back(p); // leaf l at pixel l + 2
    const auto make = [&](std::span<const PixelState> with) {
        return AssemblyLeafIndex::build(6, 4, at, {{0, drum, Eigen::Isometry3d::Identity(), "drum"},
                                                        {7, {8, 9}, Eigen::Isometry3d::Identity(), "fragment"}}, with);
    };
    const std::vector<std::uint8_t> drumLabels(21, 1);
    const std::vector<std::uint8_t> pieceLabels{2, 3};
    const auto labelsOf = [&](std::uint64_t id) {
        return id == 0 ? std::span<const std::uint8_t>(drumLabels) : std::span<const std::uint8_t>(pieceLabels);
    };

    const AssemblyLeafIndex without = make({});
    for (std::uint32_t p : {0u, 1u, 10u, 14u, 15u, 16u}) EXPECT_EQ(without.majorityLabel(p, labelsOf), 0) << p;

    const AssemblyLeafIndex with = make(states);
    const auto* piece = with.find(7);
    ASSERT_NE(piece, nullptr);
    EXPECT_EQ(piece->left, 2); // the window spans the pixels the piece shows, not only its leaves'
    EXPECT_EQ(piece->index.width(), 3);
    EXPECT_EQ(piece->index.height(), 2);
    EXPECT_EQ(with.majorityLabel(8, labelsOf), 2);
    EXPECT_EQ(with.majorityLabel(9, labelsOf), 3);
    EXPECT_EQ(with.majorityLabel(10, labelsOf), 3); // beside 9
    EXPECT_EQ(with.majorityLabel(14, labelsOf), 2); // below 8
    EXPECT_EQ(with.majorityLabel(15, labelsOf), 2); // diagonal to 8 and below 9: the first met in pixel order
    EXPECT_EQ(with.majorityLabel(16, labelsOf), 3); // diagonal to 9
    EXPECT_EQ(with.majorityLabel(0, labelsOf), 1);  // the drum's filled pixels take the drum's nearest leaves
    EXPECT_EQ(with.majorityLabel(1, labelsOf), 1);
    EXPECT_EQ(with.majorityLabel(23, labelsOf), 0); // no height: nothing
    EXPECT_EQ(with.shownPixel(15), 8);
    EXPECT_EQ(with.shownPixel(16), 9);
    EXPECT_EQ(with.shownPixel(9), 9);
    EXPECT_EQ(with.shownPixel(0), 6); // its neighbour below (1 borrows from 2)
    EXPECT_EQ(with.shownPixel(1), 2);
    EXPECT_EQ(with.shownPixel(23), -1);
    EXPECT_EQ(without.shownPixel(15), -1);
    // A change of the piece's leaf 1 redraws its pixel and its borrowers, in the image's pixels.
    EXPECT_EQ(with.pixelsOf(7, std::vector<std::uint32_t>{1}), (std::vector<std::uint32_t>{9, 10, 16}));
    // Painting takes the painted pixels' own leaves only.
    EXPECT_EQ(with.leavesOf(7, std::vector<std::uint32_t>{10, 16}), (std::vector<std::uint32_t>{}));
}

} // namespace
} // namespace stylos::core::annotation
