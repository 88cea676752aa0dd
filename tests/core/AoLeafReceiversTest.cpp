// The 3D skydome measured at receivers off the cells' lattice (leaves, each with its own position and
// normal) against the cells as occluders (AmbientOcclusion.h, AoCells.h's AoReceivers).
#include "PoctTestSupport.h"
#include "ReferenceOctree.h"
#include "stylos/core/ao/AmbientOcclusion.h"
#include "stylos/core/ao/AoCells.h"
#include "stylos/core/ao/Directions.h"
#include "stylos/core/ao/SkydomeLayer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace stylos::core;
using namespace stylos::core::ao;

namespace {

using Vec = std::array<double, 3>;

AoOptions depthMap(double bias)
{
    AoOptions o;
    o.method = AoMethod::DepthMap;
    o.directions = 256;
    o.bias = bias;
    o.receiverBias = bias;
    o.threads = 2;
    o.twoSided = false; // open sheets of cells: their back sees the whole sky (see the two-sided tests)
    return o;
}

void addCell(AoCells& cells, unsigned x, unsigned y, unsigned z, const Vec& n)
{
    cells.coords.push_back({x, y, z});
    cells.normals.push_back({float(n[0]), float(n[1]), float(n[2])});
    cells.opacity.push_back(1.0f);
    if (cells.leafBegin.empty()) cells.leafBegin.push_back(0);
    cells.leafBegin.push_back(cells.coords.size());
}

} // namespace

TEST(AoLeafReceivers, OpenTiltedPlaneReadsExactlyOneWhereCellCentresShadowThemselves)
{
    // Every cell of a 48³ grid that the plane n·x = c cuts, n = (1, 2, 3)/√14: their centres lie up to
    // ½(|nx| + |ny| + |nz|) = 0.80 edge on either side of it, so seen from a centre the cells of the same
    // plane reach 1.6 edges above its tangent plane, past the cells' default bias of 1.
    const double len = std::sqrt(14.0);
    const Vec n{1 / len, 2 / len, 3 / len};
    const double reach = 0.5 * (n[0] + n[1] + n[2]);
    const double c = 24.0 * (n[0] + n[1] + n[2]);
    AoCells cells;
    for (unsigned z = 0; z < 48; ++z)
        for (unsigned y = 0; y < 48; ++y)
            for (unsigned x = 0; x < 48; ++x) {
                const double h = (x + 0.5) * n[0] + (y + 0.5) * n[1] + (z + 0.5) * n[2] - c;
                if (std::fabs(h) < reach - 1e-4) addCell(cells, x, y, z, n);
            }
    ASSERT_GT(cells.size(), 2000u);
    // Receivers on the plane, in its middle (where all their directions pass over the plane's cells).
    AoReceivers receivers;
    std::mt19937_64 random(4);
    std::uniform_real_distribution<double> unit(14.0, 34.0);
    while (receivers.size() < 500) {
        const double x = unit(random), y = unit(random);
        const double z = (c - x * n[0] - y * n[1]) / n[2];
        if (z < 14.0 || z > 34.0) continue;
        receivers.positions.push_back({float(x), float(y), float(z)});
        receivers.normals.push_back({float(n[0]), float(n[1]), float(n[2])});
    }
    auto atLeaves = computeAmbientOcclusion(cells, receivers, depthMap(0.0));
    ASSERT_TRUE(atLeaves);
    EXPECT_EQ(std::count(atLeaves->begin(), atLeaves->end(), 1.0f), 500);
    // The cells' own rule, at their centres with the bias of 1 edge, shadows some of them.
    auto atCells = computeAmbientOcclusion(cells, depthMap(1.0));
    ASSERT_TRUE(atCells);
    EXPECT_LT(*std::min_element(atCells->begin(), atCells->end()), 0.95f);
}

