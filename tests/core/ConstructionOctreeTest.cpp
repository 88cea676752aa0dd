// The construction structure on hand-made points: Populate (Streaming), mark/allocate/findLeaf/average
// (Optimal), leaf averaging, memory limit, breadth-first listing.
#include "stylos/core/octree/ConstructionOctree.h"

#include "ReferenceOctree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>

using namespace stylos::core::octree;

namespace {

constexpr NormalCodeKind oct = NormalCodeKind::Octahedral16;
const RootBox unitBox{{0, 0, 0}, 1.0};

struct Input {
    std::vector<double> positions;
    std::vector<float> normals;
    std::vector<std::uint8_t> colours;
    void add(double x, double y, double z, float nx, float ny, float nz, std::array<std::uint8_t, 3> rgb = {})
    {
        positions.insert(positions.end(), {x, y, z});
        normals.insert(normals.end(), {nx, ny, nz});
        colours.insert(colours.end(), rgb.begin(), rgb.end());
    }
    std::size_t size() const { return positions.size() / 3; }
    PreparedPoint prepared(std::size_t i, const RootBox& box, int depth, NormalCodeKind kind = oct,
                           bool colour = false) const
    {
        return preparePoint(box, depth, kind, &positions[3 * i], &normals[3 * i], colour ? &colours[3 * i] : nullptr);
    }
};

ConstructionOctree populated(const Input& in, int depth, bool colour = false, NormalCodeKind kind = oct,
                             const RootBox& box = unitBox)
{
    ConstructionOctree tree(box, depth, kind, colour, 0);
    auto path = tree.rootPath();
    for (std::size_t i = 0; i < in.size(); ++i) EXPECT_TRUE(tree.populate(in.prepared(i, box, depth, kind, colour), path));
    return tree;
}

template <typename T, typename Pick>
std::vector<T> collect(const OctreeLevels& t, int level, Pick pick)
{
    std::vector<T> out;
    t.visitLevel(level, [&](const CellBlock& b) {
        const auto span = pick(b);
        out.insert(out.end(), span.begin(), span.end());
    });
    return out;
}
std::vector<std::uint8_t> masks(const OctreeLevels& t, int l) { return collect<std::uint8_t>(t, l, [](const CellBlock& b) { return b.masks; }); }
std::vector<std::uint16_t> normals(const OctreeLevels& t, int l) { return collect<std::uint16_t>(t, l, [](const CellBlock& b) { return b.normals; }); }
std::vector<std::uint8_t> colours(const OctreeLevels& t, int l) { return collect<std::uint8_t>(t, l, [](const CellBlock& b) { return b.colours; }); }

/** The shared leaf averaging, written out for the expectations. */
std::uint16_t averaged(std::uint16_t code, std::uint32_t w, std::array<float, 3> n)
{
    const auto u = unitNormal(n[0], n[1], n[2]);
    if (w == 0) return encodeNormal(oct, u[0], u[1], u[2]);
    const auto d = decodeNormal(oct, code);
    const float fw = float(w);
    return encodeNormal(oct, d[0] * fw + u[0], d[1] * fw + u[1], d[2] * fw + u[2]);
}

void expectSameLevels(const OctreeLevels& a, const OctreeLevels& b)
{
    ASSERT_EQ(a.description(), b.description());
    for (int l = 0; l <= a.description().depth; ++l) {
        EXPECT_EQ(masks(a, l), masks(b, l)) << "level " << l;
        EXPECT_EQ(normals(a, l), normals(b, l)) << "level " << l;
        EXPECT_EQ(colours(a, l), colours(b, l)) << "level " << l;
    }
}

/** Four points at depth 2: two in one leaf, one beside it, one in another level-1 cell. */
Input fourPoints()
{
    Input in;
    in.add(0.10, 0.10, 0.10, 0, 0, 2, {10, 20, 30});      // leaf (0,0,0)
    in.add(0.90, 0.10, 0.10, 1, 0, 0, {200, 0, 255});     // leaf (3,0,0)
    in.add(0.15, 0.20, 0.05, 0, 3, 0, {11, 21, 31});      // leaf (0,0,0) again
    in.add(0.30, 0.10, 0.10, 0, 0, -1, {1, 2, 3});        // leaf (1,0,0)
    return in;
}

} // namespace

