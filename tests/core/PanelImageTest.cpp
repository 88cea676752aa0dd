// core::plate::shownClasses: the classes a panel shows as a region (a pixel with its four neighbours of its class);
// scattered pixels and one-pixel slivers — a far-side patch glimpsed at a silhouette or through a pinhole — are not,
// so the plate's legend leaves them out.
#include "stylos/core/plate/PanelImage.h"

#include <gtest/gtest.h>

using namespace stylos::core::plate;

TEST(PanelImage, OnlyRegionsAreShownClasses)
{
    PanelImage image;
    image.width = 12;
    image.height = 8;
    image.classes.assign(std::size_t(image.width * image.height), 0);
    const auto set = [&image](int x, int y, std::uint8_t c) { image.classes[std::size_t(y * image.width + x)] = c; };
    for (int y = 1; y <= 3; ++y)
        for (int x = 1; x <= 3; ++x) set(x, y, 3); // a 3 × 3 patch: its centre's neighbours are all 3
    set(6, 2, 4);                                   // a speck
    set(8, 5, 4);                                   // another
    for (int x = 2; x <= 10; ++x) set(x, 6, 5);     // a sliver one pixel high
    for (int y = 0; y <= 7; ++y) set(11, y, 6);     // and one on the border
    const auto shown = shownClasses(image);
    for (int c = 0; c < 256; ++c) EXPECT_EQ(shown[std::size_t(c)], c == 3) << c;
    set(2, 2, 7); // the patch's centre taken: nothing of 3 has its four neighbours any more
    EXPECT_FALSE(shownClasses(image)[3]);
    EXPECT_FALSE(shownClasses(PanelImage{})[3]); // no classes
}

// On blocks (the plate's ~1/72 inch at its dpi), a region is judged as at 72 dpi: a block is the class that fills more
// than half of it. The same patch drawn at 4× the resolution is shown; a sliver 3 pixels wide (under a block) is not.
TEST(PanelImage, BlocksJudgeRegionsAsAtTheirSize)
{
    PanelImage image;
    image.width = 24;
    image.height = 24;
    image.classes.assign(std::size_t(image.width * image.height), 0);
    const auto set = [&image](int x, int y, std::uint8_t c) { image.classes[std::size_t(y * image.width + x)] = c; };
    for (int y = 4; y < 16; ++y)
        for (int x = 4; x < 16; ++x) set(x, y, 3); // 3 × 3 blocks of 4
    for (int y = 0; y < 24; ++y)
        for (int x = 18; x < 21; ++x) set(x, y, 5); // 3 pixels wide across two blocks: 8 and 4 of their 16 pixels
    for (int y = 0; y < 24; ++y) set(22, y, 6);     // 1 pixel wide
    auto shown = shownClasses(image, 4);
    EXPECT_TRUE(shown[3]);
    EXPECT_FALSE(shown[5]); // no block more than half of it
    EXPECT_FALSE(shown[6]);
    // Pixel by pixel (block 1) the 3-wide sliver is a region: its middle column's pixels have their four neighbours.
    shown = shownClasses(image, 1);
    EXPECT_TRUE(shown[3]);
    EXPECT_TRUE(shown[5]);
    EXPECT_FALSE(shown[6]);
}
