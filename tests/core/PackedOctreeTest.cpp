// Reading .poct files: round trips against the reference octree (every cell), the child index, level
// iteration, attribute layers, rewriting, open errors, and a large file.
#include "PoctTestSupport.h"
#include "QuadTreeLevels.h"
#include "ReferenceOctree.h"
#include "TestSupport.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/synth/SyntheticStream.h"
#include "stylos/core/util/Hash64.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

using namespace stylos::core;
using namespace stylos::core::octree;
using stylos::test::ManualOctree;
using stylos::test::ReferenceOctree;
using stylos::test::TempDir;
using stylos::test::fileBytes;

namespace {

ReferenceOctree cloudTree(int points, int depth, bool colour, std::uint64_t seed,
                          NormalCodeKind kind = NormalCodeKind::Octahedral16)
{
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g;
    std::vector<double> p;
    std::vector<float> n;
    std::vector<std::uint8_t> c;
    for (int i = 0; i < points; ++i) {
        // Clustered points: dense and sparse regions, so masks of every popcount occur.
        const double s = (i % 3 == 0) ? 0.05 : 1.0;
        p.insert(p.end(), {1000.0 + s * g(rng), -20.0 + s * g(rng), 5.0 + s * g(rng)});
        n.insert(n.end(), {float(g(rng)), float(g(rng)), float(g(rng))});
        if (colour) c.insert(c.end(), {std::uint8_t(rng()), std::uint8_t(rng()), std::uint8_t(rng())});
    }
    return ReferenceOctree(p, n, c, depth, kind);
}

PackedOctree openOrDie(const std::filesystem::path& p)
{
    auto r = PackedOctree::open(p);
    EXPECT_TRUE(r.ok()) << r.error().message;
    return std::move(r).value();
}

/** Every cell of @p o equals the reference's: description, masks, normals, children, coordinates, centres. */
void expectSameCells(const PackedOctree& o, const ReferenceOctree& ref)
{
    ASSERT_EQ(o.description(), ref.description());
    std::uint64_t total = 0;
    for (int l = 0; l <= o.depth(); ++l) {
        const std::size_t n = ref.cellCount(l);
        ASSERT_EQ(o.cellCount(l), n);
        total += n;
        for (std::size_t i = 0; i < n; ++i) {
            ASSERT_EQ(o.normalCode(l, i), ref.normals(l)[i]) << l << " " << i;
            if (l < o.depth()) {
                ASSERT_EQ(o.mask(l, i), ref.masks(l)[i]) << l << " " << i;
                ASSERT_EQ(o.firstChild(l, i), ref.firstChild(l, i)) << l << " " << i;
            } else {
                ASSERT_EQ(o.mask(l, i), 0);
            }
        }
        std::uint64_t next = 0;
        o.forEachCell(l, [&](const CellView& c) {
            EXPECT_EQ(c.level, l);
            EXPECT_EQ(c.index, next);
            EXPECT_EQ(c.coords, ref.coords(l, c.index));
            EXPECT_EQ(c.centre, o.box().cellCentre(l, c.coords[0], c.coords[1], c.coords[2]));
            EXPECT_EQ(c.size, o.box().cellSize(l));
            EXPECT_EQ(c.normal, decodeNormal(o.description().normalCode, ref.normals(l)[c.index]));
            EXPECT_EQ(c.mask, l < o.depth() ? ref.masks(l)[c.index] : 0);
            ++next;
            return true;
        });
        EXPECT_EQ(next, n);
    }
    EXPECT_EQ(o.totalCells(), total);
}

} // namespace