TEST(ConstructionOctree, PopulateGivesExactMasksWeightsAndCodes)
{
    const Input in = fourPoints();
    ConstructionOctree tree = populated(in, 2);
    EXPECT_EQ(tree.description().cellsPerLevel, (std::vector<std::uint64_t>{1, 2, 3}));
    EXPECT_EQ(tree.description().points, 4u);
    EXPECT_EQ(masks(tree, 0), (std::vector<std::uint8_t>{0x03}));        // level-1 cells (0,0,0), (1,0,0)
    EXPECT_EQ(masks(tree, 1), (std::vector<std::uint8_t>{0x03, 0x02}));  // (0,0,0): slots 0, 1; (1,0,0): slot 1
    EXPECT_TRUE(masks(tree, 2).empty());
    EXPECT_EQ(tree.weights(2), (std::vector<std::uint64_t>{2, 1, 1}));
    EXPECT_EQ(tree.weights(1), (std::vector<std::uint64_t>{3, 1}));
    EXPECT_EQ(tree.weights(0), (std::vector<std::uint64_t>{4}));
    const std::uint16_t first = averaged(0, 0, {0, 0, 2});
    EXPECT_EQ(first, encodeNormal(oct, 0, 0, 1));
    EXPECT_EQ(normals(tree, 2), (std::vector<std::uint16_t>{averaged(first, 1, {0, 3, 0}), averaged(0, 0, {0, 0, -1}),
                                                             averaged(0, 0, {1, 0, 0})}));
    EXPECT_TRUE(colours(tree, 2).empty());
    // The structure does not depend on the order; with 7-byte cells in one chunk.
    EXPECT_EQ(tree.bytes(), tree.arena().bytesWithChunks(1));
    EXPECT_EQ(tree.arena().cellBytes(), 7u);
}

TEST(ConstructionOctree, ColourRunningAverageIsRoundedIntegerMean)
{
    Input in = fourPoints();
    in.add(0.12, 0.11, 0.13, 0, 0, 1, {255, 255, 0});
    ConstructionOctree tree = populated(in, 2, true);
    EXPECT_EQ(tree.arena().cellBytes(), 10u);
    // Leaf (0,0,0): 10 → (10·1 + 11 + 1) / 2 = 11 → (11·2 + 255 + 1) / 3 = 92; green 20 → 21 → 99;
    // blue 30 → (30 + 31 + 1) / 2 = 31 → (62 + 0 + 1) / 3 = 21.
    EXPECT_EQ(colours(tree, 2), (std::vector<std::uint8_t>{92, 99, 21, 1, 2, 3, 200, 0, 255}));
    EXPECT_EQ(tree.weights(2), (std::vector<std::uint64_t>{3, 1, 1}));
    EXPECT_TRUE(colours(tree, 1).empty());
}

TEST(ConstructionOctree, ZeroAndNonFiniteNormalsAverageAsZeroVectors)
{
    Input in;
    in.add(0.1, 0.1, 0.1, 0, 0, 0);
    in.add(0.1, 0.1, 0.1, 1, 0, 0);
    in.add(0.1, 0.1, 0.1, std::numeric_limits<float>::quiet_NaN(), 0, 1);
    ConstructionOctree tree = populated(in, 1);
    std::uint16_t code = averaged(0, 0, {0, 0, 0});
    EXPECT_EQ(code, encodeNormal(oct, 0, 0, 1));  // zero vector: +Z's code
    code = averaged(code, 1, {1, 0, 0});
    code = averaged(code, 2, {std::numeric_limits<float>::quiet_NaN(), 0, 1});
    EXPECT_EQ(normals(tree, 1), (std::vector<std::uint16_t>{code}));
}

