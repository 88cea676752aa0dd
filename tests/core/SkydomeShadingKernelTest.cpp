// Skydome kernels: deep hulls (long concave profiles broken by spikes, which empty the register caches
// of the vector kernel) against a brute-force scan of each line; the portable and the vector kernels
// give the same bits (on a CPU without AVX-512 both runs take the portable one); opposite azimuths
// walk the same lines; an odd number of directions (no pairs of opposite walks).
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

/**
 * A dome (every profile concave: hulls as deep as the lines) with 3 % spikes, 0.3 % towers that pop
 * whole hulls at once, and 4 % empty pixels.
 */
HeightField domeWithSpikes(int width, int height, std::uint32_t seed)
{
    auto field = HeightField::create(width, height, 0.0005).value();
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> coin(0.0f, 1.0f), noise(0.0f, 0.0002f);
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) {
            const double x = (c - width / 2.0) * 0.0005, y = (r - height / 2.0) * 0.0005;
            const float dome = float(0.05 - 2.0 * (x * x + y * y));
            const float u = coin(random);
            if (u < 0.04f) continue; // Empty
            const float spike = u > 0.997f ? 0.03f : u > 0.97f ? 0.004f * coin(random) : 0.0f;
            field.setMeasured(c, r, dome + noise(random) + spike);
        }
    return field;
}

/** Horizon angle of every pixel by scanning, for each pixel, every pixel ahead on its line. */
std::vector<double> bruteForceAngles(const HeightField& field, double azimuth)
{
    const DirectionRaster raster(field.width(), field.height(), azimuth);
    std::vector<double> angles(field.pixelCount(), 0.0);
    for (int line = 0; line < raster.lineCount(); ++line) {
        std::vector<std::pair<int, int>> pixels;
        raster.forEachPixel(line, [&](int c, int r) {
            if (field.hasHeight(c, r)) pixels.emplace_back(c, r);
        });
        // Walk order: every pixel after the pixels ahead of it.
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            const auto [c, r] = pixels[i];
            double best = 0.0;
            for (std::size_t k = 0; k < i; ++k) {
                const auto [cq, rq] = pixels[k];
                const double ahead = (raster.along(cq, rq) - raster.along(c, r)) * field.pixelSize();
                best = std::max(best, std::atan2(double(field.heightAt(cq, rq)) - field.heightAt(c, r), ahead));
            }
            angles[field.index(c, r)] = best;
        }
    }
    return angles;
}

} // namespace

TEST(ShadingSkydomeKernel, DeepHullsEqualBruteForce)
{
    const auto field = domeWithSpikes(160, 120, 5);
    for (const double azimuth : {0.0, pi / 2, 1.5 * pi, pi / 4, 2.0, 3.6, 5.9}) {
        const auto angles = horizonAngles(field, azimuth, 2);
        ASSERT_TRUE(angles.ok());
        const auto expected = bruteForceAngles(field, azimuth);
        for (std::size_t i = 0; i < expected.size(); ++i)
            ASSERT_NEAR(angles.value()[i], expected[i], 1e-6) << "azimuth " << azimuth << " element " << i;
    }
}

TEST(ShadingSkydomeKernel, PortableAndVectorKernelsGiveTheSameBits)
{
    const auto field = domeWithSpikes(200, 150, 9);
    for (const int directions : {16, 5}) {
        SkydomeOptions vector{directions, 2, true}, portable{directions, 1, false};
        const auto a = shadeSkydome(field, vector);
        const auto b = shadeSkydome(field, portable);
        ASSERT_TRUE(a.ok() && b.ok());
        EXPECT_EQ(a->values, b->values) << directions << " directions";
        EXPECT_EQ(a->coverage, b->coverage);
    }
}

TEST(ShadingSkydomeKernel, OddDirectionCountEqualsBruteForce)
{
    const auto field = domeWithSpikes(61, 47, 2);
    const int directions = 7; // no opposite pairs: every direction walked on its own
    const auto image = shadeSkydome(field, {directions, 2});
    ASSERT_TRUE(image.ok());
    std::vector<double> occlusion(field.pixelCount(), 0.0);
    for (int k = 0; k < directions; ++k) {
        const auto angles = bruteForceAngles(field, skydomeAzimuth(k, directions));
        for (std::size_t i = 0; i < angles.size(); ++i) occlusion[i] += std::sin(angles[i]);
    }
    for (std::size_t i = 0; i < occlusion.size(); ++i) {
        if (field.states()[i] != PixelState::Empty) {
            ASSERT_NEAR(image->values[i], 1.0 - occlusion[i] / directions, 1e-6) << "element " << i;
        } else {
            EXPECT_EQ(image->values[i], 0.0f);
        }
    }
}

TEST(ShadingSkydomeKernel, OppositeAzimuthsWalkTheSameLines)
{
    // The skydome walks the lines of direction k backward for k + D/2: they must be the same lines.
    const int width = 37, height = 23;
    for (const int directions : {4, 8, 12, 16, 32, 40, 64, 360}) {
        for (int k = 0; k < directions / 2; ++k) {
            const DirectionRaster there(width, height, skydomeAzimuth(k, directions));
            const DirectionRaster back(width, height, skydomeAzimuth(k + directions / 2, directions));
            ASSERT_EQ(there.lineCount(), back.lineCount());
            for (int r = 0; r < height; ++r)
                for (int c = 0; c < width; ++c) {
                    // Same partition into lines (numbered alike when the axes agree) and opposite order.
                    for (int r2 = 0; r2 < height; r2 += 5)
                        for (int c2 = 0; c2 < width; c2 += 3) {
                            const bool together = there.lineOf(c, r) == there.lineOf(c2, r2);
                            ASSERT_EQ(together, back.lineOf(c, r) == back.lineOf(c2, r2))
                                << directions << " directions, k = " << k;
                        }
                    ASSERT_NEAR(there.along(c, r), -back.along(c, r), 1e-9);
                }
        }
    }
}
