// referenceAmbientOcclusion: tiny configurations whose values are counted here independently of the
// DDA (closed-form ray–box tests over the same direction set): a lone cell, a roof, a hole in the roof,
// occluders at or below the bias, a wall beside a floor cell; threads, errors, cancel.
#include "stylos/core/ao/ReferenceAo.h"

#include "stylos/core/ao/Directions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

using namespace stylos::core;
using namespace stylos::core::ao;

namespace {

using Coords = std::array<std::uint32_t, 3>;

/** Cells at level 10 with the given coordinates, all with normal @p normal, opaque, one leaf each. */
AoCells cellsOf(const std::vector<Coords>& coords, std::array<float, 3> normal = {0, 0, 1})
{
    AoCells cells;
    cells.level = 10;
    cells.coords = coords;
    cells.normals.assign(coords.size(), normal);
    cells.opacity.assign(coords.size(), 1.0f);
    cells.leafBegin.resize(coords.size() + 1);
    std::iota(cells.leafBegin.begin(), cells.leafBegin.end(), 0);
    return cells;
}

AoOptions optionsWith(int directions, double bias = 1.0, bool cosine = false)
{
    AoOptions o;
    o.directions = directions;
    o.bias = bias;
    o.cosineWeighted = cosine;
    o.threads = 2;
    return o;
}

std::vector<float> reference(const AoCells& cells, std::vector<std::size_t> samples, const AoOptions& options)
{
    auto result = referenceAmbientOcclusion(cells, samples, options);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().message);
    return result.ok() ? result.value() : std::vector<float>(samples.size(), -1.0f);
}

/** Whether the ray p + t d, t > 0, passes through the interior of the box [lo, hi]. */
bool crossesBox(const std::array<double, 3>& p, const Direction& d, const std::array<double, 3>& lo,
                const std::array<double, 3>& hi)
{
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (p[a] <= lo[a] || p[a] >= hi[a]) return false;
            continue;
        }
        const double ta = (lo[a] - p[a]) / d[a], tb = (hi[a] - p[a]) / d[a];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
    }
    return t0 < t1;
}

/** Σ w·[escapes] / Σ w over the directions in front of @p n (n·d in float, as the reference), w = 1 or n·d. */
template <typename Blocked>
double expectedValue(int directions, std::array<float, 3> n, bool cosine, Blocked blocked)
{
    double seen = 0.0, total = 0.0;
    for (const Direction& d : fibonacciDirections(directions, false)) {
        const float nd = n[0] * float(d[0]) + n[1] * float(d[1]) + n[2] * float(d[2]);
        if (!(nd > 0.0f)) continue;
        const double w = cosine ? double(nd) : 1.0;
        total += w;
        if (!blocked(d)) seen += w;
    }
    return seen / total;
}

template <typename Blocked>
double expectedUp(int directions, bool cosine, Blocked blocked)
{
    return expectedValue(directions, {0, 0, 1}, cosine, blocked);
}

} // namespace

TEST(ReferenceAo, LoneCellSeesTheWholeSky)
{
    const AoCells cells = cellsOf({{4, 7, 9}}, {0.6f, 0.0f, 0.8f});
    EXPECT_EQ(reference(cells, {0}, optionsWith(64)), std::vector<float>{1.0f});
    EXPECT_EQ(reference(cells, {0}, optionsWith(64, 1.0, true)), std::vector<float>{1.0f});
}

TEST(ReferenceAo, CellUnderARoofSeesOnlyPastItsEdges)
{
    // Floor cell (5, 5, 0), roof z = 3 over x, y in 0..10: a ray is blocked iff it enters the roof slab
    // [0, 11]² × [3, 4] (3 edges above the tangent plane > bias 1).
    std::vector<Coords> coords{{5, 5, 0}};
    for (std::uint32_t x = 0; x <= 10; ++x)
        for (std::uint32_t y = 0; y <= 10; ++y) coords.push_back({x, y, 3});
    const AoCells cells = cellsOf(coords);
    const std::array<double, 3> p{5.5, 5.5, 0.5};
    const auto blocked = [&](const Direction& d) { return crossesBox(p, d, {0, 0, 3}, {11, 11, 4}); };
    for (const bool cosine : {false, true}) {
        const double expected = expectedUp(256, cosine, blocked);
        EXPECT_GT(expected, 0.02);
        EXPECT_LT(expected, 0.5);
        EXPECT_NEAR(reference(cells, {0}, optionsWith(256, 1.0, cosine))[0], expected, 1e-6) << cosine;
    }
    // Roof cells see the sky above them, and the floor cell's half below... all of it from above.
    EXPECT_EQ(reference(cells, {1 + 5 * 11 + 5}, optionsWith(256))[0], 1.0f);
}

