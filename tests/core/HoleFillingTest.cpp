// Hole filling: small holes get the exact neighbour averages from the rim inward; large, deep and
// border-touching empty regions stay empty; the mask tells measured from filled.
#include "stylos/core/shading/HoleFilling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace stylos::core;
using namespace stylos::core::shading;

namespace {

/** A fully measured field with distinct, exactly representable heights c² + 7r² (metres). */
HeightField measuredField(int width, int height)
{
    auto field = HeightField::create(width, height, 0.001).value();
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) field.setMeasured(c, r, float(c * c + 7 * r * r));
    return field;
}

void clearRect(HeightField& field, int c0, int r0, int w, int h)
{
    for (int r = r0; r < r0 + h; ++r)
        for (int c = c0; c < c0 + w; ++c) field.clear(c, r);
}

/** Mean of the measured 8- (or 4-) neighbours of (c, r) in the original field. */
double measuredMean(const HeightField& field, int c, int r, bool eight)
{
    double sum = 0.0;
    int n = 0;
    for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
            if ((dc == 0 && dr == 0) || (!eight && dc != 0 && dr != 0)) continue;
            if (field.contains(c + dc, r + dr) && field.stateAt(c + dc, r + dr) == PixelState::Measured) {
                sum += field.heightAt(c + dc, r + dr);
                ++n;
            }
        }
    return sum / n;
}

} // namespace

TEST(ShadingHoleFilling, SinglePixelGetsTheNeighbourAverage)
{
    for (const auto connectivity : {Connectivity::Eight, Connectivity::Four}) {
        auto field = measuredField(5, 5);
        field.clear(2, 2);
        const auto report = fillHoles(field, {connectivity, 256, 0});
        ASSERT_TRUE(report.ok());
        EXPECT_EQ(field.stateAt(2, 2), PixelState::Filled);
        // Neighbours: 8, 11, 16, 29, 37, 64, 67, 72 (8-connected, mean 38); 11, 29, 37, 67 (4: mean 36).
        EXPECT_EQ(field.heightAt(2, 2), connectivity == Connectivity::Eight ? 38.0f : 36.0f);
        EXPECT_EQ(report->holes, 1u);
        EXPECT_EQ(report->filledHoles, 1u);
        EXPECT_EQ(report->filledPixels, 1u);
        EXPECT_EQ(report->deepestFill, 1);
        EXPECT_EQ(field.count(PixelState::Measured), 24u);
        EXPECT_EQ(field.count(PixelState::Filled), 1u);
    }
}

TEST(ShadingHoleFilling, TwoByTwoHoleUsesOnlyMeasuredNeighbours)
{
    auto field = measuredField(6, 6);
    clearRect(field, 2, 2, 2, 2);
    const HeightField before = field;
    const auto report = fillHoles(field);
    ASSERT_TRUE(report.ok());
    EXPECT_EQ(report->deepestFill, 1); // every pixel touches the rim: one round, no pixel sees another
    for (int r = 2; r < 4; ++r)
        for (int c = 2; c < 4; ++c) {
            EXPECT_EQ(field.stateAt(c, r), PixelState::Filled);
            EXPECT_EQ(field.heightAt(c, r), float(measuredMean(before, c, r, true))) << c << "," << r;
        }
}

TEST(ShadingHoleFilling, FillsFromTheRimInward)
{
    auto field = measuredField(7, 7);
    clearRect(field, 2, 2, 3, 3);
    const HeightField before = field;
    const auto report = fillHoles(field);
    ASSERT_TRUE(report.ok());
    EXPECT_EQ(report->deepestFill, 2);
    double ring = 0.0;
    for (int r = 2; r < 5; ++r)
        for (int c = 2; c < 5; ++c) {
            if (c == 3 && r == 3) continue;
            const float expected = float(measuredMean(before, c, r, true)); // round 1: measured only
            EXPECT_EQ(field.heightAt(c, r), expected) << c << "," << r;
            ring += expected;
        }
    EXPECT_EQ(field.heightAt(3, 3), float(ring / 8)); // round 2: the eight pixels of round 1
    EXPECT_EQ(field.count(PixelState::Filled), 9u);
}

