// FractalNoise: deterministic, bounded, continuous.
#include "stylos/core/synth/FractalNoise.h"

#include <gtest/gtest.h>

#include <cmath>

using stylos::core::synth::FractalNoise;

TEST(SynthFractalNoise, BoundedDeterministicAndSeeded)
{
    const FractalNoise a(1, 0.05, 0.004, 5), b(1, 0.05, 0.004, 5), c(2, 0.05, 0.004, 5);
    EXPECT_DOUBLE_EQ(a.bound(), 0.004 * (1 + 0.5 + 0.25 + 0.125 + 0.0625));
    double largest = 0.0, sum = 0.0;
    int differs = 0;
    const int n = 200;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double x = -0.7 + i * 0.0071, y = -0.3 + j * 0.0053;
            const double v = a.value(x, y);
            ASSERT_EQ(v, b.value(x, y));
            ASSERT_LE(std::fabs(v), a.bound());
            largest = std::max(largest, std::fabs(v));
            sum += v;
            differs += v != c.value(x, y);
        }
    EXPECT_GT(largest, 0.3 * a.bound()); // not flat
    EXPECT_LT(std::fabs(sum / (n * n)), 0.25 * a.bound());
    EXPECT_GT(differs, n * n / 2);
}

TEST(SynthFractalNoise, Continuous)
{
    const FractalNoise noise(5, 0.02, 0.001, 4);
    for (int i = 0; i < 1000; ++i) {
        const double x = 0.013 * i - 3.0, y = 0.7 - 0.011 * i;
        // Smooth-step interpolation: a step of 1 µm moves the value by far less than its amplitude.
        EXPECT_LT(std::fabs(noise.value(x + 1e-6, y) - noise.value(x, y)), 1e-6);
        EXPECT_LT(std::fabs(noise.value(x, y + 1e-6) - noise.value(x, y)), 1e-6);
    }
}
