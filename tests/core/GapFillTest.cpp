// GapFill: the 3D view's screen-space gap filling, exactly, on small hand-made frames: what it closes (enclosed
// gaps, slits up to r wide, notches along an outline, a far surface seen through a narrow gap) and what it
// keeps (an opening of 2 r or wider, a straight outline, a convex corner, a groove within the depth margin).
#include "stylos/core/view/GapFill.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace stylos::core::view;

namespace {

constexpr std::uint32_t Surface = 0xff808080u;
constexpr std::uint32_t Paper = 0u;

/** A w × h frame of background. */
GapFrame blank(int w, int h)
{
    GapFrame f;
    f.width = w;
    f.height = h;
    f.depth.assign(std::size_t(w) * h, GapFrame::Background);
    f.colour.assign(f.depth.size(), Paper);
    f.reach.assign(f.depth.size(), 0);
    return f;
}

/** Sets the rectangle [x0, x1) × [y0, y1) to surface of @p depth, @p colour and @p reach. */
void paint(GapFrame& f, int x0, int y0, int x1, int y1, float depth, std::uint32_t colour = Surface, std::uint8_t reach = 4)
{
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::size_t i = std::size_t(y) * f.width + x;
            f.depth[i] = depth;
            f.colour[i] = colour;
            f.reach[i] = reach;
        }
}

void clear(GapFrame& f, int x0, int y0, int x1, int y1)
{
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::size_t i = std::size_t(y) * f.width + x;
            f.depth[i] = GapFrame::Background;
            f.colour[i] = Paper;
            f.reach[i] = 0;
        }
}

std::int64_t backgroundIn(const GapFrame& f, int x0, int y0, int x1, int y1)
{
    std::int64_t n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) n += f.depth[std::size_t(y) * f.width + x] == GapFrame::Background ? 1 : 0;
    return n;
}

float depthAt(const GapFrame& f, int x, int y) { return f.depth[std::size_t(y) * f.width + x]; }
std::uint32_t colourAt(const GapFrame& f, int x, int y) { return f.colour[std::size_t(y) * f.width + x]; }

} // namespace

TEST(GapFillTest, AnEnclosedGapNarrowerThanTwoReachesIsFilledFromItsNeighbours)
{
    GapFrame f = blank(40, 30);
    paint(f, 5, 5, 35, 25, 2.0f);
    clear(f, 15, 12, 18, 15); // 3 × 3
    EXPECT_EQ(fillGaps(f), 9);
    EXPECT_EQ(backgroundIn(f, 0, 0, 40, 30), 40 * 30 - 30 * 20); // only the outside stays
    EXPECT_EQ(depthAt(f, 16, 13), 2.0f);
    EXPECT_EQ(colourAt(f, 16, 13), Surface);
}

TEST(GapFillTest, TheFillTakesTheNearestInDepthOfTheEnclosingNeighbours)
{
    GapFrame f = blank(20, 20);
    paint(f, 2, 2, 18, 18, 2.0f, 0xff0000ffu);
    paint(f, 11, 2, 18, 18, 1.5f, 0xff00ff00u); // the right part nearer
    clear(f, 10, 9, 11, 10);                    // one pixel at the seam
    EXPECT_EQ(fillGaps(f), 1);
    EXPECT_EQ(depthAt(f, 10, 9), 1.5f);
    EXPECT_EQ(colourAt(f, 10, 9), 0xff00ff00u);
}

TEST(GapFillTest, ASlitUpToOneReachWideClosesAWiderOneOnlyInItsMiddleAndOneOfTwoReachesStaysOpen)
{
    // A pixel of a slit sees both walls (W, E and the four diagonals: 6 directions) only when both are within
    // its reach r = 4; near one wall it sees 3.
    GapFrame f = blank(60, 20);
    paint(f, 0, 0, 60, 20, 1.0f);
    clear(f, 10, 0, 14, 20); // 4 wide = r
    clear(f, 25, 0, 31, 20); // 6 wide: the 2 middle columns are within 4 of both walls
    clear(f, 45, 0, 53, 20); // 8 wide = 2 r
    fillGaps(f);
    // Rows more than r from the picture's border (the walks leave the picture there, enclosing nothing):
    EXPECT_EQ(backgroundIn(f, 10, 4, 14, 16), 0);
    EXPECT_EQ(backgroundIn(f, 25, 4, 31, 16), 4 * 12);
    EXPECT_EQ(backgroundIn(f, 27, 4, 29, 16), 0);
    EXPECT_EQ(backgroundIn(f, 45, 0, 53, 20), 8 * 20);
}