TEST(ReferenceAo, HoleInTheRoofLetsThroughOnlyWhatCrossesItWhole)
{
    // The roof of the previous test without cell (5, 5, 3): a ray escapes through the hole only if it
    // crosses the whole slab inside the hole's column (else it enters a roof cell through the side) —
    // or passes beyond the roof's edge.
    std::vector<Coords> coords{{5, 5, 0}};
    for (std::uint32_t x = 0; x <= 10; ++x)
        for (std::uint32_t y = 0; y <= 10; ++y)
            if (x != 5 || y != 5) coords.push_back({x, y, 3});
    const AoCells cells = cellsOf(coords);
    const std::array<double, 3> p{5.5, 5.5, 0.5};
    const auto throughHole = [&](const Direction& d) {
        const double t3 = 2.5 / d[2], t4 = 3.5 / d[2];
        const auto inside = [&](double t) {
            const double x = p[0] + t * d[0], y = p[1] + t * d[1];
            return x > 5 && x < 6 && y > 5 && y < 6;
        };
        return inside(t3) && inside(t4);
    };
    const auto blocked = [&](const Direction& d) {
        return crossesBox(p, d, {0, 0, 3}, {11, 11, 4}) && !throughHole(d);
    };
    int holeRays = 0;
    for (const Direction& d : fibonacciDirections(1024, false))
        if (d[2] > 0 && throughHole(d)) ++holeRays;
    ASSERT_GT(holeRays, 3);
    const double roofOnly = expectedUp(1024, false, [&](const Direction& d) {
        return crossesBox(p, d, {0, 0, 3}, {11, 11, 4});
    });
    const double expected = expectedUp(1024, false, blocked);
    EXPECT_NEAR(expected - roofOnly, holeRays / 512.0, 1e-9); // 512 of the 1024 directions face up
    EXPECT_NEAR(reference(cells, {0}, optionsWith(1024))[0], expected, 1e-6);
}

TEST(ReferenceAo, OccludersAtOrBelowTheBiasDoNotCount)
{
    // A floor cell ringed by cells one edge up (exactly the bias) and by floor cells (0 above): with
    // bias 1 nothing occludes; a bias just below 1 lets the ring shadow the grazing directions.
    std::vector<Coords> coords{{5, 5, 0}};
    for (std::uint32_t x = 3; x <= 7; ++x)
        for (std::uint32_t y = 3; y <= 7; ++y)
            if (x != 5 || y != 5) coords.push_back({x, y, std::max(x, y) == 7 || std::min(x, y) == 3 ? 1u : 0u});
    const AoCells cells = cellsOf(coords);
    EXPECT_EQ(reference(cells, {0}, optionsWith(256, 1.0))[0], 1.0f);
    const float lower = reference(cells, {0}, optionsWith(256, 0.99))[0];
    // Along the ray from (5.5, 5.5, 0.5), the Chebyshev distance from the column's axis is t·m,
    // m = max(|dx|, |dy|); the ring (distance 1.5..2.5, height 1..2, t in 0.5/dz..1.5/dz) is crossed
    // iff 1 < m/dz < 5.
    const double expected = expectedUp(256, false, [&](const Direction& d) {
        const double m = std::max(std::fabs(d[0]), std::fabs(d[1])) / d[2];
        return m > 1.0 && m < 5.0;
    });
    EXPECT_LT(lower, 0.9f);
    EXPECT_NEAR(lower, expected, 1e-6);
}

