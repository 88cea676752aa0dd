// ImageCoverage: the holes of a rendered picture, exactly, on small hand-made masks.
#include "stylos/core/view/ImageCoverage.h"

#include <gtest/gtest.h>

using namespace stylos::core::view;

namespace {

/** A w × h mask with the rectangle [x0, x1) × [y0, y1) set to @p v. */
void fill(CoverageMask& m, int w, int x0, int y0, int x1, int y1, std::uint8_t v)
{
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) m[std::size_t(y) * w + x] = v;
}

} // namespace

TEST(ImageCoverageTest, AGapEnclosedBySurfaceIsThroughAndCountedExactly)
{
    const int w = 40, h = 30;
    CoverageMask m(w * h, 0);
    fill(m, w, 5, 5, 35, 25, 1);  // a surface 30 × 20
    fill(m, w, 15, 12, 18, 15, 0); // a 3 × 3 gap inside it
    std::vector<HoleKind> kinds;
    const CoverageCounts c = measureCoverage(m, w, h, 2, &kinds);
    EXPECT_EQ(c.silhouette, 30 * 20);
    EXPECT_EQ(c.covered, 30 * 20 - 9);
    EXPECT_EQ(c.holes, 9);
    EXPECT_EQ(c.through, 9);
    EXPECT_EQ(c.edge, 0);
    EXPECT_EQ(kinds[std::size_t(13) * w + 16], HoleKind::Through);
    EXPECT_EQ(kinds[std::size_t(0) * w + 0], HoleKind::None);
    EXPECT_DOUBLE_EQ(c.holeFraction(), 9.0 / 600.0);
}

TEST(ImageCoverageTest, ANotchInTheOutlineIsEdgeNotThrough)
{
    const int w = 40, h = 30;
    CoverageMask m(w * h, 0);
    fill(m, w, 5, 5, 35, 25, 1);
    fill(m, w, 20, 5, 22, 9, 0); // a notch 2 wide, 4 deep, from the top outline
    const CoverageCounts c = measureCoverage(m, w, h, 2);
    EXPECT_EQ(c.holes, 8);       // the closing (5 × 5) fills the notch
    EXPECT_EQ(c.through, 0);
    EXPECT_EQ(c.edge, 8);
    EXPECT_EQ(c.silhouette, 600);
}

TEST(ImageCoverageTest, AGapWiderThanTheClosingIsOutsideAndItsFilledCornersAreEdge)
{
    const int w = 40, h = 30;
    CoverageMask m(w * h, 0);
    fill(m, w, 5, 5, 35, 25, 1);
    fill(m, w, 12, 10, 22, 20, 0); // a 10 × 10 opening: wider than the 5 × 5 closing, stays outside
    const CoverageCounts c = measureCoverage(m, w, h, 2);
    EXPECT_EQ(c.silhouette, 600 - 100);
    EXPECT_EQ(c.holes, 0);
    m[std::size_t(9) * w + 12] = 0; // one pixel more above the opening's corner: a notch into it
    const CoverageCounts d = measureCoverage(m, w, h, 2);
    EXPECT_EQ(d.holes, 1);
    EXPECT_EQ(d.edge, 1);
    EXPECT_EQ(d.through, 0);
}

TEST(ImageCoverageTest, ThinStripesAcrossTheSurfaceAreThroughWhereEnclosed)
{
    // Stripes of background between scan lines, stopping one pixel short of the outline: enclosed.
    const int w = 40, h = 30;
    CoverageMask m(w * h, 0);
    fill(m, w, 5, 5, 35, 25, 1);
    for (int y = 7; y < 24; y += 3) fill(m, w, 6, y, 34, y + 1, 0); // 6 stripes of 28 pixels
    const CoverageCounts c = measureCoverage(m, w, h, 2);
    EXPECT_EQ(c.holes, 6 * 28);
    EXPECT_EQ(c.through, 6 * 28);
    // The same stripes cut through the outline join the outside: edge, still counted as holes.
    fill(m, w, 5, 7, 6, 8, 0);
    const CoverageCounts d = measureCoverage(m, w, h, 2);
    EXPECT_EQ(d.holes, 6 * 28 + 1);
    EXPECT_EQ(d.edge, 29);
    EXPECT_EQ(d.through, 5 * 28);
}

TEST(ImageCoverageTest, TheBorderCountsAsOpenAndTheClosingKeepsShapesCutByIt)
{
    const int w = 20, h = 10;
    CoverageMask m(w * h, 1);
    fill(m, w, 0, 4, 2, 6, 0); // a 2 × 2 gap on the left border
    fill(m, w, 9, 4, 11, 6, 0); // the same inside
    const CoverageCounts c = measureCoverage(m, w, h, 2);
    EXPECT_EQ(c.silhouette, 200); // a full picture stays full at the border
    EXPECT_EQ(c.holes, 8);
    EXPECT_EQ(c.through, 4);
    EXPECT_EQ(c.edge, 4);
}

TEST(ImageCoverageTest, AnEmptyPictureHasNoSilhouetteAndNoHoles)
{
    const CoverageCounts c = measureCoverage(CoverageMask(12, 0), 4, 3, 2);
    EXPECT_EQ(c.silhouette, 0);
    EXPECT_EQ(c.holes, 0);
    EXPECT_DOUBLE_EQ(c.holeFraction(), 0.0);
}
