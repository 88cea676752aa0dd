// Height as grey: nearest-rank percentiles, linear mapping, clamping, empty pixels transparent.
#include "stylos/core/shading/HeightShading.h"

#include <gtest/gtest.h>

using namespace stylos::core;
using namespace stylos::core::shading;

namespace {

/** 10 × 10, heights 0 … 99 mm in row-major order, all measured. */
HeightField ramp100()
{
    auto field = HeightField::create(10, 10, 0.001).value();
    for (int i = 0; i < 100; ++i) field.setMeasured(i % 10, i / 10, float(i));
    return field;
}

} // namespace

TEST(ShadingHeight, RobustRangeIsNearestRank)
{
    auto field = ramp100();
    auto range = robustHeightRange(field, 0.01, 0.99);
    ASSERT_TRUE(range.ok());
    EXPECT_EQ(range->low, 1.0);  // rank floor(0.01 · 99 + 0.5) = 1
    EXPECT_EQ(range->high, 98.0); // rank floor(0.99 · 99 + 0.5) = 98
    range = robustHeightRange(field, 0.0, 1.0);
    EXPECT_EQ(range->low, 0.0);
    EXPECT_EQ(range->high, 99.0);
    range = robustHeightRange(field, 0.5, 0.5);
    EXPECT_EQ(range->low, 50.0); // floor(49.5 + 0.5)
}

TEST(ShadingHeight, MapsTheRobustRangeToGrey)
{
    auto field = ramp100();
    field.setMeasured(9, 9, 1.0e6f); // an outlier (rank 99) does not stretch the range
    field.setMeasured(0, 0, -5.0f);  // nor one below (rank 0)
    const auto image = shadeHeight(field);
    ASSERT_TRUE(image.ok());
    EXPECT_EQ(image->width, 10);
    EXPECT_EQ(image->height, 10);
    EXPECT_EQ(image->pixelSize, 0.001);
    EXPECT_EQ(image->value(0, 0), 0.0f); // clamped
    EXPECT_EQ(image->value(1, 0), 0.0f); // h = 1: the low end
    EXPECT_FLOAT_EQ(image->value(0, 5), 49.0f / 97.0f);
    EXPECT_EQ(image->value(8, 9), 1.0f); // h = 98: the high end
    EXPECT_EQ(image->value(9, 9), 1.0f); // clamped
    for (const auto c : image->coverage) EXPECT_EQ(c, 1);
}

TEST(ShadingHeight, EmptyPixelsAreTransparentAndIgnored)
{
    auto field = ramp100();
    for (int c = 0; c < 10; ++c) field.clear(c, 0); // removes heights 0 … 9
    field.setFilled(5, 5, 55.0f);
    const auto range = robustHeightRange(field, 0.0, 1.0);
    EXPECT_EQ(range->low, 10.0);
    const auto image = shadeHeight(field, {0.0, 1.0, {}});
    ASSERT_TRUE(image.ok());
    EXPECT_FALSE(image->covered(3, 0));
    EXPECT_EQ(image->value(3, 0), 0.0f);
    EXPECT_TRUE(image->covered(5, 5)); // filled pixels are shaded like measured ones
    EXPECT_FLOAT_EQ(image->value(5, 5), 45.0f / 89.0f);
}

TEST(ShadingHeight, FlatFixedAndBadRanges)
{
    auto flat = HeightField::create(3, 2, 0.001).value();
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c) flat.setMeasured(c, r, 2.5f);
    EXPECT_EQ(shadeHeight(flat)->value(1, 1), 0.5f);

    const auto fixed = shadeHeight(ramp100(), {0.01, 0.99, HeightRange{0.0, 200.0}});
    EXPECT_FLOAT_EQ(fixed->value(0, 5), 50.0f / 200.0f);

    for (const HeightShadingOptions bad :
         {HeightShadingOptions{-0.1, 0.9, {}}, HeightShadingOptions{0.1, 1.5, {}},
          HeightShadingOptions{0.9, 0.1, {}}, HeightShadingOptions{0.0, 1.0, HeightRange{2.0, 1.0}}}) {
        const auto image = shadeHeight(flat, bad);
        ASSERT_FALSE(image.ok());
        EXPECT_EQ(image.error().code, ErrorCode::InvalidArgument);
    }
    HeightField none;
    EXPECT_TRUE(shadeHeight(none).ok());
}