TEST(PackedOctree, RoundTripOfTheReferenceTreeWithColour)
{
    TempDir dir;
    const auto ref = cloudTree(20000, 8, true, 5);
    const auto path = dir / "t.poct";
    auto size = writePoct(ref, path);
    ASSERT_TRUE(size.ok()) << size.error().message;
    const auto o = openOrDie(path);
    EXPECT_EQ(o.fileBytes(), *size);
    EXPECT_EQ(o.path(), path);
    expectSameCells(o, ref);
    auto colour = o.attribute("colour");
    ASSERT_TRUE(colour.has_value());
    EXPECT_EQ(colour->type, AttributeType::UInt8);
    EXPECT_EQ(colour->components, 3);
    EXPECT_TRUE(std::equal(colour->bytes.begin(), colour->bytes.end(), ref.colours().begin(), ref.colours().end()));
    EXPECT_EQ(o.attributes().size(), 1u);
    EXPECT_FALSE(o.attribute("ambient").has_value());
    EXPECT_GT(o.indexBytes(), 0u);
}

TEST(PackedOctree, RoundTripWithThePaperCodeAndWithoutColour)
{
    TempDir dir;
    const auto ref = cloudTree(5000, 11, false, 9, NormalCodeKind::Paper15);
    ASSERT_TRUE(writePoct(ref, dir / "t.poct").ok());
    const auto o = openOrDie(dir / "t.poct");
    EXPECT_EQ(o.description().normalCode, NormalCodeKind::Paper15);
    EXPECT_FALSE(o.description().hasColour);
    EXPECT_TRUE(o.attributes().empty());
    expectSameCells(o, ref);
}

TEST(PackedOctree, FromBytesEqualsOpen)
{
    TempDir dir;
    const auto ref = cloudTree(3000, 6, true, 2);
    ASSERT_TRUE(writePoct(ref, dir / "t.poct").ok());
    auto o = PackedOctree::fromBytes(fileBytes(dir / "t.poct"), "image");
    ASSERT_TRUE(o.ok()) << o.error().message;
    EXPECT_EQ(o->path(), "image");
    expectSameCells(*o, ref);
    // Moving keeps the views valid.
    PackedOctree moved = std::move(o).value();
    EXPECT_EQ(moved.root().mask, ref.masks(0)[0]);
}

TEST(PackedOctree, RootCellAndStoppingEarly)
{
    TempDir dir;
    auto tree = ManualOctree::twoLevels(0x96);  // slots 1, 2, 4, 7
    tree.mutableDescription().box = RootBox{{10, 20, 30}, 4.0};
    ASSERT_TRUE(writePoct(tree, dir / "t.poct").ok());
    const auto o = openOrDie(dir / "t.poct");
    const CellView r = o.root();
    EXPECT_EQ(r.level, 0);
    EXPECT_EQ(r.mask, 0x96);
    EXPECT_EQ(r.centre, (std::array<double, 3>{12, 22, 32}));
    EXPECT_EQ(r.size, 4.0);
    EXPECT_EQ(o.firstChild(0, 0), 0u);
    std::vector<std::array<std::uint32_t, 3>> coords;
    o.forEachCell(1, [&](const CellView& c) {
        coords.push_back(c.coords);
        EXPECT_EQ(c.size, 2.0);
        return coords.size() < 3;
    });
    EXPECT_EQ(coords, (std::vector<std::array<std::uint32_t, 3>>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}));
    const CellView c = o.cell(1, 3, {1, 1, 1});
    EXPECT_EQ(c.centre, (std::array<double, 3>{13, 23, 33}));
    EXPECT_EQ(c.normal,
              decodeNormal(NormalCodeKind::Octahedral16, encodeNormal(NormalCodeKind::Octahedral16, 1, 1, 1)));
    EXPECT_EQ(o.levelMasks(0).size(), 1u);
    EXPECT_TRUE(o.levelMasks(1).empty());
    EXPECT_EQ(o.levelNormalCodes(1).size(), 4u);
}