TEST(AoLeafReceivers, TrenchBottomReadsTheDirectionsBetweenItsWalls)
{
    // A floor (z ∈ [0, 1]) and two walls 10 high, 2 thick, 200 long, 20 apart; a receiver on the floor's
    // surface in the middle of the trench. A direction is free when the ray misses both wall boxes
    // (slab test, exact); the depth map sees the line through a pixel centre (up to 0.71 edge away) and
    // ignores the wall's bottom row, which touches the receiver's plane: grazing directions may differ.
    AoCells cells;
    for (unsigned y = 0; y < 200; ++y)
        for (unsigned x = 0; x < 60; ++x) {
            addCell(cells, x, y, 0, {0, 0, 1});
            const bool left = x >= 18 && x < 20, right = x >= 40 && x < 42;
            if (left || right)
                for (unsigned z = 1; z < 11; ++z) addCell(cells, x, y, z, {left ? 1.0 : -1.0, 0, 0});
        }
    const Vec p{30.0, 100.0, 1.0};
    const auto hitsBox = [&](const Vec& d, const Vec& lo, const Vec& hi) {
        double t0 = 1e-9, t1 = 1e30;
        for (int a = 0; a < 3; ++a) {
            if (std::fabs(d[a]) < 1e-15) {
                if (p[a] < lo[a] || p[a] > hi[a]) return false;
                continue;
            }
            double ta = (lo[a] - p[a]) / d[a], tb = (hi[a] - p[a]) / d[a];
            if (ta > tb) std::swap(ta, tb);
            t0 = std::max(t0, ta);
            t1 = std::min(t1, tb);
        }
        return t0 < t1;
    };
    int front = 0, free = 0;
    for (const auto& d : fibonacciDirections(256, false)) {
        if (!(d[2] > 0)) continue;
        ++front;
        free += !hitsBox(d, {18, 0, 1}, {20, 200, 11}) && !hitsBox(d, {40, 0, 1}, {42, 200, 11});
    }
    const double exact = double(free) / front;
    ASSERT_LT(exact, 0.8);
    AoReceivers receivers;
    receivers.positions.push_back({float(p[0]), float(p[1]), float(p[2])});
    receivers.normals.push_back({0.0f, 0.0f, 1.0f});
    auto v = computeAmbientOcclusion(cells, receivers, depthMap(0.0));
    ASSERT_TRUE(v);
    // Measured: 0.5625 for 0.4922 (9 of 128 directions): the grazing ones that cross only the walls'
    // bottom row, whose centres lie ½ edge above the receiver's plane — within the cube's reach.
    EXPECT_NEAR((*v)[0], exact, 0.08);
    EXPECT_GE((*v)[0], exact);
}

TEST(AoLeafReceivers, SlicesAndBadOptionsAreRefused)
{
    AoCells cells;
    addCell(cells, 1, 1, 1, {0, 0, 1});
    AoReceivers receivers;
    receivers.positions.push_back({1.5f, 1.5f, 1.5f});
    receivers.normals.push_back({0.0f, 0.0f, 1.0f});
    AoOptions o = depthMap(0.0);
    auto lone = computeAmbientOcclusion(cells, receivers, o);
    ASSERT_TRUE(lone);
    EXPECT_EQ(*lone, std::vector<float>{1.0f}); // its own cell never hides it
    o.method = AoMethod::Slices;
    auto slices = computeAmbientOcclusion(cells, receivers, o);
    ASSERT_FALSE(slices);
    EXPECT_EQ(slices.error().code, ErrorCode::InvalidArgument);
    o = depthMap(0.0);
    o.receiverBias = -1.0;
    EXPECT_FALSE(computeAmbientOcclusion(cells, receivers, o));
}

