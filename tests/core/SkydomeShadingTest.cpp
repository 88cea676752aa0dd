// Skydome: the rasterised lines cover every pixel once; hand-computed horizons (flat, pit, step,
// ramp); the hull sweep equals a brute-force scan of the same lines; threads do not change the image.
#include "stylos/core/shading/DirectionRaster.h"
#include "stylos/core/shading/SkydomeShading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace stylos::core;
using namespace stylos::core::shading;

namespace {

constexpr double pi = std::numbers::pi;

HeightField flatField(int width, int height, double pixelSize, float h = 0.0f)
{
    auto field = HeightField::create(width, height, pixelSize).value();
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) field.setMeasured(c, r, h);
    return field;
}

/** Rough random terrain (uniform noise plus a smooth swell), some pixels Empty. */
HeightField randomTerrain(int width, int height, std::uint32_t seed, double emptyFraction)
{
    auto field = HeightField::create(width, height, 0.0005).value();
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> noise(0.0f, 0.004f), coin(0.0f, 1.0f);
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) {
            if (coin(random) < emptyFraction) {
                field.setMeasured(c, r, 1.0f); // a tall height that must not occlude once cleared
                field.clear(c, r);
                continue;
            }
            const float swell = 0.01f * float(std::sin(c * 0.21) * std::cos(r * 0.17));
            field.setMeasured(c, r, swell + noise(random));
        }
    return field;
}

/** Horizon angle by scanning every pixel of the grid on the same line, ahead of (c, r). */
double bruteForceHorizon(const HeightField& field, const DirectionRaster& raster, int c, int r)
{
    if (!field.hasHeight(c, r)) return 0.0;
    const int line = raster.lineOf(c, r);
    const double along = raster.along(c, r);
    double best = 0.0;
    for (int rq = 0; rq < field.height(); ++rq)
        for (int cq = 0; cq < field.width(); ++cq) {
            if (!field.hasHeight(cq, rq) || raster.lineOf(cq, rq) != line) continue;
            const double ahead = raster.along(cq, rq) - along;
            if (ahead <= 0.0) continue;
            const double rise = double(field.heightAt(cq, rq)) - double(field.heightAt(c, r));
            best = std::max(best, std::atan2(rise, ahead * field.pixelSize()));
        }
    return best;
}

} // namespace

TEST(ShadingDirectionRaster, LinesCoverEveryPixelOnceInWalkOrder)
{
    const double azimuths[] = {0.0, pi / 4, pi / 2, 3 * pi / 4, pi, 1.25 * pi, 1.5 * pi, 1.75 * pi,
                               0.3, 1.1, 2.0, 2.9, 4.1, 5.0, 5.9, skydomeAzimuth(7, 40)};
    const std::pair<int, int> sizes[] = {{33, 29}, {1, 7}, {7, 1}, {1, 1}, {0, 0}, {16, 3}, {3, 16}};
    for (const auto& [width, height] : sizes)
        for (const double azimuth : azimuths) {
            const DirectionRaster raster(width, height, azimuth);
            std::vector<int> seen(std::size_t(width * height), 0);
            int total = 0;
            for (int line = 0; line < raster.lineCount(); ++line) {
                double previous = INFINITY;
                int length = 0;
                raster.forEachPixel(line, [&](int c, int r) {
                    ASSERT_TRUE(c >= 0 && r >= 0 && c < width && r < height);
                    ++seen[std::size_t(r * width + c)];
                    EXPECT_EQ(raster.lineOf(c, r), line);
                    // Walk order: against the direction, by at least 1/√2 px per step.
                    EXPECT_LE(raster.along(c, r), previous - 0.7071);
                    previous = raster.along(c, r);
                    ++length;
                });
                EXPECT_EQ(length, raster.lineLength(line));
                EXPECT_GE(length, 1) << "empty line " << line << " at azimuth " << azimuth;
                EXPECT_LE(length, raster.longestLine());
                total += length;
            }
            EXPECT_EQ(total, width * height);
            for (const int n : seen) ASSERT_EQ(n, 1) << width << "x" << height << " azimuth " << azimuth;
        }
}

