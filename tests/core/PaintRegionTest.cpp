// The painting tools' pixel sets and the pixel ↔ leaf index, on small grids with exact expected pixels.
#include "stylos/core/annotation/LabelRaster.h"
#include "stylos/core/annotation/PaintRegion.h"
#include "stylos/core/annotation/PixelLeafIndex.h"

#include <gtest/gtest.h>

using namespace stylos::core::annotation;
using Pixels = std::vector<std::uint32_t>;

namespace {

/** The pixels of @p mask ('#') on a grid of its rows, row-major indices. */
Pixels maskPixels(const std::vector<std::string>& rows)
{
    Pixels out;
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t c = 0; c < rows[r].size(); ++c)
            if (rows[r][c] == '#') out.push_back(std::uint32_t(r * rows[r].size() + c));
    return out;
}

} // namespace

TEST(PaintRegion, ADabIsTheDiscOfCentresWithinTheRadius)
{
    // Centre (3, 3) (a pixel corner), radius 1.6: centre offsets (±0.5 | ±1.5) within 1.6 — a 4 × 4 block less
    // its corners (offsets (1.5, 1.5) are 2.12 away); at radius 1.5 the offsets (1.5, 0.5) (1.58) drop out too.
    EXPECT_EQ(brushPixels({3, 3}, {3, 3}, 1.6, 7, 7), maskPixels({".......",
                                                                 "..##...",
                                                                 ".####..",
                                                                 ".####..",
                                                                 "..##...",
                                                                 ".......",
                                                                 "......."}));
    EXPECT_EQ(brushPixels({3, 3}, {3, 3}, 1.5, 7, 7), (Pixels{16, 17, 23, 24}));
    // Clipped at the border; radius 0.5 on a pixel centre: that pixel and its 4 neighbours' centres at 1 → only it.
    EXPECT_EQ(brushPixels({0.5, 0.5}, {0.5, 0.5}, 0.5, 4, 4), (Pixels{0}));
    EXPECT_TRUE(brushPixels({0.5, 0.5}, {0.5, 0.5}, -1.0, 4, 4).empty());
}

TEST(PaintRegion, ASegmentIsTheCapsule)
{
    EXPECT_EQ(brushPixels({1.5, 1.5}, {5.5, 1.5}, 0.5, 8, 4), maskPixels({"........",
                                                                        ".#####..",
                                                                        "........",
                                                                        "........"}));
}

TEST(PaintRegion, PolygonTakesThePixelsWhoseCentreIsInside)
{
    const std::vector<GridPoint> square{{1, 1}, {4, 1}, {4, 3}, {1, 3}};
    EXPECT_EQ(polygonPixels(square, 6, 5), maskPixels({"......",
                                                       ".###..",
                                                       ".###..",
                                                       "......",
                                                       "......"}));
    // A triangle, partly outside the grid.
    const std::vector<GridPoint> triangle{{-2, 0}, {4, 0}, {-2, 6}};
    EXPECT_EQ(polygonPixels(triangle, 5, 4), maskPixels({"###..",
                                                         "##...",
                                                         "#....",
                                                         "....."}));
    // Fewer than three vertices: nothing.
    EXPECT_TRUE(polygonPixels(std::vector<GridPoint>{{0, 0}, {3, 0}}, 4, 4).empty());
}

TEST(PaintRegion, MagicWandStopsAtAStepAndAtEmptyPixels)
{
    // Heights: 0 on the left, a 5 mm step on columns 4.., one Empty pixel at (1, 1).
    const int w = 6, h = 3;
    std::vector<float> values(w * h, 0.0f);
    std::vector<std::uint8_t> valid(w * h, 1);
    for (int r = 0; r < h; ++r)
        for (int c = 4; c < w; ++c) values[r * w + c] = 0.005f;
    values[2] = 0.0009f; // within tolerance of the seed
    valid[1 * w + 1] = 0;
    EXPECT_EQ(floodFill(values, valid, w, h, 0, 0.001f), maskPixels({"####..",
                                                                     "#.##..",
                                                                     "####.."}));
    EXPECT_EQ(floodFill(values, valid, w, h, 5, 0.001f), maskPixels({"....##",
                                                                     "....##",
                                                                     "....##"}));
    // A wide tolerance crosses the step; an Empty seed gives nothing.
    EXPECT_EQ(floodFill(values, valid, w, h, 0, 0.01f).size(), std::size_t(w * h - 1));
    EXPECT_TRUE(floodFill(values, valid, w, h, 1 * w + 1, 1.0f).empty());
}

TEST(PaintRegion, EnclosedHolesAreWhatTheRegionSurrounds)
{
    const std::vector<std::string> rows{"..........",
                                        ".#####....",
                                        ".#..3#.22.",
                                        ".#.#.#.2..",
                                        ".#####....",
                                        "#........#",
                                        "#..#######",
                                        "#..#......"};
    std::vector<std::uint8_t> ids;
    for (const std::string& row : rows)
        for (char ch : row) ids.push_back(ch == '#' ? 1 : ch == '.' ? 0 : std::uint8_t(ch - '0'));
    const int w = 10, h = 8;
    // The ring's holes: (2..4, 2), (2, 3), (4, 3) — the class-3 pixel among them; (3, 3) is the ring itself.
    EXPECT_EQ(enclosedHoles(ids, w, h, 1 * w + 1), (Pixels{22, 23, 24, 32, 34}));
    // A region open to the border encloses nothing; the border pixels are outside.
    EXPECT_TRUE(enclosedHoles(ids, w, h, 6 * w + 5).empty());
    EXPECT_TRUE(enclosedHoles(ids, w, h, 0).empty()); // unlabelled seed
}

