// Tests of the test reference octree itself: hand-computed trees, the averaging and pull formulas,
// breadth-first order and the invariants every octree must satisfy.
#include "ReferenceOctree.h"

#include <gtest/gtest.h>

#include <bit>
#include <random>

using namespace stylos::core::octree;
using stylos::test::ManualOctree;
using stylos::test::ReferenceOctree;

namespace {

std::vector<std::uint8_t> collectMasks(const OctreeLevels& t, int level)
{
    std::vector<std::uint8_t> out;
    t.visitLevel(level, [&](const CellBlock& b) { out.insert(out.end(), b.masks.begin(), b.masks.end()); });
    return out;
}

std::vector<std::uint16_t> collectNormals(const OctreeLevels& t, int level)
{
    std::vector<std::uint16_t> out;
    t.visitLevel(level, [&](const CellBlock& b) { out.insert(out.end(), b.normals.begin(), b.normals.end()); });
    return out;
}

} // namespace

TEST(ReferenceOctree, MortonKeyRoundTripAndOrder)
{
    EXPECT_EQ(stylos::test::mortonKey(1, 0, 0, 1), 1u);
    EXPECT_EQ(stylos::test::mortonKey(0, 1, 0, 1), 2u);
    EXPECT_EQ(stylos::test::mortonKey(0, 0, 1, 1), 4u);
    // (x=2,y=1,z=3) at level 2: top slot (1,0,1)=5, bottom slot (0,1,1)=6 -> 5*8+6.
    EXPECT_EQ(stylos::test::mortonKey(2, 1, 3, 2), 46u);
    EXPECT_EQ(stylos::test::mortonCoords(46, 2), (std::array<std::uint32_t, 3>{2, 1, 3}));
    const std::uint32_t big = (1u << 21) - 1;
    EXPECT_EQ(stylos::test::mortonCoords(stylos::test::mortonKey(big, 5, big - 7, 21), 21),
              (std::array<std::uint32_t, 3>{big, 5, big - 7}));
}

TEST(ReferenceOctree, TwoCornersAtDepthOne)
{
    const std::vector<double> p{0, 0, 0, 1, 1, 1};
    const std::vector<float> n{0, 0, 2, 3, 0, 0};
    ReferenceOctree t(p, n, {}, 1);
    EXPECT_EQ(t.description().box, (RootBox{{0, 0, 0}, 1.0}));
    EXPECT_EQ(t.description().cellsPerLevel, (std::vector<std::uint64_t>{1, 2}));
    EXPECT_EQ(t.description().points, 2u);
    EXPECT_FALSE(t.description().hasColour);
    EXPECT_EQ(collectMasks(t, 0), (std::vector<std::uint8_t>{0x81}));
    EXPECT_TRUE(collectMasks(t, 1).empty());
    const auto kind = NormalCodeKind::Octahedral16;
    EXPECT_EQ(collectNormals(t, 1), (std::vector<std::uint16_t>{encodeNormal(kind, 0, 0, 1), encodeNormal(kind, 1, 0, 0)}));
    const auto a = decodeNormal(kind, encodeNormal(kind, 0, 0, 1));
    const auto b = decodeNormal(kind, encodeNormal(kind, 1, 0, 0));
    const std::uint16_t root = encodeNormal(kind, float(double(a[0]) + double(b[0])), float(double(a[1]) + double(b[1])),
                                            float(double(a[2]) + double(b[2])));
    EXPECT_EQ(t.normals(0), (std::vector<std::uint16_t>{root}));
    EXPECT_EQ(t.weights(0), (std::vector<std::uint64_t>{2}));
    EXPECT_EQ(t.coords(1, 1), (std::array<std::uint32_t, 3>{1, 1, 1}));
}