TEST(ConstructionOctree, WeightSaturatesAtTheTopOfItsRange)
{
    Input in;
    in.add(0.7, 0.2, 0.2, 0, 1, 0, {100, 100, 100});
    ConstructionOctree tree = populated(in, 1, true);
    const std::uint32_t leaf = tree.cellIndices(1)[0];
    std::uint8_t* c = tree.arena().cell(leaf);
    cell::setValue(c, 0xFFFFFFFFu);
    const std::uint16_t before = cell::normal(c);
    Input more;
    more.add(0.7, 0.2, 0.2, 1, 0, 0, {0, 0, 0});
    tree.average(leaf, more.prepared(0, unitBox, 1, oct, true));
    EXPECT_EQ(cell::value(c), 0xFFFFFFFFu);
    EXPECT_EQ(cell::normal(c), averaged(before, 0xFFFFFFFFu, {1, 0, 0}));
    EXPECT_EQ(cell::colour(c)[0], 100u);  // (100·(2^32−1) + 0 + 2^31) / 2^32 rounds to 100
}

TEST(ConstructionOctree, OptimalPrimitivesBuildTheSameTreeAsPopulate)
{
    std::mt19937 random(4);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<float> g;
    Input in;
    for (int i = 0; i < 3000; ++i) in.add(u(random), u(random) * u(random), 0.5 + 0.1 * u(random), g(random), g(random), g(random));
    const int depth = 6;
    ConstructionOctree streaming = populated(in, depth);
    ConstructionOctree optimal(unitBox, depth, oct, false, 0);
    for (int level = 0; level < depth; ++level) {
        auto path = optimal.rootPath();
        for (std::size_t i = 0; i < in.size(); ++i)
            ASSERT_TRUE(optimal.mark(in.prepared(i, unitBox, depth).coords, level, path));
        const std::uint64_t predicted = optimal.bytesAfterAllocating(level);
        ASSERT_TRUE(optimal.allocateLevel(level));
        EXPECT_EQ(optimal.bytes(), predicted);
    }
    auto path = optimal.rootPath();
    for (std::size_t i = 0; i < in.size(); ++i) {
        const PreparedPoint p = in.prepared(i, unitBox, depth);
        const std::uint32_t leaf = optimal.findLeaf(p.coords, path);
        ASSERT_NE(leaf, CellArena::Exhausted);
        optimal.average(leaf, p);
    }
    streaming.pull(1);
    optimal.pull(2);
    expectSameLevels(streaming, optimal);
    for (int l = 0; l <= depth; ++l) EXPECT_EQ(streaming.weights(l), optimal.weights(l));
    // Optimal packs the tables exactly: nothing is lost but chunk tails (< 8 cells each).
    std::uint64_t cells = 0;
    for (auto c : optimal.description().cellsPerLevel) cells += c;
    const std::uint64_t chunks = optimal.arena().chunks();
    EXPECT_LE(chunks * CellArena::ChunkCells, cells + 7 * chunks + CellArena::ChunkCells - 1);
    // A point outside the marked cells (every z here is above 0.5) is reported, not followed.
    auto probe = optimal.rootPath();
    EXPECT_EQ(optimal.findLeaf({63, 0, 0}, probe), CellArena::Exhausted);
    auto markProbe = optimal.rootPath();
    EXPECT_FALSE(optimal.mark({63, 0, 0}, depth - 1, markProbe));
}

