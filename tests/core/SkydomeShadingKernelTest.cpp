// Skydome kernels: deep hulls (long concave profiles broken by spikes, which empty the register caches
// of the vector kernels) against a brute-force scan of each line, for each kernel the CPU runs (the
// others skip); the AVX2 and AVX-512 kernels give the portable kernel's bits; how the kernel is chosen
// (Auto, STYLOS_SKYDOME_KERNEL, a kernel the CPU lacks); opposite azimuths walk the same lines; an odd
// number of directions (no pairs of opposite walks).
#include "stylos/core/shading/DirectionRaster.h"
#include "stylos/core/shading/SkydomeShading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <utility>
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

/** Each kernel of this build, run where the CPU has it and skipped cleanly where it does not. */
class ShadingSkydomeEachKernel : public testing::TestWithParam<SkydomeKernel> {
protected:
    void SetUp() override
    {
        if (!skydomeKernelAvailable(GetParam()))
            GTEST_SKIP() << "this CPU (or build) does not run the " << skydomeKernelName(GetParam()) << " kernel";
    }
};

TEST_P(ShadingSkydomeEachKernel, DeepHullsEqualBruteForce)
{
    const auto field = domeWithSpikes(160, 120, 5);
    for (const double azimuth : {0.0, pi / 2, 1.5 * pi, pi / 4, 2.0, 3.6, 5.9}) {
        const auto angles = horizonAngles(field, azimuth, 2, nullptr, GetParam());
        ASSERT_TRUE(angles.ok());
        const auto expected = bruteForceAngles(field, azimuth);
        for (std::size_t i = 0; i < expected.size(); ++i)
            ASSERT_NEAR(angles.value()[i], expected[i], 1e-6) << "azimuth " << azimuth << " element " << i;
    }
}

TEST_P(ShadingSkydomeEachKernel, GivesThePortableKernelsBits)
{
    // Widths that leave a last band of 1–15 lines (partial halves and registers), D odd and even.
    for (const auto& [width, height] : {std::pair{200, 150}, std::pair{77, 53}, std::pair{9, 130}}) {
        const auto field = domeWithSpikes(width, height, 9);
        for (const int directions : {16, 5}) {
            const SkydomeOptions vector{directions, 2, GetParam()}, portable{directions, 1, SkydomeKernel::Portable};
            const auto a = shadeSkydome(field, vector);
            const auto b = shadeSkydome(field, portable);
            ASSERT_TRUE(a.ok() && b.ok());
            EXPECT_EQ(a->values, b->values) << width << " x " << height << ", " << directions << " directions";
            EXPECT_EQ(a->coverage, b->coverage);
        }
        // The slopes of one azimuth (HorizonValue::Slope, a single forward walk) as well.
        const auto a = horizonAngles(field, 2.0, 2, nullptr, GetParam());
        const auto b = horizonAngles(field, 2.0, 1, nullptr, SkydomeKernel::Portable);
        ASSERT_TRUE(a.ok() && b.ok());
        EXPECT_EQ(a.value(), b.value()) << width << " x " << height;
    }
}

INSTANTIATE_TEST_SUITE_P(Kernels, ShadingSkydomeEachKernel,
                         testing::Values(SkydomeKernel::Portable, SkydomeKernel::Avx2, SkydomeKernel::Avx512),
                         [](const auto& info) { return std::string(skydomeKernelName(info.param)); });

TEST(ShadingSkydomeKernel, AutoTakesTheFastestKernelOfTheCpu)
{
    const auto resolved = resolveSkydomeKernel(SkydomeKernel::Auto);
    ASSERT_TRUE(resolved.ok());
    const SkydomeKernel expected = skydomeKernelAvailable(SkydomeKernel::Avx512) ? SkydomeKernel::Avx512
                                   : skydomeKernelAvailable(SkydomeKernel::Avx2) ? SkydomeKernel::Avx2
                                                                                 : SkydomeKernel::Portable;
    EXPECT_EQ(resolved.value(), expected);
    EXPECT_EQ(resolveSkydomeKernel(SkydomeKernel::Portable).value(), SkydomeKernel::Portable);
}

TEST(ShadingSkydomeKernel, NamesRoundTripAndUnknownNamesAreRefused)
{
    for (const auto kernel : {SkydomeKernel::Auto, SkydomeKernel::Portable, SkydomeKernel::Avx2, SkydomeKernel::Avx512})
        EXPECT_EQ(parseSkydomeKernel(skydomeKernelName(kernel)).value(), kernel);
    const auto unknown = parseSkydomeKernel("sse9");
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(unknown.error().message.find("'sse9'"), std::string::npos) << unknown.error().message;
}

TEST(ShadingSkydomeKernel, EnvironmentVariableForcesTheAutoKernel)
{
    const auto field = domeWithSpikes(40, 30, 3);
    ASSERT_EQ(setenv("STYLOS_SKYDOME_KERNEL", "portable", 1), 0);
    const auto forced = resolveSkydomeKernel(SkydomeKernel::Auto);
    const auto explicitKernel = resolveSkydomeKernel(SkydomeKernel::Portable);
    ASSERT_EQ(setenv("STYLOS_SKYDOME_KERNEL", "fastest", 1), 0);
    const auto bad = shadeSkydome(field, {8, 1});
    const auto badAngles = horizonAngles(field, 1.0, 1);
    const auto unaffected = shadeSkydome(field, {8, 1, SkydomeKernel::Portable}); // only Auto reads it
    unsetenv("STYLOS_SKYDOME_KERNEL");
    ASSERT_TRUE(forced.ok());
    EXPECT_EQ(forced.value(), SkydomeKernel::Portable);
    EXPECT_EQ(explicitKernel.value(), SkydomeKernel::Portable);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(bad.error().message.find("STYLOS_SKYDOME_KERNEL=fastest"), std::string::npos) << bad.error().message;
    ASSERT_FALSE(badAngles.ok());
    EXPECT_TRUE(unaffected.ok());
}

TEST(ShadingSkydomeKernel, AKernelTheCpuLacksIsRefused)
{
    int refused = 0;
    for (const auto kernel : {SkydomeKernel::Avx2, SkydomeKernel::Avx512}) {
        if (skydomeKernelAvailable(kernel)) continue;
        ++refused;
        const auto image = shadeSkydome(domeWithSpikes(20, 20, 1), {4, 1, kernel});
        ASSERT_FALSE(image.ok());
        EXPECT_EQ(image.error().code, ErrorCode::InvalidArgument);
        EXPECT_NE(image.error().message.find(std::string(skydomeKernelName(kernel))), std::string::npos);
    }
    if (refused == 0) GTEST_SKIP() << "this CPU runs every kernel: nothing to refuse";
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
