// HeightNoise: the noise measured against the noise injected, the smoothing's exact weights, empty pixels that
// neither give nor take height, and the skydome of a noisy fluted field read evenly once smoothed.
#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/shading/HeightNoise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace stylos::core::shading {
namespace {

/** @p w × @p h pixels of @p pixel metres: flutes (a cosine @p depth deep, @p period pixels) plus white noise. */
HeightField fluted(int w, int h, double pixel, double depth, int period, double noise, unsigned seed = 7)
{
    auto field = HeightField::create(w, h, pixel).value();
    std::mt19937 rng(seed);
    std::normal_distribution<double> gauss(0.0, noise);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            const double phase = 2.0 * std::numbers::pi * c / period;
            // Flat tops (fillets) where the cosine is above 0.8, grooves between.
            const double profile = std::cos(phase) > 0.8 ? 0.0 : -depth * (0.8 - std::cos(phase)) / 1.8;
            field.setMeasured(c, r, float(profile + (noise > 0 ? gauss(rng) : 0.0)));
        }
    return field;
}

TEST(HeightNoiseTest, TheMeasuredNoiseIsTheInjectedOne)
{
    for (double sigma : {0.0001, 0.00033, 0.001}) {
        const HeightField f = fluted(600, 300, 0.0005, 0.008, 120, sigma);
        EXPECT_NEAR(estimateHeightNoise(f), sigma, 0.05 * sigma) << sigma;
    }
    // Smooth relief alone is no noise (its curvature × pixel² is micrometres here).
    EXPECT_LT(estimateHeightNoise(fluted(600, 300, 0.0005, 0.008, 120, 0.0)), 5e-6);
    // Too few pixels with four measured neighbours: no estimate.
    EXPECT_EQ(estimateHeightNoise(fluted(5, 5, 0.0005, 0.008, 120, 0.001)), 0.0);
}

TEST(HeightNoiseTest, TheSmoothingFollowsTheNoiseAndThePixel)
{
    const double pixel = 0.0005, noise = 0.0002;
    const double expected = noise / (2.0 * std::sqrt(std::numbers::pi) * kSlopeNoise * pixel) * pixel;
    EXPECT_DOUBLE_EQ(noiseSmoothingSigma(noise, pixel), expected);
    EXPECT_EQ(noiseSmoothingSigma(0.00001, pixel), 0.0);                     // under half a pixel: none
    EXPECT_DOUBLE_EQ(noiseSmoothingSigma(0.1, pixel), kMaxSmoothingPixels * pixel); // at most 16 pixels
    EXPECT_EQ(noiseSmoothingSigma(0.0, pixel), 0.0);
}

