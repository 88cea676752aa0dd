// The construction octree's one-walk paths against the level-by-level ones they replace in the writer:
// visitLevels() (one depth-first walk), pullAndVisitLevels() (the pull handing out the cells), and
// descendantCounts() (several walks in turn) against OctreeLevels' defaults; and the writer's pending layers.
#include "stylos/core/octree/ConstructionOctree.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/octree/PoctWriter.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

using namespace stylos::core;
using namespace stylos::core::octree;
using stylos::test::TempDir;

namespace {

const RootBox unitBox{{0, 0, 0}, 1.0};

/** Every cell of a level, concatenated. */
struct LevelCells {
    std::vector<std::uint8_t> masks;
    std::vector<std::uint16_t> normals;
    std::vector<std::uint8_t> colours;
    bool operator==(const LevelCells&) const = default;
    void add(const CellBlock& b)
    {
        masks.insert(masks.end(), b.masks.begin(), b.masks.end());
        normals.insert(normals.end(), b.normals.begin(), b.normals.end());
        colours.insert(colours.end(), b.colours.begin(), b.colours.end());
    }
};

std::vector<LevelCells> byVisitLevel(const OctreeLevels& t)
{
    std::vector<LevelCells> levels(std::size_t(t.description().depth) + 1);
    for (int l = 0; l <= t.description().depth; ++l)
        t.visitLevel(l, [&](const CellBlock& b) { levels[std::size_t(l)].add(b); });
    return levels;
}

/** Points on a wavy sheet and a sphere (a tree with long chains and bushy parts), with colour. */
std::unique_ptr<ConstructionOctree> unpulled(int depth, bool colour, std::size_t n = 30000)
{
    auto tree = std::make_unique<ConstructionOctree>(unitBox, depth, NormalCodeKind::Octahedral16, colour, 0);
    auto path = tree->rootPath();
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> u(0, 1);
    for (std::size_t i = 0; i < n; ++i) {
        double p[3];
        float nrm[3];
        if (i % 3 == 0) {
            const double a = 2 * M_PI * u(random), z = 2 * u(random) - 1, r = std::sqrt(1 - z * z);
            p[0] = 0.7 + 0.2 * r * std::cos(a);
            p[1] = 0.7 + 0.2 * r * std::sin(a);
            p[2] = 0.5 + 0.2 * z;
            nrm[0] = float(r * std::cos(a)), nrm[1] = float(r * std::sin(a)), nrm[2] = float(z);
        } else {
            p[0] = 0.05 + 0.5 * u(random);
            p[1] = 0.05 + 0.9 * u(random);
            p[2] = 0.3 + 0.05 * std::sin(20 * p[0]);
            nrm[0] = float(-std::cos(20 * p[0])), nrm[1] = 0, nrm[2] = 1;
        }
        const std::uint8_t rgb[3] = {std::uint8_t(i), std::uint8_t(3 * i), std::uint8_t(7 * i)};
        EXPECT_TRUE(tree->populate(preparePoint(unitBox, depth, NormalCodeKind::Octahedral16, p, nrm, colour ? rgb : nullptr), path));
    }
    return tree;
}

} // namespace

TEST(OctreeOneWalk, VisitLevelsHandsEachLevelAsVisitLevelDoes)
{
    for (bool colour : {false, true}) {
        auto tree = unpulled(9, colour);
        tree->pull(2);
        const std::vector<LevelCells> expected = byVisitLevel(*tree);
        std::vector<LevelCells> got(expected.size());
        tree->visitLevels([&](int l, const CellBlock& b) { got[std::size_t(l)].add(b); });
        EXPECT_EQ(got, expected) << "colour " << colour;
        EXPECT_EQ(got.back().colours.size(), colour ? 3 * got.back().normals.size() : 0u);
        EXPECT_EQ(got.back().normals.size(), tree->description().cellsPerLevel.back());
    }
}

TEST(OctreeOneWalk, PullAndVisitEqualsPullThenVisitWhateverTheThreads)
{
    for (bool colour : {false, true}) {
        auto reference = unpulled(10, colour);
        reference->pull(1);
        const std::vector<LevelCells> expected = byVisitLevel(*reference);
        ASSERT_GT(reference->description().cellsPerLevel[4], 20u);
        for (unsigned threads : {1u, 2u, 4u}) {
            auto tree = unpulled(10, colour);
            std::vector<LevelCells> got(expected.size());
            std::map<int, int> calls;
            const std::function<void(int, const CellBlock&)> sink = [&](int l, const CellBlock& b) {
                got[std::size_t(l)].add(b);
                ++calls[l];
            };
            tree->pullAndVisitLevels(threads, &sink);
            EXPECT_EQ(got, expected) << threads << " threads, colour " << colour;
            EXPECT_EQ(byVisitLevel(*tree), expected) << "the tree is pulled too";
            EXPECT_GT(calls[10], 1) << "the leaves come in several blocks";
        }
        // A null sink is a plain pull.
        auto tree = unpulled(10, colour);
        tree->pullAndVisitLevels(3, nullptr);
        EXPECT_EQ(byVisitLevel(*tree), expected);
    }
}

