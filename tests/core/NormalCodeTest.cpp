// NormalCode.h (suite NormalCode): round trips of every code, exact axes and diagonals, error bounds over
// 1 M random unit vectors, and the defined codes of zero and non-finite input.
// The error table: stylos_core_tests --gtest_filter='NormalCode.ErrorTable'
#include "stylos/core/octree/NormalCode.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

using namespace stylos::core::octree;

namespace {

constexpr double degree = 3.14159265358979323846 / 180;
constexpr auto paper = NormalCodeKind::Paper15;
constexpr auto octahedral = NormalCodeKind::Octahedral16;

double angleBetween(const std::array<float, 3>& a, const std::array<double, 3>& b)
{
    const double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
    return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

double length(const std::array<float, 3>& v)
{
    return std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
}

/** The 6 axes and 8 octant diagonals, unit length. */
std::vector<std::array<double, 3>> specialDirections()
{
    std::vector<std::array<double, 3>> result;
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {1.0, -1.0}) {
            std::array<double, 3> v{0, 0, 0};
            v[axis] = sign;
            result.push_back(v);
        }
    const double d = 1 / std::sqrt(3.0);
    for (int octant = 0; octant < 8; ++octant)
        result.push_back({octant & 1 ? -d : d, octant & 2 ? -d : d, octant & 4 ? -d : d});
    return result;
}

std::array<float, 3> roundTrip(NormalCodeKind kind, const std::array<double, 3>& v)
{
    return decodeNormal(kind, encodeNormal(kind, float(v[0]), float(v[1]), float(v[2])));
}

} // namespace

TEST(NormalCode, OctahedralAxesAndDiagonalsAreExact)
{
    for (const auto& v : specialDirections()) {
        const auto d = roundTrip(octahedral, v);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(d[i], v[i], 1e-6) << v[0] << ' ' << v[1] << ' ' << v[2];
    }
}

TEST(NormalCode, PaperAxesAndDiagonalsWithinCellBound)
{
    // Axes fall in a corner cell: centroid (1/192, 1/192, 190/192) → sqrt(2)/190 rad ≈ 0.43°.
    for (const auto& v : specialDirections()) {
        const auto d = roundTrip(paper, v);
        EXPECT_LT(angleBetween(d, v), 0.9 * degree);
        for (int i = 0; i < 3; ++i)
            if (v[i] != 0) {
                EXPECT_EQ(d[i] < 0, v[i] < 0);
            }
    }
    EXPECT_NEAR(angleBetween(roundTrip(paper, {0, 0, 1}), {0, 0, 1}), std::atan(std::sqrt(2.0) / 190), 1e-6);
}

TEST(NormalCode, EveryPaperCodeDecodesInItsOctantAndReencodesToItself)
{
    const auto* table = normalDecodeTable(paper);
    for (unsigned code = 0; code < (1u << 15); ++code) {
        const auto d = decodeNormal(paper, static_cast<std::uint16_t>(code));
        ASSERT_NEAR(length(d), 1.0, 1e-6) << code;
        const unsigned octant = code >> 12;
        for (int i = 0; i < 3; ++i) {
            ASSERT_NE(d[i], 0.0f) << code; // strictly inside its octant
            ASSERT_EQ(d[i] < 0, ((octant >> i) & 1u) != 0) << code;
            ASSERT_EQ(table[code][i], d[i]) << code;
        }
        ASSERT_EQ(encodeNormal(paper, d[0], d[1], d[2]), code);
    }
    // Bit 15 is ignored on decode.
    EXPECT_EQ(decodeNormal(paper, 0x8123), decodeNormal(paper, 0x0123));
}

TEST(NormalCode, OctahedralDecodeEncodeIsIdempotentOnEveryCode)
{
    const auto* table = normalDecodeTable(octahedral);
    for (unsigned code = 0; code < (1u << 16); ++code) {
        const auto d = decodeNormal(octahedral, static_cast<std::uint16_t>(code));
        ASSERT_NEAR(length(d), 1.0, 1e-6) << code;
        for (int i = 0; i < 3; ++i) ASSERT_EQ(table[code][i], d[i]) << code;
        const std::uint16_t again = encodeNormal(octahedral, d[0], d[1], d[2]);
        const auto d2 = decodeNormal(octahedral, again);
        for (int i = 0; i < 3; ++i) ASSERT_NEAR(d2[i], d[i], 1e-6) << code;
        // Codes strictly inside the map and off the folding seam (z = 0) come back unchanged. The
        // square's border has twins ((−1, v) and (−1, −v) are one vector; the 4 corners are all −Z);
        // bytes above 252 never come out.
        const unsigned ku = code >> 8, kv = code & 0xFF;
        ASSERT_LE(again >> 8, 252u);
        ASSERT_LE(again & 0xFFu, 252u);
        if (ku > 0 && ku < 252 && kv > 0 && kv < 252 && std::abs(d[2]) > 1e-6f) {
            ASSERT_EQ(again, code);
        }
    }
}

