// Picking: nearest cell and ray picks on a four-leaf tree with known answers (levels, limits, ties,
// rays from behind, growing radius), and against brute-force scans over every cell of a generated drum.
#include "PoctTestSupport.h"
#include "ReferenceOctree.h"
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/octree/CellPick.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/octree/PoctWriter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

using namespace stylos::core;
using namespace stylos::core::octree;
using stylos::test::ReferenceOctree;
using stylos::test::TempDir;
using stylos::test::pack;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// The four-leaf tree of ViewCutTest: root box origin O = (100, 200, 300), edge 4, depth 2; leaves
// a1 (0,0,0), a2 (1,0,0), b1 (2,2,2), b2 (3,2,2) (indices 0..3); level 1: a (0,0,0), b (1,1,1).
constexpr double Ox = 100, Oy = 200, Oz = 300;

std::array<double, 3> at(double x, double y, double z) { return {Ox + x, Oy + y, Oz + z}; }

class FourLeafPick : public ::testing::Test {
protected:
    void SetUp() override
    {
        const std::vector<double> p{Ox + 0.5, Oy + 0.5, Oz + 0.5, Ox + 1.5, Oy + 0.5, Oz + 0.5,
                                    Ox + 2.5, Oy + 2.5, Oz + 2.5, Ox + 3.5, Oy + 2.5, Oz + 2.5};
        const std::vector<float> n{0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, -1};
        const ReferenceOctree reference(p, n, {}, 2, NormalCodeKind::Octahedral16, RootBox{{Ox, Oy, Oz}, 4.0});
        m_octree = pack(reference, m_dir);
        ASSERT_NE(m_octree, nullptr);
    }

    TempDir m_dir;
    std::unique_ptr<PackedOctree> m_octree;
};

} // namespace

TEST_F(FourLeafPick, NearestLeafAndNearestCellOfALevel)
{
    auto r = nearestCell(*m_octree, at(1.6, 0.9, 0.5), inf);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.level, 2);
    EXPECT_EQ(r->cell.index, 1u);
    EXPECT_EQ(r->cell.coords, (std::array<std::uint32_t, 3>{1, 0, 0}));
    EXPECT_EQ(r->cell.centre, at(1.5, 0.5, 0.5));
    EXPECT_EQ(r->cell.size, 1.0);
    EXPECT_EQ(r->cell.normal, m_octree->normal(2, 1));
    EXPECT_NEAR(r->distance, std::sqrt(0.01 + 0.16), 1e-12);

    r = nearestCell(*m_octree, at(3.9, 3.9, 3.9), inf);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.index, 3u);
    // Far outside the box.
    r = nearestCell(*m_octree, at(-50, 0.4, 0.6), inf);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.index, 0u);
    EXPECT_NEAR(r->distance, std::sqrt(50.5 * 50.5 + 0.02), 1e-9);
    // Level 1: centres (1,1,1) and (3,3,3).
    r = nearestCell(*m_octree, at(2.1, 2.1, 2.1), inf, 1);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.level, 1);
    EXPECT_EQ(r->cell.index, 1u);
    EXPECT_EQ(r->cell.size, 2.0);
    // Level 0: the root, always.
    r = nearestCell(*m_octree, at(-7, 3, 1), inf, 0);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.level, 0);
    EXPECT_EQ(r->cell.centre, at(2, 2, 2));
}

TEST_F(FourLeafPick, NearestRespectsTheDistanceLimit)
{
    // a2's centre is 0.5 away.
    EXPECT_FALSE(nearestCell(*m_octree, at(2.0, 0.5, 0.5), 0.49));
    auto r = nearestCell(*m_octree, at(2.0, 0.5, 0.5), 0.5);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.index, 1u);
    EXPECT_EQ(r->distance, 0.5);
    EXPECT_FALSE(nearestCell(*m_octree, at(2.0, 0.5, 0.5), -1));
    EXPECT_FALSE(nearestCell(*m_octree, at(2.0, 0.5, 0.5), std::nan("")));
}

TEST_F(FourLeafPick, NearestTieGoesToTheSmallestIndex)
{
    // Midway between a1 and a2 (both exactly 0.5 away), and between b1 and b2.
    auto r = nearestCell(*m_octree, at(1.0, 0.5, 0.5), inf);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.index, 0u);
    EXPECT_EQ(r->distance, 0.5);
    r = nearestCell(*m_octree, at(3.0, 2.5, 2.5), inf);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.index, 2u);
}

