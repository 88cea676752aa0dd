// The .poct writer: the exact byte layout of docs/file-format.md on a hand-made tree, determinism,
// size per cell on a generated drum, atomic writes and every refused argument.
#include "PoctTestSupport.h"
#include "ReferenceOctree.h"
#include "TestSupport.h"
#include "stylos/core/octree/PoctWriter.h"
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
using stylos::test::valueAt;
using stylos::test::fileBytes;

namespace {

std::size_t entriesIn(const std::filesystem::path& dir)
{
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

/** A random cloud with normals and colours, as a reference octree. */
ReferenceOctree randomTree(int points, int depth, bool colour, std::uint64_t seed, std::size_t blockCells = 4096)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> p;
    std::vector<float> n;
    std::vector<std::uint8_t> c;
    for (int i = 0; i < points; ++i) {
        const double x = u(rng), y = u(rng);
        p.insert(p.end(), {x + 100.0, y - 50.0, 0.3 * x * y});
        n.insert(n.end(), {float(u(rng)), float(u(rng)), 1.0f});
        if (colour) c.insert(c.end(), {std::uint8_t(rng()), std::uint8_t(rng()), std::uint8_t(rng())});
    }
    return ReferenceOctree(p, n, c, depth, NormalCodeKind::Octahedral16, std::nullopt, blockCells);
}

} // namespace

TEST(PoctWriter, ByteLayoutOfTheSmallestTree)
{
    TempDir dir;
    auto tree = ManualOctree::twoLevels(0x29, true); // slots 0, 3, 5
    tree.mutableDescription().box = RootBox{{1.5, -2.0, 3.25}, 0.75};
    tree.mutableDescription().points = 7;
    const auto path = dir / "t.poct";
    auto written = writePoct(tree, path);
    ASSERT_TRUE(written.ok()) << written.error().message;
    const auto b = fileBytes(path);
    // Header: 64 fixed + 8 × 2 levels + 48 × 3 sections + 8 checksum = 232 bytes.
    const std::uint8_t magic[8] = {0x89, 'P', 'O', 'C', 'T', '\r', '\n', 0x1A};
    EXPECT_EQ(std::memcmp(b.data(), magic, 8), 0);
    EXPECT_EQ(valueAt<std::uint32_t>(b, 8), 1u);
    EXPECT_EQ(valueAt<std::uint32_t>(b, 12), 232u);
    EXPECT_EQ(valueAt<double>(b, 16), 1.5);
    EXPECT_EQ(valueAt<double>(b, 24), -2.0);
    EXPECT_EQ(valueAt<double>(b, 32), 3.25);
    EXPECT_EQ(valueAt<double>(b, 40), 0.75);
    EXPECT_EQ(valueAt<std::uint64_t>(b, 48), 7u);
    EXPECT_EQ(b[56], 1);            // depth
    EXPECT_EQ(b[57], 1);            // Octahedral16
    EXPECT_EQ(valueAt<std::uint16_t>(b, 58), 0u);
    EXPECT_EQ(valueAt<std::uint32_t>(b, 60), 3u);
    EXPECT_EQ(valueAt<std::uint64_t>(b, 64), 1u);
    EXPECT_EQ(valueAt<std::uint64_t>(b, 72), 3u);
    // Sections: masks at 256 (1 byte), normals at 320 (8 bytes), colour at 384 (9 bytes): 393 bytes.
    ASSERT_EQ(b.size(), 393u);
    ASSERT_EQ(*written, 393u);
    struct Expected { const char* name; std::uint8_t kind, type, comps; std::uint64_t offset, length; };
    const Expected sections[3] = {
        {"masks", 1, 1, 1, 256, 1}, {"normals", 2, 2, 1, 320, 8}, {"colour", 3, 1, 3, 384, 9}};
    for (int s = 0; s < 3; ++s) {
        const std::size_t e = 80 + 48 * s;
        char name[17] = {};
        std::memcpy(name, b.data() + e, 16);
        EXPECT_STREQ(name, sections[s].name);
        EXPECT_EQ(b[e + 16], sections[s].kind);
        EXPECT_EQ(b[e + 17], sections[s].type);
        EXPECT_EQ(b[e + 18], sections[s].comps);
        for (int r = 19; r < 24; ++r) EXPECT_EQ(b[e + r], 0);
        EXPECT_EQ(valueAt<std::uint64_t>(b, e + 24), sections[s].offset);
        EXPECT_EQ(valueAt<std::uint64_t>(b, e + 32), sections[s].length);
        EXPECT_EQ(valueAt<std::uint64_t>(b, e + 40), xxh64(b.data() + sections[s].offset, sections[s].length));
    }
    EXPECT_EQ(valueAt<std::uint64_t>(b, 224), xxh64(b.data(), 224));
    for (std::size_t i = 232; i < 256; ++i) EXPECT_EQ(b[i], 0) << i; // padding
    EXPECT_EQ(b[256], 0x29);
    const std::uint16_t root = encodeNormal(NormalCodeKind::Octahedral16, 0, 0, 1);
    EXPECT_EQ(valueAt<std::uint16_t>(b, 320), root);
    EXPECT_EQ(valueAt<std::uint16_t>(b, 322), encodeNormal(NormalCodeKind::Octahedral16, -1, -1, -1));
    EXPECT_EQ(valueAt<std::uint16_t>(b, 324), encodeNormal(NormalCodeKind::Octahedral16, 1, 1, -1));
    const std::vector<std::uint8_t> colours(b.begin() + 384, b.end());
    EXPECT_EQ(colours, (std::vector<std::uint8_t>{0, 0, 200, 30, 60, 200, 50, 100, 200}));
}