TEST(NormalCode, ZeroAndNonFiniteInputGivePlusZ)
{
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (auto kind : {paper, octahedral}) {
        const std::uint16_t plusZ = encodeNormal(kind, 0, 0, 1);
        EXPECT_EQ(encodeNormal(kind, 0, 0, 0), plusZ);
        EXPECT_EQ(encodeNormal(kind, -0.0f, -0.0f, -0.0f), plusZ);
        EXPECT_EQ(encodeNormal(kind, nan, 0, 0), plusZ);
        EXPECT_EQ(encodeNormal(kind, 1, inf, 0), plusZ);
        EXPECT_EQ(encodeNormal(kind, 0, 0, -inf), plusZ);
        EXPECT_GT(decodeNormal(kind, plusZ)[2], 0.9999f);
    }
}

TEST(NormalCode, LengthDoesNotMatter)
{
    std::mt19937_64 random(7);
    std::normal_distribution<float> gauss;
    for (int i = 0; i < 1000; ++i) {
        const float x = gauss(random), y = gauss(random), z = gauss(random);
        for (auto kind : {paper, octahedral}) {
            const std::uint16_t code = encodeNormal(kind, x, y, z);
            EXPECT_EQ(encodeNormal(kind, x * 1e-30f, y * 1e-30f, z * 1e-30f), code);
            EXPECT_EQ(encodeNormal(kind, x * 1e30f, y * 1e30f, z * 1e30f), code);
        }
    }
}

TEST(NormalCode, ErrorBoundsOverOneMillionRandomVectors)
{
    // Measured (seed 1): Paper15 mean 0.4736°, max 1.2568°; Octahedral16 mean 0.3173°, max 0.6387°.
    const auto p = measureNormalCodeError(paper, 1'000'000, 1);
    EXPECT_LT(p.meanRadians, 0.48 * degree);
    EXPECT_LT(p.maxRadians, 1.30 * degree);
    const auto o = measureNormalCodeError(octahedral, 1'000'000, 1);
    EXPECT_LT(o.meanRadians, 0.32 * degree);
    EXPECT_LT(o.maxRadians, 0.65 * degree);
    EXPECT_LT(o.meanRadians, p.meanRadians);
    EXPECT_LT(o.maxRadians, p.maxRadians);
    // Deterministic.
    const auto again = measureNormalCodeError(paper, 1000, 1);
    EXPECT_EQ(again.maxRadians, measureNormalCodeError(paper, 1000, 1).maxRadians);
    EXPECT_EQ(measureNormalCodeError(paper, 0, 1).maxRadians, 0.0);
}

TEST(NormalCode, ErrorTable)
{
    // The precise Octahedral16 encoding against plain rounding, same vectors (std::normal_distribution).
    std::mt19937_64 random(1);
    std::normal_distribution<double> gauss;
    double roundedMax = 0, roundedSum = 0, preciseMax = 0, preciseSum = 0;
    constexpr int samples = 1'000'000;
    for (int i = 0; i < samples; ++i) {
        std::array<double, 3> v{gauss(random), gauss(random), gauss(random)};
        const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (double& c : v) c /= n;
        const float x = float(v[0]), y = float(v[1]), z = float(v[2]);
        const double rounded = angleBetween(decodeNormal(octahedral, encodeOctahedral16Rounded(x, y, z)), v);
        const double precise = angleBetween(decodeNormal(octahedral, encodeNormal(octahedral, x, y, z)), v);
        ASSERT_LE(precise, rounded + 1e-7);
        roundedSum += rounded, preciseSum += precise;
        roundedMax = std::max(roundedMax, rounded), preciseMax = std::max(preciseMax, precise);
    }
    EXPECT_LT(preciseMax, roundedMax);
    std::printf("code                  bits  mean (deg)  max (deg)   [1 M random unit vectors, seed 1]\n");
    for (auto kind : {paper, octahedral}) {
        const auto e = measureNormalCodeError(kind, samples, 1);
        std::printf("%-20s  %4d  %10.4f  %9.4f\n", kind == paper ? "Paper15" : "Octahedral16 precise",
                    kind == paper ? 15 : 16, e.meanRadians / degree, e.maxRadians / degree);
    }
    std::printf("%-20s  %4d  %10.4f  %9.4f   [std::normal_distribution vectors]\n", "Octahedral16 rounded", 16,
                roundedSum / samples / degree, roundedMax / degree);
    std::printf("%-20s  %4d  %10.4f  %9.4f   [same vectors]\n", "Octahedral16 precise", 16,
                preciseSum / samples / degree, preciseMax / degree);
}