TEST(PixelLeafIndex, BothDirectionsAndTheMajority)
{
    // 6 leaves on a 3 × 2 grid: pixel 0 ← leaves 1, 4, 5; pixel 4 ← leaf 0; leaf 2 off; leaf 3 → pixel 5.
    const std::vector<std::int64_t> leafPixels{4, 0, -1, 5, 0, 0};
    const PixelLeafIndex index = PixelLeafIndex::build(leafPixels, 3, 2);
    EXPECT_EQ(index.mappedLeafCount(), 5u);
    EXPECT_EQ(Pixels(index.leavesAt(0).begin(), index.leavesAt(0).end()), (Pixels{1, 4, 5}));
    EXPECT_TRUE(index.leavesAt(1).empty());
    EXPECT_EQ(index.leavesOf(Pixels{5, 0, 0, 2}), (Pixels{1, 3, 4, 5}));
    EXPECT_EQ(index.pixelsOf(Pixels{5, 2, 0, 4, 9}), (Pixels{0, 4}));
    EXPECT_EQ(index.pixelOf(2), -1);
    // Majority as labelRasterFromLeaves: pixel 0 holds {2, 0, 2} → 2.
    std::vector<std::uint8_t> labels{7, 2, 9, 1, 0, 2};
    EXPECT_EQ(index.majorityLabel(0, labels), 2);
    const std::vector<std::uint8_t> all = index.majorityLabels(labels);
    EXPECT_EQ(all, (std::vector<std::uint8_t>{2, 0, 0, 0, 7, 1}));
    labels = {7, 3, 9, 1, 0, 4}; // pixel 0: {3, 0, 4}, a three-way tie → the smallest, 0
    EXPECT_EQ(index.majorityLabel(0, labels), 0);
    const LabelRaster reference = labelRasterFromLeaves(labels, leafPixels, 3, 2);
    EXPECT_EQ(index.majorityLabels(labels), reference.ids);
    // Many leaves on one pixel (the table path) agree with labelRasterFromLeaves too.
    std::vector<std::int64_t> many(40, 1);
    std::vector<std::uint8_t> manyLabels(40, 5);
    for (int i = 0; i < 20; ++i) manyLabels[i] = std::uint8_t(i % 2 ? 6 : 4);
    const PixelLeafIndex crowd = PixelLeafIndex::build(many, 2, 1);
    EXPECT_EQ(crowd.majorityLabels(manyLabels), labelRasterFromLeaves(manyLabels, many, 2, 1).ids);
    EXPECT_EQ(crowd.majorityLabel(1, manyLabels), 5);
}

TEST(PixelLeafIndex, PixelsWithAHeightButNoLeafShowTheirNearestLeaves)
{
    // A 6 × 2 grid: leaves on pixels 0 (label 3) and 5 (label 8); pixel 3 is empty, every other pixel has a height but
    // no leaf. Each shows the leaves nearest in 8-connected steps through pixels with a height: 1, 2, 6, 7, 8 are
    // nearer 0 (2 and 8 two steps away, three from 5); 4, 9, 10, 11 nearer 5; the empty pixel 3 shows nothing.
    using S = stylos::core::shading::PixelState;
    const std::vector<std::int64_t> leafPixels{0, 5};
    PixelLeafIndex index = PixelLeafIndex::build(leafPixels, 6, 2);
    const std::vector<std::uint8_t> labels{3, 8};
    // Before any lending: unpainted specks (0) beside the painted pixels.
    EXPECT_EQ(index.majorityLabels(labels), (std::vector<std::uint8_t>{3, 0, 0, 0, 0, 8, 0, 0, 0, 0, 0, 0}));
    const std::vector<S> states{S::Measured, S::Filled, S::Filled, S::Empty, S::Filled, S::Measured,
                                S::Filled,   S::Filled, S::Filled, S::Filled, S::Filled, S::Filled};
    index.lendLeaves(states);
    EXPECT_EQ(index.majorityLabels(labels), (std::vector<std::uint8_t>{3, 3, 3, 0, 8, 8, 3, 3, 3, 8, 8, 8}));
    EXPECT_EQ(index.shownPixel(2), 0);
    EXPECT_EQ(index.shownPixel(3), -1);
    EXPECT_EQ(index.shownPixel(9), 5);
    // Painting takes a pixel's own leaves only; a change of leaf 1 (pixel 5) redraws its borrowers too.
    EXPECT_TRUE(index.leavesOf(Pixels{1, 2, 4}).empty());
    EXPECT_EQ(index.pixelsOf(Pixels{1}), (Pixels{4, 5, 9, 10, 11}));
    EXPECT_EQ(index.pixelsOf(Pixels{0}), (Pixels{0, 1, 2, 6, 7, 8}));
}