TEST(ShadingSkydome, FlatFieldIsExactlyOne)
{
    auto field = flatField(50, 37, 0.0005, 0.25f);
    field.setMeasured(10, 10, 9.0f);
    field.clear(10, 10); // an empty pixel with a tall stale height: does not occlude
    const auto image = shadeSkydome(field);
    ASSERT_TRUE(image.ok());
    for (int r = 0; r < 37; ++r)
        for (int c = 0; c < 50; ++c) {
            if (c == 10 && r == 10) {
                EXPECT_FALSE(image->covered(c, r));
                EXPECT_EQ(image->value(c, r), 0.0f);
            } else {
                EXPECT_TRUE(image->covered(c, r));
                ASSERT_EQ(image->value(c, r), 1.0f) << c << "," << r;
            }
        }
}

TEST(ShadingSkydome, SinglePit)
{
    const double s = 1.0 / 1024, depth = 1.0 / 512; // exactly representable
    auto field = flatField(9, 9, s);
    field.setMeasured(4, 4, float(-depth));
    const auto image = shadeSkydome(field, {8, 1});
    ASSERT_TRUE(image.ok());
    // Axis directions see the next pixel at s, diagonal ones the diagonal pixel at √2 s.
    const double axis = depth / std::hypot(depth, s), diagonal = depth / std::hypot(depth, std::sqrt(2.0) * s);
    EXPECT_NEAR(image->value(4, 4), 1.0 - (4 * axis + 4 * diagonal) / 8, 1e-6);
    for (int r = 0; r < 9; ++r)
        for (int c = 0; c < 9; ++c)
            if (c != 4 || r != 4) {
                EXPECT_EQ(image->value(c, r), 1.0f) << c << "," << r;
            }

    const auto angles = horizonAngles(field, pi / 4, 1);
    ASSERT_TRUE(angles.ok());
    EXPECT_NEAR(angles.value()[field.index(4, 4)], std::atan(depth / (std::sqrt(2.0) * s)), 1e-6);
    EXPECT_EQ(angles.value()[field.index(3, 5)], 0.0f); // looks over the pit: nothing above it
}

TEST(ShadingSkydome, Step)
{
    const double s = 1.0 / 1024, rise = 3.0 / 1024;
    auto field = flatField(12, 5, s);
    for (int r = 0; r < 5; ++r)
        for (int c = 8; c < 12; ++c) field.setMeasured(c, r, float(rise));
    const auto image = shadeSkydome(field, {4, 2});
    const auto right = horizonAngles(field, pi / 2);
    const auto left = horizonAngles(field, 3 * pi / 2);
    ASSERT_TRUE(image.ok() && right.ok() && left.ok());
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 12; ++c) {
            const std::size_t i = field.index(c, r);
            EXPECT_EQ(left.value()[i], 0.0f);
            if (c >= 8) {
                EXPECT_EQ(right.value()[i], 0.0f);
                EXPECT_EQ(image->value(c, r), 1.0f);
                continue;
            }
            const double theta = std::atan(rise / ((8 - c) * s)); // the nearest high pixel wins
            EXPECT_NEAR(right.value()[i], theta, 1e-6) << c << "," << r;
            EXPECT_NEAR(image->value(c, r), 1.0 - std::sin(theta) / 4, 1e-6) << c << "," << r;
        }
}

TEST(ShadingSkydome, Ramp)
{
    // h = x / 2 (x to the right), pixel size 1/64 m: exact heights c / 128.
    const int width = 10, height = 8;
    auto field = HeightField::create(width, height, 1.0 / 64).value();
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) field.setMeasured(c, r, float(c) / 128.0f);
    const auto image = shadeSkydome(field, {8, 0});
    ASSERT_TRUE(image.ok());
    // Uphill to the right: atan(1/2); up-right and down-right (diagonal lines): atan(1/2 / √2).
    const double straight = std::sin(std::atan(0.5)), diagonal = std::sin(std::atan(0.5 / std::sqrt(2.0)));
    for (int r = 1; r < height - 1; ++r)
        for (int c = 0; c < width - 1; ++c)
            EXPECT_NEAR(image->value(c, r), 1.0 - (straight + 2 * diagonal) / 8, 1e-6) << c << "," << r;
    for (int r = 0; r < height; ++r) EXPECT_EQ(image->value(width - 1, r), 1.0f); // nothing uphill
    const auto upRight = horizonAngles(field, pi / 4);
    EXPECT_NEAR(upRight.value()[field.index(2, 5)], std::atan(0.5 / std::sqrt(2.0)), 1e-6);
}

