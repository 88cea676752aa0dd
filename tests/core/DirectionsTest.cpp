// The skydome's direction sets (Directions.h): count, unit length, hemisphere, equal spread.
#include "stylos/core/ao/Directions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace stylos::core::ao;

namespace {

double dot(const Direction& a, const Direction& b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/** Angle to the nearest other direction of the set, for each direction (radians). */
std::vector<double> nearestAngles(const std::vector<Direction>& set)
{
    std::vector<double> out;
    for (std::size_t i = 0; i < set.size(); ++i) {
        double best = -1.0;
        for (std::size_t j = 0; j < set.size(); ++j)
            if (j != i) best = std::max(best, dot(set[i], set[j]));
        out.push_back(std::acos(std::min(1.0, best)));
    }
    return out;
}

} // namespace

TEST(Directions, CountIsTheOneAskedAndClampedTo1Through65536)
{
    for (int n : {1, 16, 255, 256, 4096}) {
        EXPECT_EQ(fibonacciDirections(n, false).size(), std::size_t(n));
        EXPECT_EQ(fibonacciDirections(n, true).size(), std::size_t(n));
    }
    EXPECT_EQ(fibonacciDirections(0, false).size(), 1u);
    EXPECT_EQ(fibonacciDirections(-5, true).size(), 1u);
    EXPECT_EQ(fibonacciDirections(70000, false).size(), 65536u);
}

TEST(Directions, AreUnitVectorsAndDeterministic)
{
    for (bool upper : {false, true}) {
        const auto set = fibonacciDirections(4096, upper);
        for (const auto& d : set)
            EXPECT_NEAR(std::sqrt(dot(d, d)), 1.0, 1e-15);
        EXPECT_EQ(set, fibonacciDirections(4096, upper));
    }
}

TEST(Directions, FirstPointsFollowTheSpiralFormula)
{
    // Sphere, D = 4: z_0 = 1 − 1/4, φ_0 = 0; z_1 = 1 − 3/4, φ_1 = π (3 − √5).
    const auto s = fibonacciDirections(4, false);
    EXPECT_NEAR(s[0][0], std::sqrt(1.0 - 0.75 * 0.75), 1e-15);
    EXPECT_EQ(s[0][1], 0.0);
    EXPECT_EQ(s[0][2], 0.75);
    const double phi = std::numbers::pi * (3.0 - std::sqrt(5.0));
    EXPECT_NEAR(s[1][0], std::sqrt(1.0 - 0.0625) * std::cos(phi), 1e-15);
    EXPECT_NEAR(s[1][1], std::sqrt(1.0 - 0.0625) * std::sin(phi), 1e-15);
    EXPECT_EQ(s[1][2], 0.25);
    // Hemisphere, D = 2: z = 1 − ½/2, 1 − 1.5/2.
    const auto h = fibonacciDirections(2, true);
    EXPECT_EQ(h[0][2], 0.75);
    EXPECT_EQ(h[1][2], 0.25);
}

TEST(Directions, UpperHemisphereHasOnlyDirectionsAboveTheHorizon)
{
    for (int n : {1, 7, 256, 4096}) {
        const auto set = fibonacciDirections(n, true);
        for (const auto& d : set)
            EXPECT_GT(d[2], 0.0);
    }
    // The whole sphere: exactly half of its directions below the horizon.
    const auto sphere = fibonacciDirections(256, false);
    EXPECT_EQ(std::count_if(sphere.begin(), sphere.end(), [](const Direction& d) { return d[2] < 0.0; }), 128);
}

TEST(Directions, EqualAreaBands)
{
    // The cap z > ½ is a quarter of the sphere (2π(1 − ½) / 4π): exactly 64 of 256 points; on the
    // hemisphere it is half of the 2π: 128 of 256.
    const auto sphere = fibonacciDirections(256, false);
    EXPECT_EQ(std::count_if(sphere.begin(), sphere.end(), [](const Direction& d) { return d[2] > 0.5; }), 64);
    const auto half = fibonacciDirections(256, true);
    EXPECT_EQ(std::count_if(half.begin(), half.end(), [](const Direction& d) { return d[2] > 0.5; }), 128);
}

TEST(Directions, MeanIsTheCentroidOfTheUniformDistribution)
{
    // Uniform on the sphere: mean 0; on the upper hemisphere: (0, 0, ½).
    for (int n : {256, 1000}) {
        for (bool upper : {false, true}) {
            Direction mean{0, 0, 0};
            for (const auto& d : fibonacciDirections(n, upper))
                for (int a = 0; a < 3; ++a)
                    mean[a] += d[a] / n;
            EXPECT_NEAR(mean[0], 0.0, 0.003) << n;
            EXPECT_NEAR(mean[1], 0.0, 0.003) << n;
            EXPECT_NEAR(mean[2], upper ? 0.5 : 0.0, 1e-12) << n;
        }
    }
}

TEST(Directions, NearestNeighbourAnglesAreCloseToTheIdealSpacing)
{
    // Ideal: a hexagonal packing of D points over the area A (4π or 2π) has spacing √(2A / (√3 D)).
    // The spiral keeps every point's nearest neighbour within 0.8–0.95 of it (no clumps, no gaps).
    for (int n : {16, 256, 1024}) {
        for (bool upper : {false, true}) {
            const double area = (upper ? 2.0 : 4.0) * std::numbers::pi;
            const double ideal = std::sqrt(2.0 * area / (std::sqrt(3.0) * n));
            const auto angles = nearestAngles(fibonacciDirections(n, upper));
            const auto [lo, hi] = std::minmax_element(angles.begin(), angles.end());
            EXPECT_GT(*lo / ideal, 0.75) << n << (upper ? " hemisphere" : " sphere");
            EXPECT_LT(*hi / ideal, 1.0) << n << (upper ? " hemisphere" : " sphere");
        }
    }
}