TEST(PackedOctree, FirstChildOnWideLevels)
{
    // A level of 8^4 = 4096 cells with every mask full, and one of mixed masks: the prefix index
    // across 64-cell blocks and the partial-word popcounts at every offset.
    TempDir dir;
    const auto ref = cloudTree(60000, 5, false, 17);
    ASSERT_TRUE(writePoct(ref, dir / "t.poct").ok());
    const auto o = openOrDie(dir / "t.poct");
    for (int l = 0; l < o.depth(); ++l) {
        std::uint64_t expected = 0;
        for (std::uint64_t i = 0; i < o.cellCount(l); ++i) {
            ASSERT_EQ(o.firstChild(l, i), expected) << l << " " << i;
            expected += static_cast<std::uint64_t>(std::popcount(o.mask(l, i)));
        }
        EXPECT_EQ(expected, o.cellCount(l + 1));
    }
    EXPECT_GT(o.cellCount(4), 1000u);
}

TEST(PackedOctree, LevelsAdapterRewritesTheSameBytes)
{
    TempDir dir;
    const auto ref = cloudTree(4000, 7, true, 3);
    ASSERT_TRUE(writePoct(ref, dir / "a.poct").ok());
    const auto o = openOrDie(dir / "a.poct");
    EXPECT_EQ(o.levels().description(), ref.description());
    ASSERT_TRUE(writePoct(o.levels(), dir / "b.poct").ok());
    EXPECT_EQ(fileBytes(dir / "a.poct"), fileBytes(dir / "b.poct"));
}

TEST(PackedOctree, SetAttributeLayerAddsAndReplaces)
{
    TempDir dir;
    const auto path = dir / "t.poct";
    const auto ref = cloudTree(2000, 6, true, 4);
    ASSERT_TRUE(writePoct(ref, path).ok());
    const std::uint64_t leaves = ref.cellCount(6);
    std::vector<std::uint8_t> ao(4 * leaves);
    for (std::size_t i = 0; i < ao.size(); ++i) ao[i] = static_cast<std::uint8_t>(i * 7);
    auto added = setPoctAttributeLayer(path, {"ambient", AttributeType::Float32, 1, ao});
    ASSERT_TRUE(added.ok()) << added.error().message;
    {
        const auto o = openOrDie(path);
        EXPECT_EQ(o.fileBytes(), *added);
        expectSameCells(o, ref);
        const auto layers = o.attributes();
        ASSERT_EQ(layers.size(), 2u);
        EXPECT_EQ(layers[0].name, "colour");
        EXPECT_TRUE(
            std::equal(layers[0].bytes.begin(), layers[0].bytes.end(), ref.colours().begin(), ref.colours().end()));
        EXPECT_EQ(layers[1].name, "ambient");
        EXPECT_EQ(layers[1].type, AttributeType::Float32);
        EXPECT_TRUE(std::equal(layers[1].bytes.begin(), layers[1].bytes.end(), ao.begin(), ao.end()));
    }
    // Replace it (another type), then add a class layer: order is kept.
    std::vector<std::uint8_t> ao8(leaves, 9);
    ASSERT_TRUE(setPoctAttributeLayer(path, {"ambient", AttributeType::UInt8, 1, ao8}).ok());
    std::vector<std::uint8_t> cls(2 * leaves, 1);
    ASSERT_TRUE(setPoctAttributeLayer(path, {"class", AttributeType::UInt16, 1, cls}).ok());
    // Replace the colour itself.
    std::vector<std::uint8_t> grey(3 * leaves, 128);
    ASSERT_TRUE(setPoctAttributeLayer(path, {"colour", AttributeType::UInt8, 3, grey}).ok());
    const auto o = openOrDie(path);
    const auto layers = o.attributes();
    ASSERT_EQ(layers.size(), 3u);
    EXPECT_EQ(layers[0].name, "colour");
    EXPECT_TRUE(std::all_of(layers[0].bytes.begin(), layers[0].bytes.end(), [](auto b) { return b == 128; }));
    EXPECT_EQ(layers[1].name, "ambient");
    EXPECT_EQ(layers[1].type, AttributeType::UInt8);
    EXPECT_EQ(layers[1].bytes.size(), leaves);
    EXPECT_EQ(layers[2].name, "class");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}

