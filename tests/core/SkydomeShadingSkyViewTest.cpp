// The RVT-like sky-view factor (radius-limited ray march): hand-computed values and invariants.
#include "stylos/core/shading/SkyViewFactor.h"
#include "stylos/core/shading/SkydomeShading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace stylos::core;
using namespace stylos::core::shading;

namespace {

HeightField flatField(int width, int height, double pixelSize)
{
    auto field = HeightField::create(width, height, pixelSize).value();
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) field.setMeasured(c, r, 0.0f);
    return field;
}

} // namespace

TEST(ShadingSkyView, FlatIsOneAndPitMatchesTheSkydome)
{
    const double s = 1.0 / 1024, depth = 1.0 / 512;
    auto field = flatField(25, 21, s);
    field.setMeasured(3, 3, 7.0f);
    field.clear(3, 3); // empty: skipped, not an obstacle
    auto image = shadeSkyViewFactor(field);
    ASSERT_TRUE(image.ok());
    for (int r = 0; r < 21; ++r)
        for (int c = 0; c < 25; ++c)
            if (c != 3 || r != 3) {
                ASSERT_EQ(image->value(c, r), 1.0f);
            }
    EXPECT_FALSE(image->covered(3, 3));

    // A one-pixel pit: its nearest samples are the 4 axis neighbours (s) and 4 diagonal ones (√2 s),
    // as in the skydome.
    field.setMeasured(12, 10, float(-depth));
    image = shadeSkyViewFactor(field, {8, 10, 1, 1});
    const auto dome = shadeSkydome(field, {8, 1});
    const double axis = depth / std::hypot(depth, s), diagonal = depth / std::hypot(depth, std::sqrt(2.0) * s);
    EXPECT_NEAR(image->value(12, 10), 1.0 - (4 * axis + 4 * diagonal) / 8, 1e-6);
    EXPECT_NEAR(image->value(12, 10), dome->value(12, 10), 1e-6);
}

TEST(ShadingSkyView, RadiusLimitsTheHorizon)
{
    // A wall 12 px away is seen by the skydome but not by a 10 px ray march.
    const double s = 1.0 / 1024;
    auto field = flatField(30, 5, s);
    for (int r = 0; r < 5; ++r) field.setMeasured(20, r, 0.01f);
    const auto march = shadeSkyViewFactor(field, {4, 10, 1, 0});
    const auto dome = shadeSkydome(field, {4, 0});
    EXPECT_EQ(march->value(8, 2), 1.0f);
    EXPECT_NEAR(dome->value(8, 2), 1.0 - std::sin(std::atan(0.01 / (12 * s))) / 4, 1e-6);
    EXPECT_NEAR(march->value(10, 2), dome->value(10, 2), 1e-6); // 10 px: both see it
}

TEST(ShadingSkyView, ThreadsCancelAndBadOptions)
{
    auto field = HeightField::create(97, 61, 0.0005).value();
    std::mt19937 random(3);
    std::uniform_real_distribution<float> noise(0.0f, 0.003f);
    for (int r = 0; r < 61; ++r)
        for (int c = 0; c < 97; ++c) field.setMeasured(c, r, noise(random));
    field.clear(40, 30);
    const auto one = shadeSkyViewFactor(field, {16, 10, 1, 1});
    const auto three = shadeSkyViewFactor(field, {16, 10, 1, 3});
    ASSERT_TRUE(one.ok() && three.ok());
    EXPECT_EQ(one->values, three->values);
    for (const float v : one->values) {
        EXPECT_GE(v, 0.0f);
        EXPECT_LE(v, 1.0f);
    }

    SilentProgress cancelled;
    cancelled.cancel();
    auto image = shadeSkyViewFactor(field, {}, &cancelled);
    ASSERT_FALSE(image.ok());
    EXPECT_EQ(image.error().code, ErrorCode::Cancelled);

    for (const SkyViewOptions bad : {SkyViewOptions{0, 10, 1, 0}, SkyViewOptions{16, 10, 0, 0},
                                     SkyViewOptions{16, 3, 5, 0}, SkyViewOptions{16, 5000, 1, 0}}) {
        image = shadeSkyViewFactor(field, bad);
        ASSERT_FALSE(image.ok());
        EXPECT_EQ(image.error().code, ErrorCode::InvalidArgument);
    }
}
