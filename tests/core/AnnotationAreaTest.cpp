// Area per class from the cells (crossing density at the area level), measured against analytic areas on a
// generated plain drum: the painted rectangle and the whole object. The bounds are the measured errors
// (docs/annotation.md) with a little margin.
#include "AnnotationTestSupport.h"

#include "stylos/core/annotation/LabelArea.h"
#include "stylos/core/annotation/LeafLabels.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <numeric>

using namespace stylos::core::annotation;
namespace oct = stylos::core::octree;

TEST(AnnotationArea, MeasureClassesCountsAndSums)
{
    const std::vector<std::uint8_t> labels{0, 2, 2, 255};
    const std::vector<double> areas{1.0, 0.25, 0.5, 2.0};
    const auto m = measureClasses(labels, areas);
    ASSERT_EQ(m.size(), 256u);
    EXPECT_EQ(m[2].cells, 2u);
    EXPECT_DOUBLE_EQ(m[2].areaM2, 0.75);
    EXPECT_EQ(m[255].cells, 1u);
    EXPECT_EQ(m[0].cells, 1u);
    EXPECT_EQ(m[1].cells, 0u);
}

TEST(AnnotationArea, MatchesTheAnalyticAreaOfThePatchAndTheDrum)
{
    const auto& d = stylos::test::annotatedDrum();
    auto octree = oct::PackedOctree::open(d.poct);
    ASSERT_TRUE(octree.ok());
    auto pixels = leafPixels(*octree, *d.map);
    ASSERT_TRUE(pixels.ok());
    std::vector<std::uint8_t> labels(pixels->size(), 0);
    applyLabelRaster(d.rectangle(2), *pixels, labels);
    const double truePatch = d.rectangleArea();
    // The whole drum: lateral surface + two bed faces (their 2 mm recess adds its rim: 2 · 2π r · 0.002).
    const double ringInner = d.radius - std::min(0.08, 0.2 * d.radius);
    const double trueTotal = 2 * M_PI * d.radius * d.height + 2 * M_PI * d.radius * d.radius + 2 * 2 * M_PI * ringInner * 0.002;
    for (int up : {0, 1, 2, 3}) {
        auto areas = leafAreas(*octree, {up});
        ASSERT_TRUE(areas.ok());
        const auto m = measureClasses(labels, *areas);
        const double total = std::accumulate(areas->begin(), areas->end(), 0.0);
        std::printf("levelsUp %d: patch %.5f m2 (analytic %.5f, %+.2f %%), whole drum %.4f m2 (analytic %.4f, %+.2f %%)\n", up,
                    m[2].areaM2, truePatch, 100 * (m[2].areaM2 / truePatch - 1), total, trueTotal, 100 * (total / trueTotal - 1));
        if (up == LeafAreaOptions{}.levelsUp) {
            // Measured: patch +1.26 %, whole drum −4.75 % (the rims between the lateral surface and the beds,
            // where one area-level cell holds two faces, count once).
            EXPECT_NEAR(m[2].areaM2 / truePatch, 1.0, 0.02);
            EXPECT_NEAR(total / trueTotal, 1.0, 0.06);
        }
    }
}