TEST(ShadingHoleFilling, LargeAndDeepHolesStayEmpty)
{
    auto field = measuredField(20, 20);
    clearRect(field, 5, 5, 10, 10);
    auto copy = field;
    auto report = fillHoles(field, {Connectivity::Eight, 99, 0});
    ASSERT_TRUE(report.ok());
    EXPECT_EQ(report->filledHoles, 0u);
    EXPECT_EQ(report->largeHolePixels, 100u);
    EXPECT_EQ(field.count(PixelState::Empty), 100u);
    EXPECT_EQ(field.count(PixelState::Filled), 0u);

    report = fillHoles(copy, {Connectivity::Eight, 100, 0});
    ASSERT_TRUE(report.ok());
    EXPECT_EQ(report->filledPixels, 100u);
    EXPECT_EQ(report->deepestFill, 5);

    // Depth limit: a 3 × 3 hole is 2 deep; a 1 × 30 crack is 1 deep whatever its length.
    auto deep = measuredField(40, 8);
    clearRect(deep, 2, 2, 3, 3);
    clearRect(deep, 6, 4, 30, 1);
    report = fillHoles(deep, {Connectivity::Eight, 1000, 1});
    ASSERT_TRUE(report.ok());
    EXPECT_EQ(report->holes, 2u);
    EXPECT_EQ(report->filledPixels, 30u);
    EXPECT_EQ(report->largeHolePixels, 9u);
    EXPECT_EQ(deep.stateAt(3, 3), PixelState::Empty);
    EXPECT_EQ(deep.stateAt(20, 4), PixelState::Filled);
}

TEST(ShadingHoleFilling, RegionsTouchingTheBorderStayEmpty)
{
    auto field = measuredField(10, 10);
    clearRect(field, 0, 3, 2, 2); // touches the left border
    clearRect(field, 4, 9, 1, 1); // one pixel on the bottom row
    field.clear(5, 5);            // a true hole
    const auto report = fillHoles(field);
    ASSERT_TRUE(report.ok());
    EXPECT_EQ(report->holes, 3u);
    EXPECT_EQ(report->filledHoles, 1u);
    EXPECT_EQ(report->borderPixels, 5u);
    EXPECT_EQ(field.stateAt(0, 3), PixelState::Empty);
    EXPECT_EQ(field.stateAt(1, 4), PixelState::Empty);
    EXPECT_EQ(field.stateAt(4, 9), PixelState::Empty);
    EXPECT_EQ(field.stateAt(5, 5), PixelState::Filled);
    EXPECT_EQ(field.count(PixelState::Measured), 94u);
}

TEST(ShadingHoleFilling, ConnectivityDefinesTheHoles)
{
    // Two diagonal empty pixels: one hole of 2 pixels (8-connected) or two of 1 (4-connected).
    for (const auto connectivity : {Connectivity::Eight, Connectivity::Four}) {
        auto field = measuredField(6, 6);
        field.clear(2, 2);
        field.clear(3, 3);
        const auto report = fillHoles(field, {connectivity, 1, 0});
        ASSERT_TRUE(report.ok());
        const bool eight = connectivity == Connectivity::Eight;
        EXPECT_EQ(report->holes, eight ? 1u : 2u);
        EXPECT_EQ(report->filledPixels, eight ? 0u : 2u);
        EXPECT_EQ(field.stateAt(2, 2), eight ? PixelState::Empty : PixelState::Filled);
    }
}

TEST(ShadingHoleFilling, AlreadyFilledPixelsCountAsData)
{
    auto field = measuredField(5, 5);
    field.setFilled(1, 1, 100.0f);
    field.clear(2, 2);
    ASSERT_TRUE(fillHoles(field).ok());
    EXPECT_EQ(field.heightAt(2, 2), float((304.0 - 8.0 + 100.0) / 8));
    EXPECT_EQ(field.stateAt(1, 1), PixelState::Filled);
}

TEST(ShadingHoleFilling, CancelLeavesTheFieldUnchanged)
{
    auto field = measuredField(8, 8);
    field.clear(3, 3);
    SilentProgress progress;
    progress.cancel();
    const auto report = fillHoles(field, {}, &progress);
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().code, ErrorCode::Cancelled);
    EXPECT_EQ(field.stateAt(3, 3), PixelState::Empty);

    SilentProgress running;
    ASSERT_TRUE(fillHoles(field, {}, &running).ok());
    EXPECT_EQ(running.last(), 1.0);
}