TEST(ShadingSkydome, DeepHoleSeesAlmostNoSky)
{
    auto field = flatField(15, 15, 0.0005);
    field.setMeasured(7, 7, -100.0f);
    const auto image = shadeSkydome(field);
    EXPECT_NEAR(image->value(7, 7), 0.0, 1e-6);
}

TEST(ShadingSkydome, HullSweepEqualsBruteForce)
{
    const double azimuths[] = {0.0, pi / 2, pi, 1.5 * pi, pi / 4, 0.3, 1.1, 2.0, 2.9, 3.6, 4.1, 5.0, 5.9};
    for (const std::uint32_t seed : {1u, 2u, 3u}) {
        const auto field = randomTerrain(33, 29, seed, seed == 3 ? 0.15 : 0.0);
        for (const double azimuth : azimuths) {
            const DirectionRaster raster(field.width(), field.height(), azimuth);
            const auto angles = horizonAngles(field, azimuth, seed);
            ASSERT_TRUE(angles.ok());
            for (int r = 0; r < field.height(); ++r)
                for (int c = 0; c < field.width(); ++c)
                    ASSERT_NEAR(angles.value()[field.index(c, r)], bruteForceHorizon(field, raster, c, r), 1e-6)
                        << "seed " << seed << " azimuth " << azimuth << " pixel " << c << "," << r;
        }
        // The whole skydome against the brute-force sum over its 12 directions.
        const int directions = 12;
        const auto image = shadeSkydome(field, {directions, 2});
        ASSERT_TRUE(image.ok());
        std::vector<double> occlusion(field.pixelCount(), 0.0);
        for (int k = 0; k < directions; ++k) {
            const DirectionRaster raster(field.width(), field.height(), skydomeAzimuth(k, directions));
            for (int r = 0; r < field.height(); ++r)
                for (int c = 0; c < field.width(); ++c)
                    occlusion[field.index(c, r)] += std::sin(bruteForceHorizon(field, raster, c, r));
        }
        for (int r = 0; r < field.height(); ++r)
            for (int c = 0; c < field.width(); ++c) {
                if (!field.hasHeight(c, r)) continue;
                ASSERT_NEAR(image->value(c, r), 1.0 - occlusion[field.index(c, r)] / directions, 1e-6)
                    << "seed " << seed << " pixel " << c << "," << r;
            }
    }
}

TEST(ShadingSkydome, ThreadCountDoesNotChangeTheImage)
{
    const auto field = randomTerrain(211, 150, 7, 0.05);
    const auto one = shadeSkydome(field, {16, 1});
    const auto three = shadeSkydome(field, {16, 3});
    ASSERT_TRUE(one.ok() && three.ok());
    EXPECT_EQ(one->values, three->values);
    EXPECT_EQ(one->coverage, three->coverage);
    for (const float v : one->values) {
        EXPECT_GE(v, 0.0f);
        EXPECT_LE(v, 1.0f);
    }
}

TEST(ShadingSkydome, CancelProgressAndBadOptions)
{
    const auto field = randomTerrain(40, 30, 4, 0.0);
    SilentProgress cancelled;
    cancelled.cancel();
    auto image = shadeSkydome(field, {}, &cancelled);
    ASSERT_FALSE(image.ok());
    EXPECT_EQ(image.error().code, ErrorCode::Cancelled);
    const auto angles = horizonAngles(field, 1.0, 0, &cancelled);
    ASSERT_FALSE(angles.ok());
    EXPECT_EQ(angles.error().code, ErrorCode::Cancelled);

    SilentProgress running;
    ASSERT_TRUE(shadeSkydome(field, {}, &running).ok());
    EXPECT_EQ(running.last(), 1.0);

    for (const int bad : {0, -3, 5000}) {
        image = shadeSkydome(field, {bad, 0});
        ASSERT_FALSE(image.ok());
        EXPECT_EQ(image.error().code, ErrorCode::InvalidArgument);
    }
    EXPECT_EQ(horizonAngles(field, NAN).error().code, ErrorCode::InvalidArgument);

    HeightField none;
    image = shadeSkydome(none);
    ASSERT_TRUE(image.ok());
    EXPECT_TRUE(image->values.empty());
}