TEST_F(FourLeafPick, RayHitsTheFirstCentreWithinTheRadius)
{
    // Along +x through a1 and a2: a1 first, 10.5 m along.
    auto r = pickRay(*m_octree, at(-10, 0.5, 0.5), {1, 0, 0}, 0.01, 0);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.index, 0u);
    EXPECT_DOUBLE_EQ(r->distance, 10.5);
    // The direction need not be unit; from the other side a2 comes first.
    r = pickRay(*m_octree, at(20, 0.5, 0.5), {-7, 0, 0}, 0.01, 0);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.index, 1u);
    EXPECT_DOUBLE_EQ(r->distance, 18.5);
    // Starting between a1 and a2: a1 is behind the origin.
    r = pickRay(*m_octree, at(1.0, 0.5, 0.5), {1, 0, 0}, 0, 0);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.index, 1u);
    EXPECT_DOUBLE_EQ(r->distance, 0.5);
    // Level 1: the diagonal through both level-1 centres, from beyond b.
    r = pickRay(*m_octree, at(5, 5, 5), {-1, -1, -1}, 1e-9, 0, 1);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.level, 1);
    EXPECT_EQ(r->cell.index, 1u);
    EXPECT_NEAR(r->distance, std::sqrt(12.0), 1e-12);
    // Pointing away: nothing.
    EXPECT_FALSE(pickRay(*m_octree, at(-10, 0.5, 0.5), {-1, 0, 0}, 0.5, 0.1));
}

TEST_F(FourLeafPick, RayRadiusGrowsWithDistance)
{
    // A ray parallel to x, 0.3 m off a1 and a2 (in y); b's centres are ≥ 1.7 m off.
    const auto origin = at(-10, 0.8, 0.5);
    EXPECT_FALSE(pickRay(*m_octree, origin, {1, 0, 0}, 0.29, 0));
    // radius(10.5) = 0.1 + 10.5 · 0.02 = 0.31 ≥ 0.3: a1.
    auto r = pickRay(*m_octree, origin, {1, 0, 0}, 0.1, 0.02);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.index, 0u);
    // radius(10.5) = 0.1 + 10.5 · 0.019 = 0.2995 < 0.3 but radius(11.5) = 0.3185: a2.
    r = pickRay(*m_octree, origin, {1, 0, 0}, 0.1, 0.019);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.index, 1u);
    EXPECT_DOUBLE_EQ(r->distance, 11.5);
}

TEST_F(FourLeafPick, RayTieGoesToTheSmallestIndex)
{
    // Perpendicular to the a1–a2 line, through its midpoint: both centres at t = 10, 0.5 m off.
    const auto r = pickRay(*m_octree, at(1.0, -9.5, 0.5), {0, 1, 0}, 0.5, 0);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->cell.index, 0u);
    EXPECT_DOUBLE_EQ(r->distance, 10.0);
}

// ---- Against brute force on a generated drum ----

namespace {

struct Centre {
    std::uint64_t index;
    std::array<double, 3> c;
};

class DrumPick : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        s_dir = std::make_unique<TempDir>();
        auto o = stylos::test::coarse(0.01, 11);
        o.writeNormals = true;
        stylos::test::generate(synth::SyntheticKind::Drum, o, *s_dir / "drum.ply");
        auto reader = io::openPointReader(*s_dir / "drum.ply");
        ASSERT_TRUE(reader.ok());
        auto batch = stylos::test::readAllPoints(**reader, 65536);
        ASSERT_TRUE(batch.ok());
        s_octree = pack(ReferenceOctree::fromBatch(*batch, 10), *s_dir, "drum.poct");
        ASSERT_NE(s_octree, nullptr);
    }

    static void TearDownTestSuite()
    {
        s_octree.reset();
        s_dir.reset();
    }

    void SetUp() override { ASSERT_NE(s_octree, nullptr) << "the drum octree could not be built"; }

    static std::vector<Centre> centres(int level)
    {
        std::vector<Centre> out;
        s_octree->forEachCell(level, [&](const CellView& c) {
            out.push_back({c.index, c.centre});
            return true;
        });
        return out;
    }

    static inline std::unique_ptr<TempDir> s_dir;
    static inline std::unique_ptr<PackedOctree> s_octree;
};

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

} // namespace

