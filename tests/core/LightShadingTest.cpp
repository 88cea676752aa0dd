// One directional light: a plane facing the light is 1, a plane at angle α is cos α, flat is sin e.
#include "stylos/core/shading/LightShading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace stylos::core;
using namespace stylos::core::shading;

namespace {

constexpr double pi = std::numbers::pi;

/** Plane h = a·x + b·y in the shading frame (x right, y up toward row 0), pixel size 1/64 m. */
HeightField plane(double a, double b, int width = 9, int height = 7)
{
    auto field = HeightField::create(width, height, 1.0 / 64).value();
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) {
            const double x = c / 64.0, y = (height - 1 - r) / 64.0;
            field.setMeasured(c, r, float(a * x + b * y));
        }
    return field;
}

} // namespace

TEST(ShadingLight, PlaneFacingTheLightIsOne)
{
    const double a = 0.75, b = -0.5; // normal ∝ (−a, −b, 1)
    const double norm = std::sqrt(a * a + b * b + 1.0);
    const LightShadingOptions light{std::atan2(-a, -b), std::asin(1.0 / norm), 1.0};
    const auto image = shadeLight(plane(a, b), light);
    ASSERT_TRUE(image.ok());
    for (int r = 0; r < 7; ++r)
        for (int c = 0; c < 9; ++c) EXPECT_NEAR(image->value(c, r), 1.0, 1e-6) << c << "," << r;
}

TEST(ShadingLight, PlaneAtKnownAngleIsCosine)
{
    // Flat field: n = z, so n · l = sin(elevation) whatever the azimuth.
    const auto flat = shadeLight(plane(0, 0), {0.3, pi / 6, 1.0});
    EXPECT_NEAR(flat->value(4, 3), 0.5, 1e-7);

    // h = −x (falling to the right): the normal leans 45° toward +x (the right, azimuth π/2).
    const auto tilted = plane(-1.0, 0.0);
    const auto zenith = shadeLight(tilted, {0.0, pi / 2, 1.0});
    EXPECT_NEAR(zenith->value(4, 3), std::cos(pi / 4), 1e-6);
    const auto fromRight = shadeLight(tilted, {pi / 2, pi / 6, 1.0}); // 15° from the normal
    EXPECT_NEAR(fromRight->value(0, 0), std::cos(pi / 12), 1e-6);
    const auto fromLeft = shadeLight(tilted, {3 * pi / 2, pi / 3, 1.0}); // 75° from the normal
    EXPECT_NEAR(fromLeft->value(8, 6), std::cos(5 * pi / 12), 1e-6);
    const auto grazing = shadeLight(tilted, {3 * pi / 2, pi / 6, 1.0}); // 105°: in shadow
    EXPECT_EQ(grazing->value(4, 3), 0.0f);

    // Rising toward the top (row 0): the normal leans toward −y, away from a light at azimuth 0.
    const auto up = shadeLight(plane(0.0, 1.0), {pi, pi / 4, 1.0}); // light from below: facing it
    EXPECT_NEAR(up->value(4, 3), 1.0, 1e-6);

    // Vertical exaggeration 2 on slope 0.5 is slope 1: 45° from the zenith.
    const auto exaggerated = shadeLight(plane(-0.5, 0.0), {0.0, pi / 2, 2.0});
    EXPECT_NEAR(exaggerated->value(4, 3), std::cos(pi / 4), 1e-6);
}

TEST(ShadingLight, EmptyNeighboursUseOneSidedDifferences)
{
    auto field = plane(-1.0, 0.0);
    field.clear(3, 3); // (4, 3) has a neighbour only on its right; (2, 3) only on its left
    field.clear(5, 2);
    field.clear(5, 4); // (5, 3): both vertical neighbours missing → no slope along y
    const auto image = shadeLight(field, {0.0, pi / 2, 1.0});
    ASSERT_TRUE(image.ok());
    for (const auto& [c, r] : {std::pair{4, 3}, std::pair{2, 3}, std::pair{5, 3}})
        EXPECT_NEAR(image->value(c, r), std::cos(pi / 4), 1e-6);
    EXPECT_FALSE(image->covered(3, 3));
    EXPECT_EQ(image->value(3, 3), 0.0f);

    auto lonely = HeightField::create(3, 3, 0.01).value();
    lonely.setMeasured(1, 1, 5.0f); // no neighbours at all: flat
    EXPECT_NEAR(shadeLight(lonely, {1.0, pi / 6, 1.0})->value(1, 1), 0.5, 1e-7);
}

TEST(ShadingLight, RefusesBadOptions)
{
    const auto field = plane(0, 0);
    for (const LightShadingOptions bad : {LightShadingOptions{0.0, -0.1, 1.0}, LightShadingOptions{0.0, 2.0, 1.0},
                                          LightShadingOptions{NAN, 0.5, 1.0}, LightShadingOptions{0.0, 0.5, 0.0},
                                          LightShadingOptions{0.0, 0.5, INFINITY}}) {
        const auto image = shadeLight(field, bad);
        ASSERT_FALSE(image.ok());
        EXPECT_EQ(image.error().code, ErrorCode::InvalidArgument);
    }
}