TEST(PoctWriter, DeterministicWhateverTheBlockSize)
{
    TempDir dir;
    const auto a = randomTree(5000, 7, true, 1, 4096);
    const auto b = randomTree(5000, 7, true, 1, 13);
    ASSERT_TRUE(writePoct(a, dir / "a.poct").ok());
    ASSERT_TRUE(writePoct(a, dir / "a2.poct").ok());
    ASSERT_TRUE(writePoct(b, dir / "b.poct").ok());
    const auto bytes = fileBytes(dir / "a.poct");
    EXPECT_EQ(bytes, fileBytes(dir / "a2.poct"));
    EXPECT_EQ(bytes, fileBytes(dir / "b.poct"));
    // A different tree gives different bytes.
    ASSERT_TRUE(writePoct(randomTree(5000, 7, true, 2), dir / "c.poct").ok());
    EXPECT_NE(bytes, fileBytes(dir / "c.poct"));
    EXPECT_EQ(entriesIn(dir.path()), 4u); // no temporary left
}

TEST(PoctWriter, UnderThreeBytesPerCellOnAGeneratedDrum)
{
    synth::SyntheticStreamOptions o;
    o.points = 200'000;
    auto reader = synth::openSyntheticStream(o);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    auto all = stylos::test::readAllPoints(**reader, 65536);
    ASSERT_TRUE(all.ok());
    const auto tree = ReferenceOctree::fromBatch(*all, 9);
    TempDir dir;
    auto size = writePoct(tree, dir / "drum.poct");
    ASSERT_TRUE(size.ok()) << size.error().message;
    std::uint64_t cells = 0;
    for (auto c : tree.description().cellsPerLevel) cells += c;
    const double perCell = double(*size) / double(cells);
    std::printf("drum: %llu cells, %llu bytes, %.3f bytes per cell\n", (unsigned long long)cells,
                (unsigned long long)*size, perCell);
    EXPECT_LT(perCell, 3.0);
    EXPECT_GT(perCell, 2.0);  // 2 bytes of normal per cell plus a mask per inner cell
}

TEST(PoctWriter, ExtraLayersAreWrittenAfterTheColour)
{
    TempDir dir;
    const auto tree = ManualOctree::twoLevels(0x81, true);
    AttributeLayer ao{"ambient", AttributeType::Float32, 1, std::vector<std::uint8_t>(8, 0x3F)};
    AttributeLayer cls{"class", AttributeType::UInt16, 2, std::vector<std::uint8_t>(8, 7)};
    const std::vector<AttributeLayer> layers{ao, cls};
    auto size = writePoct(tree, dir / "t.poct", layers);
    ASSERT_TRUE(size.ok()) << size.error().message;
    const auto b = fileBytes(dir / "t.poct");
    EXPECT_EQ(valueAt<std::uint32_t>(b, 60), 5u);
    const std::size_t table = 64 + 16;
    EXPECT_STREQ(reinterpret_cast<const char*>(b.data() + table + 2 * 48), "colour");
    EXPECT_STREQ(reinterpret_cast<const char*>(b.data() + table + 3 * 48), "ambient");
    EXPECT_EQ(b[table + 3 * 48 + 17], 3);
    EXPECT_STREQ(reinterpret_cast<const char*>(b.data() + table + 4 * 48), "class");
    EXPECT_EQ(b[table + 4 * 48 + 18], 2);
    EXPECT_EQ(valueAt<std::uint64_t>(b, table + 4 * 48 + 32), 8u);
}

