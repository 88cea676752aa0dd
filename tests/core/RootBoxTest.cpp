#include "stylos/core/octree/RootBox.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace stylos::core::octree;

TEST(RootBox, EnclosingIsACubeOnTheLargestExtentCentredOnTheBounds)
{
    const RootBox box = RootBox::enclosing({1, 2, 3, 5, 4, 3.5});
    EXPECT_EQ(box.size, 4.0);
    EXPECT_EQ(box.origin[0], 1.0);  // centre 3
    EXPECT_EQ(box.origin[1], 1.0);  // centre 3
    EXPECT_EQ(box.origin[2], 1.25); // centre 3.25
}

TEST(RootBox, EnclosingDegenerateBounds)
{
    // A single point: a 1 m cube centred on it.
    const RootBox point = RootBox::enclosing({2, -3, 10, 2, -3, 10});
    EXPECT_EQ(point.size, 1.0);
    EXPECT_EQ(point.origin, (std::array<double, 3>{1.5, -3.5, 9.5}));
    // Flat along two axes: the one extent decides.
    const RootBox line = RootBox::enclosing({0, 0, 0, 0, 0, 0.25});
    EXPECT_EQ(line.size, 0.25);
    EXPECT_EQ(line.origin, (std::array<double, 3>{-0.125, -0.125, 0}));
}

TEST(RootBox, CellSizeAndCentre)
{
    RootBox box;
    box.origin = {-1, 0, 2};
    box.size = 8;
    EXPECT_EQ(box.cellSize(0), 8.0);
    EXPECT_EQ(box.cellSize(3), 1.0);
    EXPECT_EQ(box.cellCentre(0, 0, 0, 0), (std::array<double, 3>{3, 4, 6}));
    EXPECT_EQ(box.cellCentre(3, 0, 7, 2), (std::array<double, 3>{-0.5, 7.5, 4.5}));
}

TEST(RootBox, QuantiseEdgesAndClamping)
{
    RootBox box;
    box.origin = {0, 0, 0};
    box.size = 1;
    const double inside[3] = {0.0, 0.5, 0.999};
    EXPECT_EQ(box.quantise(inside, 2), (std::array<std::uint32_t, 3>{0, 2, 3}));
    // Points on the maximum faces go in the last cell; points outside are clamped.
    const double maxFace[3] = {1.0, 1.0, 1.0};
    EXPECT_EQ(box.quantise(maxFace, 4), (std::array<std::uint32_t, 3>{15, 15, 15}));
    const double outside[3] = {-0.1, 2.0, -1e300};
    EXPECT_EQ(box.quantise(outside, 4), (std::array<std::uint32_t, 3>{0, 15, 0}));
    // Just under a cell boundary stays in the lower cell.
    const double below[3] = {0.25 - 1e-12, 0.25, 0.75 - 1e-12};
    EXPECT_EQ(box.quantise(below, 2), (std::array<std::uint32_t, 3>{0, 1, 2}));
    // NaN never gives an undefined conversion.
    const double nan[3] = {std::numeric_limits<double>::quiet_NaN(), 0, 0};
    EXPECT_EQ(box.quantise(nan, 3)[0], 0u);
}

TEST(RootBox, QuantiseAtMaximumDepthAndCoarserLevelsAreShifts)
{
    const RootBox box = RootBox::enclosing({10, 20, 30, 11, 20.5, 30.25});
    const double p[3] = {10.123456, 20.3, 30.2};
    const auto deep = box.quantise(p, MaxOctreeDepth);
    EXPECT_LE(deep[0], (1u << MaxOctreeDepth) - 1);
    for (int l = 0; l <= MaxOctreeDepth; ++l) {
        const auto q = box.quantise(p, l);
        for (int a = 0; a < 3; ++a) EXPECT_EQ(q[a], deep[a] >> (MaxOctreeDepth - l)) << "level " << l;
    }
    const double corner[3] = {11, 20.5 + 0.25, 30.25 + 0.5};
    EXPECT_EQ(box.quantise(corner, MaxOctreeDepth)[0], (1u << MaxOctreeDepth) - 1);
}

TEST(RootBox, ChildSlotBits)
{
    EXPECT_EQ(childSlot(0, 0, 0), 0u);
    EXPECT_EQ(childSlot(1, 0, 0), 1u);
    EXPECT_EQ(childSlot(2, 3, 0), 2u);
    EXPECT_EQ(childSlot(5, 7, 9), 7u);
    EXPECT_EQ(childSlot(4, 6, 1), 4u);
}