TEST(PackedOctree, SetAttributeLayerRefusesBadLayersAndKeepsTheFile)
{
    TempDir dir;
    const auto path = dir / "t.poct";
    ASSERT_TRUE(writePoct(ManualOctree::twoLevels(0x81), path).ok());
    const auto before = fileBytes(path);
    auto expectRefused = [&](const AttributeLayer& layer, ErrorCode code) {
        auto r = setPoctAttributeLayer(path, layer);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, code) << r.error().message;
        EXPECT_NE(r.error().message.find(path.string()), std::string::npos);
    };
    expectRefused({"ambient", AttributeType::Float32, 1, std::vector<std::uint8_t>(7)}, ErrorCode::InvalidArgument);
    expectRefused({"bad name", AttributeType::UInt8, 1, {1, 2}}, ErrorCode::InvalidArgument);
    expectRefused({"colour", AttributeType::UInt8, 1, {1, 2}}, ErrorCode::InvalidArgument);
    EXPECT_EQ(fileBytes(path), before);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
    // Adding a colour layer to an octree without colour makes it coloured.
    ASSERT_TRUE(setPoctAttributeLayer(path, {"colour", AttributeType::UInt8, 3, std::vector<std::uint8_t>(6, 5)}).ok());
    EXPECT_TRUE(openOrDie(path).description().hasColour);
    // Errors of open come through.
    auto missing = setPoctAttributeLayer(dir / "none.poct", {"a", AttributeType::UInt8, 1, {1}});
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
}

TEST(PackedOctree, OpenErrors)
{
    TempDir dir;
    auto missing = PackedOctree::open(dir / "none.poct");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
    EXPECT_NE(missing.error().message.find("none.poct"), std::string::npos);

    stylos::test::writeText(dir / "empty.poct", "");
    auto empty = PackedOctree::open(dir / "empty.poct");
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.error().code, ErrorCode::Empty);

    auto folder = PackedOctree::open(dir.path());
    ASSERT_FALSE(folder.ok());
    EXPECT_EQ(folder.error().code, ErrorCode::Unreadable);

    stylos::test::writeText(dir / "cloud.ply", "ply\nformat ascii 1.0\nelement vertex 0\nend_header\n");
    auto ply = PackedOctree::open(dir / "cloud.ply");
    ASSERT_FALSE(ply.ok());
    EXPECT_EQ(ply.error().code, ErrorCode::UnknownFormat);
    EXPECT_NE(ply.error().message.find("bad magic"), std::string::npos);
    EXPECT_FALSE(isPoctSignature(std::vector<std::uint8_t>{'p', 'l', 'y', '\n', 0, 0, 0, 0}));
}

TEST(PackedOctree, NewerVersionIsUnsupported)
{
    TempDir dir;
    ASSERT_TRUE(writePoct(ManualOctree::twoLevels(0x0F), dir / "t.poct").ok());
    auto bytes = fileBytes(dir / "t.poct");
    EXPECT_TRUE(isPoctSignature(bytes));
    bytes[8] = 2; // version 2, header checksum not even looked at
    auto r = PackedOctree::fromBytes(bytes, "v2.poct");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::Unsupported);
    EXPECT_EQ(r.error().message, "v2.poct: byte 8: version 2 is newer than this program reads (version 1)");
}

TEST(PackedOctree, OpensALargeFile)
{
    // Its speed is a benchmark (BM_PackedOctreeOpen in tests/benchmarks/FileOpenBenchmark.cpp), not a test.
    TempDir dir(stylos::test::fastTempBase());
    const stylos::test::QuadTreeLevels tree(11); // 5.6 M cells, 12 MB
    const auto path = dir / "big.poct";
    auto size = writePoct(tree, path);
    ASSERT_TRUE(size.ok()) << size.error().message;
    auto o = PackedOctree::open(path);
    ASSERT_TRUE(o.ok()) << o.error().message;
    EXPECT_EQ(o->totalCells(), ((std::uint64_t(1) << 24) - 1) / 3); // (4^12 − 1) / 3
    EXPECT_EQ(o->firstChild(10, o->cellCount(10) - 1), o->cellCount(11) - 4);
    EXPECT_EQ(o->cellCount(11), std::uint64_t(1) << 22);
}
