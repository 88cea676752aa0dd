// Label raster ↔ leaves on a generated plain drum: a rectangle of class 2 painted on its développée labels
// exactly the leaves whose centres map inside it (apart from a one-pixel border) and none outside; the raster
// made back from the leaves gives the rectangle; files round trip; bad rasters are refused naming the file.
#include "AnnotationTestSupport.h"

#include "stylos/core/annotation/LabelRaster.h"
#include "stylos/core/annotation/LeafLabels.h"

#include <gtest/gtest.h>

using namespace stylos::core::annotation;
namespace oct = stylos::core::octree;
namespace fs = std::filesystem;

namespace {

struct Mapped {
    oct::PackedOctree octree;
    std::vector<std::int64_t> pixels;
};

Mapped mapDrum()
{
    const auto& drum = stylos::test::annotatedDrum();
    auto opened = oct::PackedOctree::open(drum.poct);
    EXPECT_TRUE(opened.ok());
    auto pixels = leafPixels(*opened, *drum.map);
    EXPECT_TRUE(pixels.ok());
    return {std::move(opened).value(), std::move(pixels).value()};
}

/** 0 strictly inside the rectangle shrunk by one pixel, 2 outside it grown by one, 1 on the border band. */
int zone(const stylos::test::AnnotatedDrum& d, int c, int r)
{
    if (c > d.c0 && c < d.c1 - 1 && r > d.r0 && r < d.r1 - 1) return 0;
    if (c < d.c0 - 1 || c > d.c1 || r < d.r0 - 1 || r > d.r1) return 2;
    return 1;
}

} // namespace

TEST(AnnotationRaster, FixtureIsSound)
{
    const auto& d = stylos::test::annotatedDrum();
    ASSERT_TRUE(d.map.has_value());
    EXPECT_NEAR(d.map->surface().referenceRadius(), d.radius, 0.002);
    EXPECT_GE(d.r1 - d.r0, 4);
    EXPECT_GE(d.c1 - d.c0, 20);
}

TEST(AnnotationRaster, RectangleLabelsExactlyTheLeavesInside)
{
    const auto& d = stylos::test::annotatedDrum();
    Mapped m = mapDrum();
    std::vector<std::uint8_t> labels(m.pixels.size(), 0);
    const LabelRaster painted = d.rectangle(2);
    const std::uint64_t changed = applyLabelRaster(painted, m.pixels, labels);
    std::uint64_t inside = 0, insideLabelled = 0, outsideLabelled = 0, border = 0;
    for (std::size_t i = 0; i < labels.size(); ++i) {
        if (m.pixels[i] < 0) {
            EXPECT_EQ(labels[i], 0);
            continue;
        }
        const int c = int(m.pixels[i] % d.map->width()), r = int(m.pixels[i] / d.map->width());
        switch (zone(d, c, r)) {
        case 0: ++inside; insideLabelled += labels[i] == 2; break;
        case 2: outsideLabelled += labels[i] != 0; break;
        default: ++border;
        }
    }
    EXPECT_GT(inside, 500u);
    EXPECT_EQ(insideLabelled, inside);
    EXPECT_EQ(outsideLabelled, 0u);
    EXPECT_GE(changed, inside);
    EXPECT_LE(changed, inside + border);
    // Painting again changes nothing; id 0 pixels never erase.
    EXPECT_EQ(applyLabelRaster(painted, m.pixels, labels), 0u);
    EXPECT_EQ(applyLabelRaster(LabelRaster(d.map->width(), d.map->height()), m.pixels, labels), 0u);
}

