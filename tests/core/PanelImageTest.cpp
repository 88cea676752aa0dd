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
