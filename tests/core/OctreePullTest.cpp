// Pull on hand-checked trees: an inner cell's normal is the encoded count-weighted sum of its children's
// decoded normals (double, slot order), its weight the sum of theirs.
#include "stylos/core/octree/ConstructionOctree.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

using namespace stylos::core::octree;

namespace {

const RootBox unitBox{{0, 0, 0}, 1.0};

struct Leaf {
    std::array<double, 3> position;
    std::array<float, 3> normal;
    int points;  ///< how many identical points
};

ConstructionOctree build(const std::vector<Leaf>& leaves, int depth, NormalCodeKind kind, unsigned threads = 1)
{
    ConstructionOctree tree(unitBox, depth, kind, false, 0);
    auto path = tree.rootPath();
    for (const Leaf& l : leaves)
        for (int i = 0; i < l.points; ++i)
            EXPECT_TRUE(tree.populate(preparePoint(unitBox, depth, kind, l.position.data(), l.normal.data(), nullptr), path));
    tree.pull(threads);
    return tree;
}

std::vector<std::uint16_t> normals(const OctreeLevels& t, int level)
{
    std::vector<std::uint16_t> out;
    t.visitLevel(level, [&](const CellBlock& b) { out.insert(out.end(), b.normals.begin(), b.normals.end()); });
    return out;
}

/** The shared pull of one cell from its children's (weight, code), in slot order. */
std::uint16_t pulled(NormalCodeKind kind, const std::vector<std::pair<std::uint64_t, std::uint16_t>>& children)
{
    double s[3] = {0, 0, 0};
    for (const auto& [w, code] : children) {
        const auto d = decodeNormal(kind, code);
        for (int a = 0; a < 3; ++a) s[a] += double(w) * double(d[a]);
    }
    return encodeNormal(kind, float(s[0]), float(s[1]), float(s[2]));
}

/** The shared leaf averaging of @p points identical normals. */
std::uint16_t leafCode(NormalCodeKind kind, std::array<float, 3> n, int points)
{
    const auto u = unitNormal(n[0], n[1], n[2]);
    std::uint16_t code = encodeNormal(kind, u[0], u[1], u[2]);
    for (int w = 1; w < points; ++w) {
        const auto d = decodeNormal(kind, code);
        code = encodeNormal(kind, d[0] * float(w) + u[0], d[1] * float(w) + u[1], d[2] * float(w) + u[2]);
    }
    return code;
}

} // namespace

TEST(OctreePull, HandCheckedTwoLevelTree)
{
    for (NormalCodeKind kind : {NormalCodeKind::Octahedral16, NormalCodeKind::Paper15}) {
        // Depth 2. Level-1 cell (0,0,0): leaves (0,0,0) ×3 points along +x and (1,1,0) ×1 along +y;
        // level-1 cell (1,1,1): leaf (3,3,3) ×2 along −z.
        const std::vector<Leaf> leaves = {{{0.1, 0.1, 0.1}, {1, 0, 0}, 3},
                                          {{0.3, 0.3, 0.1}, {0, 1, 0}, 1},
                                          {{0.9, 0.9, 0.9}, {0, 0, -1}, 2}};
        const ConstructionOctree tree = build(leaves, 2, kind);
        const std::uint16_t x = leafCode(kind, {1, 0, 0}, 3), y = leafCode(kind, {0, 1, 0}, 1),
                            mz = leafCode(kind, {0, 0, -1}, 2);
        EXPECT_EQ(normals(tree, 2), (std::vector<std::uint16_t>{x, y, mz}));
        if (kind == NormalCodeKind::Octahedral16) {
            EXPECT_EQ(x, encodeNormal(kind, 1, 0, 0));  // axes are exact
        }
        const std::uint16_t a = pulled(kind, {{3, x}, {1, y}});
        const std::uint16_t b = pulled(kind, {{2, mz}});
        EXPECT_EQ(normals(tree, 1), (std::vector<std::uint16_t>{a, b}));
        EXPECT_EQ(normals(tree, 0), (std::vector<std::uint16_t>{pulled(kind, {{4, a}, {2, b}})}));
        EXPECT_EQ(tree.weights(1), (std::vector<std::uint64_t>{4, 2}));
        // Cell a leans to +x, 3 : 1.
        const auto da = decodeNormal(kind, a);
        EXPECT_NEAR(da[0], 3 / std::sqrt(10.0), 0.03);
        EXPECT_NEAR(da[1], 1 / std::sqrt(10.0), 0.03);
    }
}

TEST(OctreePull, SingleChildChainsFollowTheGeneralFormulaForEveryWeight)
{
    // A chain of single-child cells above one leaf: power-of-two weights take the re-encoding shortcut,
    // others the general sum; both must give exactly the formula, level after level.
    for (NormalCodeKind kind : {NormalCodeKind::Octahedral16, NormalCodeKind::Paper15}) {
        for (int w : {1, 2, 3, 4, 5, 7, 8, 64, 100, 1024}) {
            const std::vector<Leaf> leaves = {{{0.3, 0.6, 0.8}, {0.3f, -0.5f, 0.81f}, 1},
                                              {{0.3, 0.6, 0.8}, {0.9f, 0.1f, -0.2f}, w - 1}};
            const int depth = 5;
            const ConstructionOctree tree = build(leaves, depth, kind);
            std::uint16_t code = normals(tree, depth)[0];
            for (int level = depth - 1; level >= 0; --level) {
                code = pulled(kind, {{std::uint64_t(w), code}});
                ASSERT_EQ(normals(tree, level), (std::vector<std::uint16_t>{code})) << "w " << w << " level " << level;
            }
        }
    }
}

TEST(OctreePull, ThreadsDoNotChangeTheResult)
{
    std::vector<Leaf> leaves;
    std::uint64_t points = 0;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            leaves.push_back({{(i + 0.5) / 40, (j + 0.5) / 40, 0.5 + 0.2 * ((i * j) % 5) / 5.0},
                              {float(i - 20), float(j - 20), 10.0f}, 1 + (i + j) % 3});
            points += std::uint64_t(leaves.back().points);
        }
    const ConstructionOctree one = build(leaves, 7, NormalCodeKind::Octahedral16, 1);
    const ConstructionOctree three = build(leaves, 7, NormalCodeKind::Octahedral16, 3);
    for (int l = 0; l <= 7; ++l) EXPECT_EQ(normals(one, l), normals(three, l)) << l;
    EXPECT_EQ(one.weights(0), (std::vector<std::uint64_t>{points}));
    EXPECT_EQ(one.description().points, points);
}

TEST(OctreePull, PowerOfTwoSingleChildShortcutHoldsForEveryCode)
{
    // The pull re-encodes a single child of power-of-two weight w from a table of encode(decode(code)).
    // The premise, for every code: the general formula encode(float(0 + w · d)) equals encode(d).
    for (NormalCodeKind kind : {NormalCodeKind::Octahedral16, NormalCodeKind::Paper15}) {
        const auto* table = normalDecodeTable(kind);
        for (std::size_t c = 0; c < normalCodeCount(kind); ++c) {
            const auto& d = table[c];
            const std::uint16_t once = encodeNormal(kind, d[0], d[1], d[2]);
            for (double w : {1.0, 2.0, 64.0, 4294967296.0, 9223372036854775808.0}) {
                const std::uint16_t general = encodeNormal(kind, float(0.0 + w * double(d[0])),
                                                          float(0.0 + w * double(d[1])), float(0.0 + w * double(d[2])));
                ASSERT_EQ(general, once) << "code " << c << " weight " << w;
            }
        }
    }
}