TEST(ReferenceOctree, LeafAveragingFollowsTheRunningFormula)
{
    // Three points in one leaf (depth 1, box given), one in another to fix the box.
    const RootBox box{{0, 0, 0}, 2.0};
    const std::vector<double> p{0.1, 0.1, 0.1, 0.2, 0.2, 0.2, 0.3, 0.3, 0.3, 1.5, 1.5, 1.5};
    const std::vector<float> n{0, 0, 5, 1, 0, 0, 0, 3, 4, 0, 0, 0};
    const std::vector<std::uint8_t> c{10, 0, 255, 21, 1, 0, 0, 2, 255, 7, 8, 9};
    for (auto kind : {NormalCodeKind::Octahedral16, NormalCodeKind::Paper15}) {
        ReferenceOctree t(p, n, c, 1, kind, box);
        ASSERT_EQ(t.cellCount(1), 2u);
        std::uint16_t code = encodeNormal(kind, 0, 0, 1);
        auto d = decodeNormal(kind, code);
        code = encodeNormal(kind, d[0] * 1.0f + 1.0f, d[1] * 1.0f, d[2] * 1.0f);
        d = decodeNormal(kind, code);
        code = encodeNormal(kind, d[0] * 2.0f, d[1] * 2.0f + 0.6f, d[2] * 2.0f + 0.8f);
        EXPECT_EQ(t.normals(1)[0], code);
        // Zero normal: +Z's code.
        EXPECT_EQ(t.normals(1)[1], encodeNormal(kind, 0, 0, 1));
        EXPECT_EQ(t.weights(1), (std::vector<std::uint64_t>{3, 1}));
        // Colour: (10+21+1)/2 = 16, then (16*2+0+1)/3 = 11; (0+1+1)/2 = 1, (1*2+2+1)/3 = 1;
        // (255+0+1)/2 = 128, (128*2+255+1)/3 = 170.
        EXPECT_EQ(t.colours(), (std::vector<std::uint8_t>{11, 1, 170, 7, 8, 9}));
    }
}

TEST(ReferenceOctree, SkipsNonFinitePositions)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> p{0, 0, 0, nan, 5, 5, 1, 1, 1};
    const std::vector<float> n{0, 0, 1, 0, 0, 1, 0, 0, 1};
    ReferenceOctree t(p, n, {}, 2);
    EXPECT_EQ(t.description().points, 2u);
    EXPECT_EQ(t.description().box, (RootBox{{0, 0, 0}, 1.0}));
    EXPECT_EQ(t.description().cellsPerLevel, (std::vector<std::uint64_t>{1, 2, 2}));
}

TEST(ReferenceOctree, BreadthFirstOrderAndInvariantsOnRandomCloud)
{
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-2.0, 3.0);
    std::normal_distribution<float> g;
    std::vector<double> p;
    std::vector<float> n;
    for (int i = 0; i < 3000; ++i) {
        p.push_back(u(rng)); p.push_back(u(rng) * 0.5); p.push_back(u(rng) * 0.1);
        n.push_back(g(rng)); n.push_back(g(rng)); n.push_back(g(rng));
    }
    ReferenceOctree t(p, n, {}, 6, NormalCodeKind::Octahedral16, std::nullopt, 100);
    const auto& d = t.description();
    ASSERT_EQ(d.cellsPerLevel.size(), 7u);
    EXPECT_EQ(d.cellsPerLevel[0], 1u);
    std::uint64_t leafWeights = 0;
    for (auto w : t.weights(6)) leafWeights += w;
    EXPECT_EQ(leafWeights, 3000u);
    EXPECT_EQ(t.weights(0)[0], 3000u);
    for (int l = 0; l < 6; ++l) {
        const auto masks = collectMasks(t, l);
        ASSERT_EQ(masks.size(), d.cellsPerLevel[l]);
        std::uint64_t children = 0;
        for (std::size_t i = 0; i < masks.size(); ++i) {
            ASSERT_NE(masks[i], 0);
            EXPECT_EQ(t.firstChild(l, i), children);
            // Children are consecutive, in slot order, and lie inside their parent.
            unsigned k = 0;
            for (unsigned s = 0; s < 8; ++s) {
                if (!(masks[i] & (1u << s))) continue;
                const auto cc = t.coords(l + 1, children + k);
                const auto pc = t.coords(l, i);
                EXPECT_EQ(childSlot(cc[0], cc[1], cc[2]), s);
                EXPECT_EQ((std::array<std::uint32_t, 3>{cc[0] >> 1, cc[1] >> 1, cc[2] >> 1}), pc);
                ++k;
            }
            children += static_cast<unsigned>(std::popcount(masks[i]));
        }
        EXPECT_EQ(children, d.cellsPerLevel[l + 1]);
        EXPECT_EQ(collectNormals(t, l).size(), d.cellsPerLevel[l]);
    }
    EXPECT_EQ(collectNormals(t, 6), t.normals(6));
}

TEST(ManualOctree, TwoLevelsDescribesItsCells)
{
    const auto t = ManualOctree::twoLevels(0x29, true);
    EXPECT_EQ(t.description().depth, 1);
    EXPECT_EQ(t.description().cellsPerLevel, (std::vector<std::uint64_t>{1, 3}));
    EXPECT_EQ(t.description().points, 3u);
    std::vector<std::uint8_t> colours;
    t.visitLevel(1, [&](const CellBlock& b) { colours.insert(colours.end(), b.colours.begin(), b.colours.end()); });
    EXPECT_EQ(colours, (std::vector<std::uint8_t>{0, 0, 200, 30, 60, 200, 50, 100, 200}));
}