TEST(OctreeOneWalk, DescendantCountsEqualTheLevelByLevelOnes)
{
    auto tree = unpulled(9, false);
    tree->pull(2);
    for (unsigned threads : {1u, 2u}) {
        tree->setThreads(threads);
        for (int ancestor : {0, 3, 5, 9}) {
            std::vector<int> levels;
            for (int l = 9; l >= ancestor; l -= 2) levels.push_back(l);
            levels.push_back(ancestor);
            const auto fast = tree->descendantCounts(ancestor, levels);
            const auto slow = tree->OctreeLevels::descendantCounts(ancestor, levels);
            EXPECT_EQ(fast, slow) << "ancestor level " << ancestor;
            ASSERT_EQ(fast.size(), levels.size());
            // Every level's counts add up to its cells; an ancestor counts itself once.
            for (std::size_t k = 0; k < levels.size(); ++k) {
                std::uint64_t sum = 0;
                for (std::uint64_t c : fast[k]) sum += c;
                EXPECT_EQ(sum, tree->description().cellsPerLevel[std::size_t(levels[k])]);
            }
            for (std::uint64_t c : fast.back()) EXPECT_EQ(c, 1u);
        }
    }
}

TEST(OctreeOneWalk, DescendantCountsOfAHandMadeTree)
{
    // Three points: two share a depth-2 cell's parent, one is alone in the other half of the box.
    ConstructionOctree tree(unitBox, 3, NormalCodeKind::Octahedral16, false, 0);
    auto path = tree.rootPath();
    const float n[3] = {0, 0, 1};
    for (const std::array<double, 3> p : {std::array<double, 3>{0.1, 0.1, 0.1}, {0.2, 0.1, 0.1}, {0.9, 0.9, 0.9}})
        ASSERT_TRUE(tree.populate(preparePoint(unitBox, 3, NormalCodeKind::Octahedral16, p.data(), n, nullptr), path));
    tree.pull(1);
    const std::array<int, 3> levels{1, 2, 3};
    const auto counts = tree.descendantCounts(1, levels);
    ASSERT_EQ(counts.size(), 3u);
    EXPECT_EQ(counts[0], (std::vector<std::uint64_t>{1, 1}));
    EXPECT_EQ(counts[1], (std::vector<std::uint64_t>{1, 1}));  // (0.1, 0.2) share the depth-2 cell of edge 1/4
    EXPECT_EQ(counts[2], (std::vector<std::uint64_t>{2, 1}));  // leaves of edge 1/8: 0.1 and 0.2 differ
}

TEST(OctreeOneWalk, PendingLayerWritesTheSameFileAsAGivenOne)
{
    TempDir dir;
    auto tree = unpulled(8, true);
    tree->pull(2);
    const std::uint64_t leaves = tree->description().cellsPerLevel.back();
    AttributeLayer layer{"ambient", AttributeType::Float32, 1, std::vector<std::uint8_t>(4 * leaves)};
    for (std::size_t i = 0; i < layer.bytes.size(); ++i) layer.bytes[i] = std::uint8_t(i * 13);
    ASSERT_TRUE(writePoct(*tree, dir / "given.poct", std::span<const AttributeLayer>(&layer, 1)).ok());
    int finished = 0;
    const PendingLayer pending{"ambient", AttributeType::Float32, 1, [&] {
                                   ++finished;
                                   return layer;
                               }};
    ASSERT_TRUE(writePoct(*tree, dir / "pending.poct", {}, std::span<const PendingLayer>(&pending, 1)).ok());
    EXPECT_EQ(finished, 1);
    EXPECT_EQ(stylos::test::readBytes(dir / "pending.poct"), stylos::test::readBytes(dir / "given.poct"));

    // A pending layer that comes back the wrong size, or under another name, is refused; nothing is left.
    const PendingLayer shortLayer{"ambient", AttributeType::Float32, 1, [&] {
                                      AttributeLayer l = layer;
                                      l.bytes.resize(l.bytes.size() - 4);
                                      return l;
                                  }};
    auto r = writePoct(*tree, dir / "short.poct", {}, std::span<const PendingLayer>(&shortLayer, 1));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(r.error().message.find("expected " + std::to_string(4 * leaves)), std::string::npos) << r.error().message;
    const PendingLayer renamed{"ambient", AttributeType::Float32, 1, [&] {
                                   AttributeLayer l = layer;
                                   l.name = "other";
                                   return l;
                               }};
    r = writePoct(*tree, dir / "renamed.poct", {}, std::span<const PendingLayer>(&renamed, 1));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("came back as \"other\""), std::string::npos) << r.error().message;
    EXPECT_FALSE(std::filesystem::exists(dir / "short.poct"));
    EXPECT_FALSE(std::filesystem::exists(dir / "renamed.poct"));
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++files;
    EXPECT_EQ(files, 2u);
}