TEST(HeightNoiseTest, ASpikeSpreadsByTheGaussianWeightsAndEmptyPixelsStayOut)
{
    auto f = HeightField::create(21, 21, 0.001).value();
    for (int r = 0; r < 21; ++r)
        for (int c = 0; c < 21; ++c) f.setMeasured(c, r, 0.0f);
    f.setMeasured(10, 10, 1.0f);
    for (int r = 0; r < 21; ++r) f.clear(20, r); // an empty last column
    auto s = smoothHeights(f, 0.001); // σ = 1 pixel, taps exp(-k²/2) for |k| ≤ 3
    ASSERT_TRUE(s.ok());
    const double sum = 1.0 + 2.0 * (std::exp(-0.5) + std::exp(-2.0) + std::exp(-4.5));
    EXPECT_NEAR(s->heightAt(10, 10), 1.0 / (sum * sum), 1e-6);
    EXPECT_NEAR(s->heightAt(11, 10), std::exp(-0.5) / (sum * sum), 1e-6);
    EXPECT_NEAR(s->heightAt(12, 11), std::exp(-2.0) * std::exp(-0.5) / (sum * sum), 1e-6);
    EXPECT_EQ(s->heightAt(14, 10), 0.0f);                       // beyond 3σ
    EXPECT_EQ(s->stateAt(20, 5), PixelState::Empty);            // the states are kept
    EXPECT_EQ(s->count(PixelState::Measured), f.count(PixelState::Measured));

    // A level field beside an empty region stays level to its edge (no height pulled from the empty pixels).
    auto level = HeightField::create(30, 10, 0.001).value();
    for (int r = 0; r < 10; ++r)
        for (int c = 0; c < 15; ++c) level.setMeasured(c, r, 0.25f);
    auto smoothed = smoothHeights(level, 0.002);
    ASSERT_TRUE(smoothed.ok());
    for (int r = 0; r < 10; ++r)
        for (int c = 0; c < 15; ++c) EXPECT_NEAR(smoothed->heightAt(c, r), 0.25f, 1e-6f) << c << "," << r;

    EXPECT_EQ(smoothHeights(f, 0.0)->heights()[f.index(10, 10)], 1.0f); // 0: a copy
    EXPECT_EQ(smoothHeights(f, -0.001).error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(smoothHeights(f, 0.017).error().code, ErrorCode::InvalidArgument); // 17 pixels
    EXPECT_EQ(smoothHeights(f, std::nan("")).error().code, ErrorCode::InvalidArgument);
}

/** Mean and standard deviation of @p image over the columns where @p keep holds (rows 20 to h-20). */
std::pair<double, double> stats(const ShadedImage& image, auto keep)
{
    double sum = 0, sum2 = 0;
    std::size_t n = 0;
    for (int r = 20; r < image.height - 20; ++r)
        for (int c = 0; c < image.width; ++c)
            if (keep(c)) {
                const double v = image.value(c, r);
                sum += v, sum2 += v * v, ++n;
            }
    const double mean = sum / double(n);
    return {mean, std::sqrt(std::max(0.0, sum2 / double(n) - mean * mean))};
}

TEST(HeightNoiseTest, TheDefaultSkydomeReadsFlatTopsEvenlyAndKeepsTheGroovesDark)
{
    // Half-millimetre pixels, 0.25 mm of noise, grooves 8 mm deep every 60 mm: the drum of the issue, in small.
    const int period = 120;
    const HeightField f = fluted(720, 200, 0.0005, 0.008, period, 0.00025);
    const auto top = [&](int c) { // the middle of each flat top, away from the grooves' edges
        const double phase = 2.0 * std::numbers::pi * c / period;
        return std::cos(phase) > 0.95 && c > 20 && c < 700;
    };
    const auto bottom = [&](int c) { return std::cos(2.0 * std::numbers::pi * c / period) < -0.95 && c > 20 && c < 700; };

    developpee::DeveloppeeOptions options;
    options.smoothing = 0.0;
    developpee::ShadingReport report;
    auto raw = developpee::shadeField(f, options, nullptr, &report);
    ASSERT_TRUE(raw.ok());
    EXPECT_EQ(report.smoothing, 0.0);
    options.smoothing.reset();
    auto smoothed = developpee::shadeField(f, options, nullptr, &report);
    ASSERT_TRUE(smoothed.ok());
    EXPECT_NEAR(report.heightNoise, 0.00025, 0.0000125);
    EXPECT_DOUBLE_EQ(report.smoothing, noiseSmoothingSigma(report.heightNoise, 0.0005));

    const auto [rawTop, rawTopStd] = stats(*raw, top);
    const auto [smoothTop, smoothTopStd] = stats(*smoothed, top);
    const auto [smoothBottom, smoothBottomStd] = stats(*smoothed, bottom);
    EXPECT_GT(rawTopStd, 0.1);        // salt and pepper
    EXPECT_LT(smoothTopStd, 0.03);    // even
    EXPECT_GT(smoothTop - smoothBottom, 0.1); // the grooves stay darker
    (void)rawTop;
    (void)smoothBottomStd;
}

} // namespace
} // namespace stylos::core::shading