TEST(AnnotationRaster, RasterFromLeavesGivesBackTheRectangle)
{
    const auto& d = stylos::test::annotatedDrum();
    Mapped m = mapDrum();
    std::vector<std::uint8_t> labels(m.pixels.size(), 0);
    applyLabelRaster(d.rectangle(2), m.pixels, labels);
    const LabelRaster back = labelRasterFromLeaves(labels, m.pixels, d.map->width(), d.map->height());
    std::vector<int> hasLeaf(back.ids.size(), 0);
    for (auto p : m.pixels)
        if (p >= 0) hasLeaf[std::size_t(p)] = 1;
    int insideWithLeaves = 0;
    for (int r = 0; r < back.height; ++r)
        for (int c = 0; c < back.width; ++c) {
            const int z = zone(d, c, r);
            const std::uint8_t v = back.at(c, r);
            if (z == 0 && hasLeaf[std::size_t(r) * back.width + c]) {
                ++insideWithLeaves;
                EXPECT_EQ(v, 2) << c << "," << r;
            }
            if (z == 0 && !hasLeaf[std::size_t(r) * back.width + c]) {
                EXPECT_EQ(v, 0);
            }
            if (z == 2) {
                EXPECT_EQ(v, 0) << c << "," << r;
            }
        }
    EXPECT_GT(insideWithLeaves, (d.c1 - d.c0 - 2) * (d.r1 - d.r0 - 2) * 9 / 10);
}

TEST(AnnotationRaster, MajorityAndTies)
{
    const std::vector<std::uint8_t> labels{3, 3, 1, 5, 1, 0, 0, 7};
    const std::vector<std::int64_t> pixels{0, 0, 0, 1, 1, 2, -1, 3};
    const LabelRaster r = labelRasterFromLeaves(labels, pixels, 5, 1);
    EXPECT_EQ(r.ids, (std::vector<std::uint8_t>{3, 1, 0, 7, 0}));
}

TEST(AnnotationRaster, FileRoundTripPngAndTiff)
{
    stylos::test::TempDir dir;
    LabelRaster raster(37, 11);
    for (std::size_t i = 0; i < raster.ids.size(); ++i) raster.ids[i] = std::uint8_t(i * 7);
    for (const char* name : {"l.png", "l.tif"}) {
        ASSERT_TRUE(writeLabelRaster(raster, dir / name, 0.0005).ok()) << name;
        const auto back = readLabelRaster(dir / name);
        ASSERT_TRUE(back.ok()) << back.error().message;
        EXPECT_EQ(back->width, 37);
        EXPECT_EQ(back->height, 11);
        EXPECT_EQ(back->ids, raster.ids) << name;
    }
    EXPECT_FALSE(writeLabelRaster(raster, dir / "l.jpg", 0.0005).ok());
    EXPECT_FALSE(fs::exists(dir / "l.jpg"));
    const auto missing = readLabelRaster(dir / "none.png");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, stylos::core::ErrorCode::NotFound);
    stylos::test::writeText(dir / "junk.png", "not a png");
    const auto junk = readLabelRaster(dir / "junk.png");
    ASSERT_FALSE(junk.ok());
    EXPECT_NE(junk.error().message.find("junk.png"), std::string::npos);
}

TEST(AnnotationRaster, CheckRefusesWrongSizeAndUnknownIds)
{
    const auto& d = stylos::test::annotatedDrum();
    const Legend legend = Legend::defaults();
    EXPECT_TRUE(checkLabelRaster(d.rectangle(4), "r.png", *d.map, "m.json", legend, AnnotationLayer::Material).ok());
    const auto small = checkLabelRaster(LabelRaster(d.map->width() - 1, d.map->height()), "r.png", *d.map, "m.json", legend,
                                        AnnotationLayer::Material);
    ASSERT_FALSE(small.ok());
    EXPECT_EQ(small.error().message.rfind("r.png: ", 0), 0u) << small.error().message;
    EXPECT_NE(small.error().message.find("m.json"), std::string::npos);
    LabelRaster bad = d.rectangle(0);
    bad.at(5, 1) = 5; // toolmark has 5 (rasp), material does not
    EXPECT_TRUE(checkLabelRaster(bad, "r.png", *d.map, "m.json", legend, AnnotationLayer::Toolmark).ok());
    const auto unknown = checkLabelRaster(bad, "r.png", *d.map, "m.json", legend, AnnotationLayer::Material);
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().message, "r.png: pixel (5, 1): class id 5 is not in the material legend");
}
