#include "stylos/core/shading/ContrastStretch.h"

#include <gtest/gtest.h>

namespace stylos::core::shading {
namespace {

/** 1 × n image of @p values, all covered but the last. */
ShadedImage row(std::vector<float> values)
{
    ShadedImage image;
    image.width = int(values.size());
    image.height = 1;
    image.coverage.assign(values.size(), 1);
    image.coverage.back() = 0;
    image.values = std::move(values);
    return image;
}

TEST(ContrastStretchTest, PercentilesMapToZeroAndOne)
{
    // 11 covered values 0.80, 0.81, ... 0.90 and an uncovered 0.
    std::vector<float> v;
    for (int i = 0; i <= 10; ++i) v.push_back(0.80f + 0.01f * float(i));
    v.push_back(0.0f);
    ShadedImage image = row(v);
    const auto range = stretchContrast(image, 0.1, 0.9); // ranks 1 and 9
    ASSERT_TRUE(range.ok());
    EXPECT_FLOAT_EQ(range->low, 0.81f);
    EXPECT_FLOAT_EQ(range->high, 0.89f);
    EXPECT_EQ(image.values[0], 0.0f);  // below low: clamped
    EXPECT_EQ(image.values[1], 0.0f);
    EXPECT_NEAR(image.values[5], 0.5f, 1e-6f);
    EXPECT_EQ(image.values[9], 1.0f);
    EXPECT_EQ(image.values[10], 1.0f); // above high: clamped
    EXPECT_EQ(image.values[11], 0.0f); // uncovered stays 0
}

TEST(ContrastStretchTest, FlatImageIsMidGreyAndBadPercentilesAreRefused)
{
    ShadedImage flat = row({0.7f, 0.7f, 0.7f, 0.0f});
    ASSERT_TRUE(stretchContrast(flat).ok());
    EXPECT_EQ(flat.values, (std::vector<float>{0.5f, 0.5f, 0.5f, 0.0f}));
    ShadedImage image = row({0.1f, 0.2f, 0.0f});
    const auto bad = stretchContrast(image, 0.9, 0.1);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(image.values, (std::vector<float>{0.1f, 0.2f, 0.0f}));
    ShadedImage empty = row({0.3f});
    EXPECT_EQ(stretchContrast(empty)->high, 0.0f);
    EXPECT_EQ(empty.values[0], 0.3f); // uncovered: untouched
}

} // namespace
} // namespace stylos::core::shading