TEST(ShadingHoleFilling, RefusesBadOptions)
{
    auto field = measuredField(4, 4);
    auto report = fillHoles(field, {Connectivity::Eight, 0, 0});
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().code, ErrorCode::InvalidArgument);
    report = fillHoles(field, {Connectivity::Eight, 10, -1});
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().code, ErrorCode::InvalidArgument);
    report = fillHoles(field, {Connectivity(6), 10, 0});
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().code, ErrorCode::InvalidArgument);
}

TEST(ShadingHoleFilling, EmptyFieldAndFullyEmptyField)
{
    HeightField none;
    EXPECT_EQ(fillHoles(none)->holes, 0u);
    auto blank = HeightField::create(6, 4, 0.001).value();
    const auto report = fillHoles(blank);
    ASSERT_TRUE(report.ok());
    EXPECT_EQ(report->holes, 1u);
    EXPECT_EQ(report->borderPixels, 24u);
    EXPECT_EQ(blank.count(PixelState::Empty), 24u);
}

// The gaps between samples at a pixel near the spacing: one-pixel lines joined into a network larger than the
// largest hole filled (and reaching the border), which fillHoles() leaves and which read as cracks, are filled
// inside the footprint; a region wider than the footprint's closing (a broken face) stays empty.
TEST(ShadingHoleFilling, GapsInsideTheFootprintAreFilledWhateverTheirExtent)
{
    auto field = measuredField(70, 40);
    const HeightField original = field;
    // A grid of one-pixel gaps every 4 pixels over columns 2 … 42 and rows 2 … 38, one line reaching the top border.
    for (int r = 2; r <= 38; ++r)
        for (int c = 2; c <= 42; ++c)
            if (r % 4 == 2 || c % 4 == 2) field.clear(c, r);
    for (int r = 0; r < 2; ++r) field.clear(10, r);
    clearRect(field, 48, 8, 18, 18); // a broken region: 18 × 18, more than the 256 pixels fillHoles() fills
    const auto small = fillHoles(field);
    ASSERT_TRUE(small.ok());
    EXPECT_EQ(small->filledPixels, 0u); // the network is one hole of > 256 pixels, and touches the border
    const int holes = int(std::count(field.states().begin(), field.states().end(), PixelState::Empty));

    const auto gaps = fillFootprintGaps(field, 1);
    ASSERT_TRUE(gaps.ok()) << gaps.error().message;
    EXPECT_EQ(gaps->holes, 2u);
    EXPECT_EQ(gaps->filledHoles, 1u);
    EXPECT_EQ(gaps->largeHolePixels, 324u);
    EXPECT_EQ(gaps->filledPixels, std::size_t(holes - 324));
    for (int r = 8; r < 26; ++r)
        for (int c = 48; c < 66; ++c) EXPECT_EQ(field.stateAt(c, r), PixelState::Empty) << c << "," << r;
    // A gap pixel between measured ones has their exact average: (10, 0) lies between (9, 0) and (11, 0) and over
    // (9, 1)…(11, 1) of which (10, 1) is a gap too (depth 2 is filled after it): first round, depth 1.
    EXPECT_EQ(field.stateAt(10, 0), PixelState::Filled);
    EXPECT_EQ(field.heightAt(10, 0), float((81.0 + 121.0 + (81.0 + 7) + (121.0 + 7)) / 4.0));
    // A crossing of two gap lines (6, 6): its 8 neighbours are gaps but the diagonals (5, 5), (7, 5), (5, 7), (7, 7).
    EXPECT_EQ(field.stateAt(6, 6), PixelState::Filled);
    EXPECT_EQ(field.heightAt(6, 6), float((double(original.heightAt(5, 5)) + original.heightAt(7, 5) +
                                           original.heightAt(5, 7) + original.heightAt(7, 7)) / 4.0));
    for (int r = 0; r < 40; ++r)
        for (int c = 0; c < 70; ++c)
            if (original.stateAt(c, r) == PixelState::Measured && field.stateAt(c, r) == PixelState::Measured)
                EXPECT_EQ(field.heightAt(c, r), original.heightAt(c, r));
    EXPECT_FALSE(fillFootprintGaps(field, 0).ok());
}
