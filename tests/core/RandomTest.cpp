// Random: the generators' portable random numbers.
#include "stylos/core/synth/Random.h"

#include <gtest/gtest.h>

#include <cmath>

using stylos::core::synth::Random;

TEST(SynthRandom, EngineIsTheStandardMersenneTwister)
{
    Random random(5489); // the standard fixes the 10000th output for the default seed
    std::uint64_t value = 0;
    for (int i = 0; i < 10000; ++i) value = random.bits();
    EXPECT_EQ(value, 9981545732273789042ull);
}

TEST(SynthRandom, SameSeedSameNumbers)
{
    Random a(42), b(42), c(43);
    bool differs = false;
    for (int i = 0; i < 1000; ++i) {
        const double x = a.normal();
        EXPECT_EQ(x, b.normal());
        differs = differs || x != c.normal();
    }
    EXPECT_TRUE(differs);
    EXPECT_NE(Random::derive(1, 0), Random::derive(1, 1));
    EXPECT_NE(Random::derive(1, 0), Random::derive(2, 0));
    EXPECT_EQ(Random::derive(9, 3), Random::derive(9, 3));
}

TEST(SynthRandom, UniformAndNormalHaveTheirMoments)
{
    Random random(7);
    const int n = 200000;
    double sum = 0.0, sum2 = 0.0, usum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double u = random.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        usum += u;
        const double x = random.normal();
        sum += x;
        sum2 += x * x;
    }
    EXPECT_NEAR(usum / n, 0.5, 0.005);
    EXPECT_NEAR(sum / n, 0.0, 0.01);
    EXPECT_NEAR(sum2 / n, 1.0, 0.02);
    for (int i = 0; i < 1000; ++i) {
        const double u = random.uniform(-2.0, 3.0);
        ASSERT_GE(u, -2.0);
        ASSERT_LT(u, 3.0);
    }
}

TEST(SynthRandom, RotationsAndDirectionsAreProper)
{
    Random random(3);
    for (int i = 0; i < 100; ++i) {
        const Eigen::Matrix3d r = random.rotation();
        EXPECT_TRUE((r.transpose() * r).isIdentity(1e-12));
        EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
        EXPECT_NEAR(random.unitVector().norm(), 1.0, 1e-12);
    }
}