TEST(PoctWriter, RefusesBadLayers)
{
    TempDir dir;
    const auto tree = ManualOctree::twoLevels(0x81, true); // 2 leaves, with colour
    const auto path = dir / "t.poct";
    auto refused = [&](std::vector<AttributeLayer> layers, const std::string& fragment) {
        auto r = writePoct(tree, path, layers);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument);
        EXPECT_NE(r.error().message.find(path.string()), std::string::npos) << r.error().message;
        EXPECT_NE(r.error().message.find(fragment), std::string::npos) << r.error().message;
    };
    refused({{"", AttributeType::UInt8, 1, {1, 2}}}, "empty");
    refused({{"sixteen_chars_xx", AttributeType::UInt8, 1, {1, 2}}}, "longer than 15");
    refused({{"a b", AttributeType::UInt8, 1, {1, 2}}}, "ASCII");
    refused({{"normals", AttributeType::UInt8, 1, {1, 2}}}, "reserved");
    refused({{"ao", AttributeType::UInt8, 1, {1, 2, 3}}}, "expected 2");
    refused({{"ao", AttributeType::Float32, 1, {1, 2}}}, "expected 8");
    refused({{"ao", AttributeType::UInt8, 0, {}}}, "components");
    refused({{"ao", AttributeType::UInt8, 17, std::vector<std::uint8_t>(34)}}, "components");
    refused({{"ao", static_cast<AttributeType>(9), 1, {1, 2}}}, "unknown element type");
    refused({{"ao", AttributeType::UInt8, 1, {1, 2}}, {"ao", AttributeType::UInt8, 1, {1, 2}}}, "twice");
    refused({{"colour", AttributeType::UInt8, 3, std::vector<std::uint8_t>(6)}}, "twice");
    std::vector<AttributeLayer> many;
    for (int i = 0; i < 32; ++i) {
        std::string name = "l";
        name += std::to_string(i); // (not "l" + to_string: GCC 12 warns falsely, -Wrestrict)
        many.push_back({name, AttributeType::UInt8, 1, {1, 2}});
    }
    refused(many, "more than 32");
    // Without colour, "colour" must still be 3 × UInt8.
    const auto plain = ManualOctree::twoLevels(0x81, false);
    auto r = writePoct(plain, path, std::vector<AttributeLayer>{{"colour", AttributeType::UInt8, 1, {1, 2}}});
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("3 × UInt8"), std::string::npos);
    EXPECT_EQ(entriesIn(dir.path()), 0u);
}

TEST(PoctWriter, RefusesInconsistentTreesAndLeavesNothing)
{
    TempDir dir;
    const auto path = dir / "t.poct";
    stylos::test::writeText(path, "previous content");
    auto refused = [&](const OctreeLevels& t, const std::string& fragment) {
        auto r = writePoct(t, path);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument);
        EXPECT_NE(r.error().message.find(fragment), std::string::npos) << r.error().message;
        EXPECT_EQ(entriesIn(dir.path()), 1u);
        EXPECT_EQ(stylos::test::readBytes(path).size(), 16u); // the old file is untouched
    };
    OctreeDescription d;
    const std::uint16_t z = encodeNormal(d.normalCode, 0, 0, 1);
    // Root mask announces 2 children, level 1 has 3 cells.
    refused(ManualOctree(d, {{{0x03}, {z}, {}}, {{}, {z, z, z}, {}}}), "child masks give 2 children");
    // An inner cell without children.
    refused(ManualOctree(d, {{{0x03}, {z}, {}}, {{0x01, 0x00}, {z, z}, {}}, {{}, {z}, {}}}), "has no children");
    // Fewer masks than cells.
    refused(ManualOctree(d, {{{}, {z}, {}}, {{}, {z}, {}}}), "0 masks for 1 cells");
    // Colour announced but missing.
    OctreeDescription dc = d;
    dc.hasColour = true;
    refused(ManualOctree(dc, {{{0x01}, {z}, {}}, {{}, {z}, {}}}), "0 colour bytes for 1 cells");
    // A description that contradicts the cells delivered.
    ManualOctree wrongCount(d, {{{0x01}, {z}, {}}, {{}, {z, z}, {}}});
    wrongCount.mutableDescription().cellsPerLevel = {1, 1};
    refused(wrongCount, "level 1 delivered 2 cells");
    // Depth out of range, bad box.
    ManualOctree deep(d, {{{}, {z}, {}}});
    refused(deep, "depth 0 outside 1..21");
    ManualOctree badBox = ManualOctree::twoLevels(0x01);
    badBox.mutableDescription().box.size = 0;
    refused(badBox, "root box");
}

TEST(PoctWriter, WriteFailedNamesTheFileAndTheSystemError)
{
    TempDir dir;
    const auto path = dir / "missing-folder" / "t.poct";
    auto r = writePoct(ManualOctree::twoLevels(0x01), path);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(r.error().message.find(path.string()), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find("No such file or directory"), std::string::npos) << r.error().message;
    EXPECT_EQ(entriesIn(dir.path()), 0u);
}

namespace {

/** Cancels at the n-th update. */
class CancelAt final : public ProgressSink {
public:
    explicit CancelAt(int n) : m_n(n) {}
    void update(double fraction) override
    {
        ++m_updates;
        m_last = fraction;
    }
    bool isCancelRequested() const override { return m_n > 0 && m_updates >= m_n; }
    int m_n;
    int m_updates = 0;
    double m_last = 0;
};

} // namespace

TEST(PoctWriter, ReportsProgressAndCancelsCleanly)
{
    TempDir dir;
    const auto tree = randomTree(3000, 6, true, 8, 100);
    CancelAt never(0);
    ASSERT_TRUE(writePoct(tree, dir / "a.poct", {}, &never).ok());
    EXPECT_GT(never.m_updates, 10);
    EXPECT_EQ(never.m_last, 1.0);
    CancelAt third(3);
    auto r = writePoct(tree, dir / "b.poct", {}, &third);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::Cancelled);
    EXPECT_EQ(third.m_updates, 3);
    EXPECT_EQ(entriesIn(dir.path()), 1u);
}