TEST(AoLeafReceivers, LeavesAreReceiversInTheCellsUnits)
{
    // Root box at O = (10, 20, 30), edge 8, depth 2: leaves of 2 m, level-1 cells of 4 m. A leaf with
    // coordinates c is at (c + ½) / 2 level-1 edges.
    std::vector<double> p{10 + 1, 20 + 1, 30 + 1, 10 + 7, 20 + 3, 30 + 5};
    std::vector<float> n{0, 0, 1, 1, 0, 0};
    const stylos::test::ReferenceOctree reference(p, n, {}, 2, octree::NormalCodeKind::Octahedral16,
                                                  octree::RootBox{{10, 20, 30}, 8.0});
    stylos::test::TempDir dir;
    const auto packed = stylos::test::pack(reference, dir);
    ASSERT_NE(packed, nullptr);
    auto cells = cellsAtLevel(*packed, 1);
    ASSERT_TRUE(cells);
    auto receivers = leafReceivers(*packed, *cells);
    ASSERT_TRUE(receivers);
    ASSERT_EQ(receivers->size(), 2u);
    std::vector<std::array<float, 3>> got = receivers->positions;
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got[0], (std::array<float, 3>{0.25f, 0.25f, 0.25f}));
    EXPECT_EQ(got[1], (std::array<float, 3>{1.75f, 0.75f, 1.25f}));
    // The skydome layer with leaf receivers: one value per leaf. The second leaf's cell lies 1.25 edges
    // above the first's tangent plane (z) and hides part of its sky; the first's cell is behind the
    // second's (normal +x).
    SkydomeLayerOptions layer;
    layer.level = 1;
    layer.leafReceivers = true;
    layer.ao = depthMap(0.0);
    auto values = computeLeafSkydome(*packed, layer);
    ASSERT_TRUE(values);
    ASSERT_EQ(values->size(), 2u);
    EXPECT_LT((*values)[0], 0.95f);
    EXPECT_GT((*values)[0], 0.5f);
    EXPECT_EQ((*values)[1], 1.0f);
}

TEST(AoLeafReceivers, TwoSidedReadsTheOutsideWhicheverWayTheNormalPoints)
{
    // The shell of a closed 24³ box of cells (every cell with a coordinate 0 or 23), receivers on its top
    // face's surface (z = 24) in the middle: with the normal up, the whole hemisphere; with it flipped
    // into the box, one-sided it sees the box's inside (nothing), two-sided the outside again. At the
    // box's centre nothing is visible on either side.
    AoCells cells;
    constexpr unsigned kSize = 24;
    for (unsigned z = 0; z < kSize; ++z)
        for (unsigned y = 0; y < kSize; ++y)
            for (unsigned x = 0; x < kSize; ++x) {
                const bool shell = x == 0 || y == 0 || z == 0 || x == kSize - 1 || y == kSize - 1 || z == kSize - 1;
                if (!shell) continue;
                const Vec n = z == kSize - 1 ? Vec{0, 0, 1} : z == 0 ? Vec{0, 0, -1} : x == 0 ? Vec{-1, 0, 0}
                            : x == kSize - 1 ? Vec{1, 0, 0} : y == 0 ? Vec{0, -1, 0} : Vec{0, 1, 0};
                addCell(cells, x, y, z, n);
            }
    AoReceivers receivers;
    for (const float sign : {1.0f, -1.0f}) {
        receivers.positions.push_back({11.3f, 12.6f, float(kSize)});
        receivers.normals.push_back({0.0f, 0.0f, sign});
    }
    receivers.positions.push_back({12.0f, 12.0f, 12.0f});
    receivers.normals.push_back({0.0f, 0.6f, 0.8f});
    AoOptions o = depthMap(0.5);
    auto oneSided = computeAmbientOcclusion(cells, receivers, o);
    ASSERT_TRUE(oneSided);
    // Inside, only the grazing directions whose wall lies within the slope-scaled tolerance read free
    // (an occluder t away is t·(n·d) above the plane: n·d < ~0.08 for walls 12–17 edges away; measured
    // 10 and 12 of 128).
    EXPECT_EQ((*oneSided)[0], 1.0f);
    EXPECT_LT((*oneSided)[1], 0.1f);
    EXPECT_LT((*oneSided)[2], 0.1f);
    o.twoSided = true;
    auto twoSided = computeAmbientOcclusion(cells, receivers, o);
    ASSERT_TRUE(twoSided);
    EXPECT_EQ((*twoSided)[0], 1.0f);
    EXPECT_EQ((*twoSided)[1], 1.0f);
    EXPECT_LT((*twoSided)[2], 0.1f);
    // Only on the full sphere of directions: with the upper hemisphere alone it stays one-sided.
    o.upperHemisphere = true;
    auto upper = computeAmbientOcclusion(cells, receivers, o);
    ASSERT_TRUE(upper);
    EXPECT_LT((*upper)[1], 0.1f);
}