TEST(GapFillTest, AnOpeningWiderThanTwoReachesStaysButForItsConcaveCorners)
{
    GapFrame f = blank(40, 40);
    paint(f, 0, 0, 40, 40, 1.0f);
    clear(f, 14, 14, 26, 26); // 12 × 12: an unscanned box
    // Only the pixels within r = 4 of two walls at once (an r × r square in each corner) are enclosed.
    EXPECT_EQ(fillGaps(f), 4 * 4 * 4);
    EXPECT_EQ(backgroundIn(f, 14, 14, 26, 26), 12 * 12 - 64);
    EXPECT_EQ(backgroundIn(f, 18, 14, 22, 26), 4 * 12); // the middle columns, top to bottom, stay open
    EXPECT_EQ(backgroundIn(f, 14, 18, 26, 22), 4 * 12); // and the middle rows
    EXPECT_EQ(depthAt(f, 14, 14), 1.0f);
    EXPECT_EQ(depthAt(f, 18, 14), GapFrame::Background);
}

TEST(GapFillTest, AStraightOutlineAndConvexCornersStayCrisp)
{
    GapFrame f = blank(40, 30);
    paint(f, 10, 8, 30, 22, 1.0f); // a rectangle: four straight sides, four convex corners
    EXPECT_EQ(fillGaps(f), 0);
    EXPECT_EQ(backgroundIn(f, 0, 0, 40, 30), 40 * 30 - 20 * 14);
}

TEST(GapFillTest, ANotchInTheOutlineClosesAndTheBackgroundAboveItStays)
{
    GapFrame f = blank(40, 30);
    paint(f, 5, 10, 35, 25, 1.0f);
    clear(f, 18, 10, 21, 13); // a notch 3 wide, 3 deep, open upward
    EXPECT_EQ(fillGaps(f), 9);
    EXPECT_EQ(backgroundIn(f, 18, 10, 21, 13), 0);
    EXPECT_EQ(backgroundIn(f, 0, 0, 40, 10), 40 * 10);
}

TEST(GapFillTest, AFarSurfaceSeenThroughANarrowGapIsHiddenAndAWideOneIsKept)
{
    GapFrame f = blank(60, 20);
    paint(f, 0, 0, 60, 20, 1.0f, Surface);
    paint(f, 10, 0, 12, 20, 3.0f, 0xff000000u);  // a stripe of the far side, 2 px
    paint(f, 30, 0, 40, 20, 3.0f, 0xff000000u);  // 10 px: a true view of the far side
    paint(f, 50, 0, 52, 20, 1.02f, 0xff000000u); // a groove only 2 % deeper: within the margin
    EXPECT_EQ(fillGaps(f), 2 * 18); // all but the stripe's ends on the picture's border (4 directions there)
    EXPECT_EQ(depthAt(f, 10, 5), 1.0f);
    EXPECT_EQ(colourAt(f, 11, 5), Surface);
    EXPECT_EQ(depthAt(f, 35, 5), 3.0f);
    EXPECT_EQ(depthAt(f, 50, 5), 1.02f);
}

TEST(GapFillTest, AGapCountsOnlyAsWideAsTheReachOfTheDiscsAroundIt)
{
    GapFrame f = blank(20, 20);
    paint(f, 2, 2, 18, 18, 1.0f, Surface, 1);
    clear(f, 8, 8, 11, 11); // 3 × 3 among discs of reach 1: only its 4 corner pixels see 5 walls 1 step away
    EXPECT_EQ(fillGaps(f), 4);
    EXPECT_EQ(depthAt(f, 8, 8), 1.0f);
    EXPECT_EQ(depthAt(f, 9, 8), GapFrame::Background);
    EXPECT_EQ(depthAt(f, 9, 9), GapFrame::Background);
}

TEST(GapFillTest, WalksStopAtMaxStepsAndAtThePicturesBorder)
{
    GapFrame f = blank(30, 30);
    paint(f, 0, 0, 30, 30, 1.0f, Surface, 100);
    clear(f, 10, 10, 19, 19); // 9 × 9 among wide discs: the centre is 5 steps from every wall
    GapFillOptions options;
    options.maxSteps = 4;
    GapFrame g = f;
    EXPECT_EQ(fillGaps(g, options), 4 * 4 * 4); // the corners; the cross 5 steps from two walls stays
    EXPECT_EQ(depthAt(g, 14, 14), GapFrame::Background);
    EXPECT_EQ(depthAt(g, 14, 10), GapFrame::Background);
    options.maxSteps = 5;
    g = f;
    EXPECT_EQ(fillGaps(g, options), 81);

    GapFrame edge = blank(10, 10); // background along the border: the outside encloses nothing
    paint(edge, 0, 1, 10, 10, 1.0f);
    EXPECT_EQ(fillGaps(edge), 0);
}

TEST(GapFillTest, TheReachOfADiscIsItsRadiusRoundedWithinOneTo127)
{
    EXPECT_EQ(gapReach(0.2), 1);
    EXPECT_EQ(gapReach(2.49), 2);
    EXPECT_EQ(gapReach(2.5), 3);
    EXPECT_EQ(gapReach(500.0), 127);
    EXPECT_EQ(gapReach(std::nan("")), 1);
}