TEST(ReferenceAo, WallBesideAFloorCellHidesTheDirectionsThatReachItAboveTheBias)
{
    // Floor cell (10, 10, 0), normal +z; wall x = 12, y and z in 0..20. Wall cells at z ≥ 2 lie more
    // than 1 edge above the floor's plane: a ray is blocked iff it passes through [12, 13] × [0, 21] × [2, 21].
    std::vector<Coords> coords{{10, 10, 0}};
    for (std::uint32_t y = 0; y <= 20; ++y)
        for (std::uint32_t z = 0; z <= 20; ++z) coords.push_back({12, y, z});
    const AoCells cells = cellsOf(coords);
    const std::array<double, 3> p{10.5, 10.5, 0.5};
    const auto blocked = [&](const Direction& d) { return crossesBox(p, d, {12, 0, 2}, {13, 21, 21}); };
    for (const bool cosine : {false, true}) {
        const double expected = expectedUp(512, cosine, blocked);
        int count = 0;
        for (const Direction& d : fibonacciDirections(512, false)) count += d[2] > 0 && blocked(d);
        EXPECT_GT(count, 40);                        // about a quarter of the up directions
        EXPECT_NEAR(reference(cells, {0}, optionsWith(512, 1.0, cosine))[0], expected, 1e-6) << cosine;
    }
    // A top wall cell facing the floor cell (normal −x): the other wall cells lie in its plane (0 above);
    // only the floor cell, 2 edges in front of it, can hide a direction: the box [10, 11]² × [0, 1].
    AoCells facing = cells;
    for (std::size_t i = 1; i < facing.size(); ++i) facing.normals[i] = {-1, 0, 0};
    const std::size_t top = 1 + 10 * 21 + 20;
    ASSERT_EQ(facing.coords[top], (Coords{12, 10, 20}));
    const double expectedTop = expectedValue(4096, {-1, 0, 0}, false, [&](const Direction& d) {
        return crossesBox({12.5, 10.5, 20.5}, d, {10, 10, 0}, {11, 11, 1});
    });
    EXPECT_NEAR(reference(facing, {top}, optionsWith(4096))[0], expectedTop, 1e-6);
}

TEST(ReferenceAo, SameValuesWithAnyThreadCountAndInSampleOrder)
{
    std::vector<Coords> coords{{5, 5, 0}};
    for (std::uint32_t x = 0; x <= 10; ++x)
        for (std::uint32_t y = 0; y <= 10; ++y) coords.push_back({x, y, 3});
    const AoCells cells = cellsOf(coords);
    std::vector<std::size_t> samples(cells.size());
    std::iota(samples.begin(), samples.end(), 0);
    std::reverse(samples.begin(), samples.end());
    AoOptions one = optionsWith(128);
    one.threads = 1;
    AoOptions three = optionsWith(128);
    three.threads = 3;
    const auto a = reference(cells, samples, one);
    EXPECT_EQ(a, reference(cells, samples, three));
    EXPECT_EQ(a.back(), reference(cells, {0}, one)[0]);
    EXPECT_LT(a.back(), 0.5f);
}

TEST(ReferenceAo, RefusesBadArgumentsAndStopsOnCancel)
{
    const AoCells cells = cellsOf({{1, 1, 1}, {2, 2, 2}});
    const std::vector<std::size_t> samples{0, 1};
    auto bad = referenceAmbientOcclusion(cells, samples, optionsWith(0));
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::InvalidArgument);
    bad = referenceAmbientOcclusion(cells, samples, optionsWith(16, -0.5));
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::InvalidArgument);
    const std::vector<std::size_t> outside{0, 2};
    bad = referenceAmbientOcclusion(cells, outside, optionsWith(16));
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::InvalidArgument);

    SilentProgress cancelled;
    cancelled.cancel();
    const auto stopped = referenceAmbientOcclusion(cells, samples, optionsWith(16), &cancelled);
    ASSERT_FALSE(stopped.ok());
    EXPECT_EQ(stopped.error().code, ErrorCode::Cancelled);

    SilentProgress progress;
    const auto done = referenceAmbientOcclusion(cells, samples, optionsWith(16), &progress);
    ASSERT_TRUE(done.ok());
    EXPECT_EQ(progress.last(), 1.0);
}