TEST_F(DrumPick, NearestCellMatchesBruteForce)
{
    const PackedOctree& octree = *s_octree;
    const RootBox& box = octree.box();
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-0.2, 1.2);
    for (const int level : {-1, octree.depth() - 3, 2}) {
        const std::vector<Centre> all = centres(level < 0 ? octree.depth() : level);
        for (int q = 0; q < 150; ++q) {
            const std::array<double, 3> p{box.origin[0] + u(rng) * box.size, box.origin[1] + u(rng) * box.size,
                                          box.origin[2] + u(rng) * box.size};
            const double limit = q % 3 == 0 ? 0.02 * box.size : inf;
            // Brute force: smallest distance, then smallest index, within the limit.
            const Centre* best = nullptr;
            double bestD = inf;
            for (const Centre& c : all) {
                const double d = distance(p, c.c);
                if (d <= limit && (best == nullptr || d < bestD)) best = &c, bestD = d;
            }
            const auto r = nearestCell(octree, p, limit, level);
            SCOPED_TRACE(testing::Message() << "level " << level << " query " << q);
            ASSERT_EQ(bool(r), best != nullptr);
            if (!best) continue;
            EXPECT_EQ(r->cell.index, best->index);
            EXPECT_EQ(r->distance, bestD);
            EXPECT_EQ(r->cell.centre, best->c);
        }
    }
}

TEST_F(DrumPick, RayPickMatchesBruteForce)
{
    const PackedOctree& octree = *s_octree;
    const RootBox& box = octree.box();
    const std::vector<Centre> leaves = centres(octree.depth());
    const std::array<double, 3> mid{box.origin[0] + box.size / 2, box.origin[1] + box.size / 2,
                                    box.origin[2] + box.size / 2};
    std::mt19937_64 rng(9);
    std::normal_distribution<double> g(0, 1);
    std::uniform_real_distribution<double> u(0, 1);
    std::uniform_int_distribution<std::size_t> pickLeaf(0, leaves.size() - 1);
    int hits = 0, misses = 0;
    for (int q = 0; q < 150; ++q) {
        // An origin on a sphere around the drum, aimed near a random leaf (or anywhere, one in five).
        std::array<double, 3> v{g(rng), g(rng), g(rng)};
        const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        const double reach = (q % 7 == 0 ? 0.3 : 1.5) * box.size; // some origins inside the box
        const std::array<double, 3> o{mid[0] + v[0] / n * reach, mid[1] + v[1] / n * reach, mid[2] + v[2] / n * reach};
        std::array<double, 3> target = leaves[pickLeaf(rng)].c;
        if (q % 5 == 0) target = {mid[0] + g(rng), mid[1] + g(rng), mid[2] + g(rng)};
        const double jitter = 0.005 * box.size;
        const std::array<double, 3> d{target[0] + jitter * g(rng) - o[0], target[1] + jitter * g(rng) - o[1],
                                      target[2] + jitter * g(rng) - o[2]};
        // Mostly a pixel's footprint; one in three a wide cone (the radius grows a lot across a cell).
        const double r0 = u(rng) * 0.004 * box.size, k = u(rng) * (q % 3 == 2 ? 0.3 : 0.004);
        const int level = q % 4 == 3 ? octree.depth() - 2 : -1;
        const std::vector<Centre> cells = level < 0 ? std::vector<Centre>{} : centres(level);
        const std::vector<Centre>& all = level < 0 ? leaves : cells;
        // Brute force: smallest t, then smallest index.
        const double dn = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const std::array<double, 3> u3{d[0] / dn, d[1] / dn, d[2] / dn};
        const Centre* best = nullptr;
        double bestT = inf;
        for (const Centre& c : all) {
            const std::array<double, 3> w{c.c[0] - o[0], c.c[1] - o[1], c.c[2] - o[2]};
            const double t = w[0] * u3[0] + w[1] * u3[1] + w[2] * u3[2];
            if (!(t >= 0)) continue;
            const std::array<double, 3> perp{w[0] - t * u3[0], w[1] - t * u3[1], w[2] - t * u3[2]};
            if (!(std::sqrt(perp[0] * perp[0] + perp[1] * perp[1] + perp[2] * perp[2]) <= r0 + k * t)) continue;
            if (best == nullptr || t < bestT) best = &c, bestT = t;
        }
        const auto r = pickRay(octree, o, d, r0, k, level);
        SCOPED_TRACE(testing::Message() << "ray " << q);
        ASSERT_EQ(bool(r), best != nullptr);
        if (!best) {
            ++misses;
            continue;
        }
        ++hits;
        EXPECT_EQ(r->cell.index, best->index);
        EXPECT_EQ(r->distance, bestT);
    }
    EXPECT_GT(hits, 50);
    EXPECT_GT(misses, 5);
}