TEST(ConstructionOctree, MatchesTheReferenceInAnyOrderAndBlockSize)
{
    // 40,000 leaves in a plane at depth 8: several visitLevel blocks; shuffled input exercises the
    // free lists and the path restart far from the previous point.
    Input in;
    std::mt19937 random(8);
    std::normal_distribution<float> g;
    for (int i = 0; i < 200; ++i)
        for (int j = 0; j < 200; ++j)
            in.add((i + 0.5) / 256.0 + 0.1, (j + 0.5) / 256.0 + 0.1, 0.5 + 0.001 * (i % 3), g(random), g(random), 1.0f);
    for (bool shuffle : {false, true}) {
        Input order = in;
        if (shuffle) {
            std::vector<std::size_t> perm(in.size());
            std::iota(perm.begin(), perm.end(), 0);
            std::shuffle(perm.begin(), perm.end(), random);
            order = {};
            for (std::size_t k : perm)
                order.add(in.positions[3 * k], in.positions[3 * k + 1], in.positions[3 * k + 2], in.normals[3 * k],
                          in.normals[3 * k + 1], in.normals[3 * k + 2]);
        }
        ConstructionOctree tree = populated(order, 8, false, oct, unitBox);
        tree.pull(2);
        tree.setThreads(shuffle ? 3 : 1);  // visitLevel walks the 40,000 leaves on 3 threads, or 1
        stylos::test::ReferenceOctree reference(order.positions, order.normals, {}, 8, oct, unitBox);
        expectSameLevels(tree, reference);
        EXPECT_EQ(tree.weights(8), reference.weights(8));
        EXPECT_EQ(tree.weights(3), reference.weights(3));
        std::size_t blocks = 0;
        tree.visitLevel(8, [&](const CellBlock& b) {
            ++blocks;
            EXPECT_LE(b.normals.size(), 16384u);
        });
        EXPECT_GE(blocks, 3u);
        // Construction bytes: close to 7 per cell in order; in random order the free lists take back
        // most released tables (without them a cell grown to k children costs k(k+1)/2 cells).
        std::uint64_t cells = 0;
        for (auto c : tree.description().cellsPerLevel) cells += c;
        EXPECT_LT(double(tree.bytes()) / double(cells), shuffle ? 11.0 : 7.6) << "shuffled " << shuffle;
    }
}

TEST(ConstructionOctree, RestartedDescentsEqualDescentsFromTheRoot)
{
    std::mt19937 random(2);
    std::uniform_real_distribution<double> u(0, 1);
    Input in;
    double x = 0.5, y = 0.5, z = 0.5;  // a random walk: neighbours share long prefixes
    for (int i = 0; i < 5000; ++i) {
        x = std::clamp(x + 0.002 * (u(random) - 0.5), 0.0, 1.0);
        y = std::clamp(y + 0.002 * (u(random) - 0.5), 0.0, 1.0);
        z = std::clamp(z + 0.002 * (u(random) - 0.5), 0.0, 1.0);
        in.add(x, y, z, float(u(random)), 1, 0);
    }
    ConstructionOctree cached = populated(in, 12);
    ConstructionOctree fresh(unitBox, 12, oct, false, 0);
    for (std::size_t i = 0; i < in.size(); ++i) {
        auto path = fresh.rootPath();
        ASSERT_TRUE(fresh.populate(in.prepared(i, unitBox, 12), path));
    }
    cached.pull(1);
    fresh.pull(1);
    expectSameLevels(cached, fresh);
}

TEST(ConstructionOctree, PopulateStopsAtTheMemoryLimit)
{
    const std::uint64_t limit = ConstructionOctree::minimumBytes(false);
    ConstructionOctree tree(unitBox, 10, oct, false, limit);
    auto path = tree.rootPath();
    std::mt19937 random(6);
    std::uniform_real_distribution<double> u(0, 1);
    Input in;
    for (int i = 0; i < 2000; ++i) in.add(u(random), u(random), u(random), 0, 0, 1);
    std::size_t inserted = 0;
    while (inserted < in.size() && tree.populate(in.prepared(inserted, unitBox, 10), path)) ++inserted;
    EXPECT_LT(inserted, in.size());
    EXPECT_GT(inserted, 100u);  // 2,048 cells hold a few hundred points of 10 levels
    EXPECT_LE(tree.bytes(), limit);
    EXPECT_EQ(tree.arena().chunks(), 1u);
}

TEST(ConstructionOctree, AllocateLevelRefusesBeforeAllocating)
{
    Input in;
    for (int i = 0; i < 8; ++i) in.add((i & 1) ? 0.75 : 0.25, (i & 2) ? 0.75 : 0.25, (i & 4) ? 0.75 : 0.25, 0, 0, 1);
    // Depth 11 with 8 points: 8 chains of 11 cells — under one chunk; a limit of one chunk holds it.
    ConstructionOctree fits(unitBox, 11, oct, false, ConstructionOctree::minimumBytes(false));
    for (int level = 0; level < 11; ++level) {
        auto path = fits.rootPath();
        for (std::size_t i = 0; i < in.size(); ++i) ASSERT_TRUE(fits.mark(in.prepared(i, unitBox, 11).coords, level, path));
        ASSERT_TRUE(fits.allocateLevel(level));
    }
    EXPECT_EQ(fits.description().cellsPerLevel.back(), 8u);
    // 2,100 points in distinct level-4 cells at depth 4 need more than one chunk at level 4.
    Input many;
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j)
            for (int k = 0; k < 9; ++k) many.add((i + 0.5) / 16, (j + 0.5) / 16, (k + 0.5) / 16, 0, 0, 1);
    ConstructionOctree tight(unitBox, 4, oct, false, ConstructionOctree::minimumBytes(false));
    int refused = -1;
    for (int level = 0; level < 4 && refused < 0; ++level) {
        auto path = tight.rootPath();
        for (std::size_t i = 0; i < many.size(); ++i) tight.mark(many.prepared(i, unitBox, 4).coords, level, path);
        const std::uint64_t chunksBefore = tight.arena().chunks();
        if (!tight.allocateLevel(level)) {
            refused = level;
            EXPECT_EQ(tight.arena().chunks(), chunksBefore);
            EXPECT_GT(tight.bytesAfterAllocating(level), tight.arena().limitBytes());
        }
    }
    EXPECT_EQ(refused, 3);  // level 4 holds 2,304 cells
}

TEST(ConstructionOctree, BatchedDescentsEqualSingleOnes)
{
    // markAll/findLeaves (groups of prefetched descents for far points, the path cache for near ones)
    // give what mark/findLeaf give one point at a time, on random and on coherent input.
    std::mt19937 random(12);
    std::uniform_real_distribution<double> u(0, 1);
    Input in;
    for (int i = 0; i < 4000; ++i) in.add(u(random), u(random), 0.3 + 0.4 * u(random), 0, 0, 1);
    double x = 0.2, y = 0.2;
    for (int i = 0; i < 4000; ++i) {  // a scan-like line
        x = std::min(0.99, x + 0.0003), y = std::min(0.99, y + 0.0001 * u(random));
        in.add(x, y, 0.5, 0, 0, 1);
    }
    const int depth = 9;
    std::vector<PreparedPoint> points;
    for (std::size_t i = 0; i < in.size(); ++i) points.push_back(in.prepared(i, unitBox, depth));
    ConstructionOctree single(unitBox, depth, oct, false, 0), batched(unitBox, depth, oct, false, 0);
    for (int level = 0; level < depth; ++level) {
        auto a = single.rootPath(), b = batched.rootPath();
        for (const PreparedPoint& p : points) ASSERT_TRUE(single.mark(p.coords, level, a));
        ASSERT_TRUE(batched.markAll(std::span(points).subspan(0, 5000), level, b));
        ASSERT_TRUE(batched.markAll(std::span(points).subspan(5000), level, b));
        ASSERT_TRUE(single.allocateLevel(level));
        ASSERT_TRUE(batched.allocateLevel(level));
        EXPECT_EQ(single.description().cellsPerLevel, batched.description().cellsPerLevel) << level;
    }
    std::vector<std::uint32_t> leaves(points.size());
    auto path = batched.rootPath();
    batched.findLeaves(points, leaves, path);
    auto one = batched.rootPath();
    for (std::size_t i = 0; i < points.size(); ++i) ASSERT_EQ(leaves[i], batched.findLeaf(points[i].coords, one)) << i;
    // Points outside the tree are reported by both.
    std::vector<PreparedPoint> outside(40, points[0]);
    for (std::size_t i = 0; i < outside.size(); ++i) outside[i].coords = {std::uint32_t(i), 0, 0};  // z = 0: empty
    std::vector<std::uint32_t> none(outside.size());
    batched.findLeaves(outside, none, path);
    for (std::uint32_t leaf : none) EXPECT_EQ(leaf, CellArena::Exhausted);
    auto markPath = batched.rootPath();
    EXPECT_FALSE(batched.markAll(outside, depth - 1, markPath));
}
