// A .poct written before XXH64 moved to libxxhash (tests/data/fragment-v1.poct, stylos-cli at 18eb8c3)
// still opens: every section checksum verifies, the cells are those that were written, and writing
// the same octree again gives the same bytes, checksums included.
#include "stylos/core/octree/PackedOctree.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cstring>

namespace fs = std::filesystem;
using stylos::core::octree::AttributeLayer;
using stylos::core::octree::AttributeType;
using stylos::core::octree::NormalCodeKind;
using stylos::core::octree::PackedOctree;

namespace {

const fs::path Fixture = fs::path(STYLOS_TEST_DATA) / "fragment-v1.poct";

float ambientAt(const stylos::core::octree::AttributeView& layer, std::size_t leaf)
{
    float v = 0;
    std::memcpy(&v, layer.bytes.data() + 4 * leaf, 4);
    return v;
}

} // namespace

TEST(PoctFixture, AFileWrittenBeforeTheLibraryChangeOpens)
{
    auto opened = PackedOctree::open(Fixture);
    ASSERT_TRUE(opened.ok()) << opened.error().message;
    const PackedOctree& tree = *opened;
    const auto& d = tree.description();
    EXPECT_EQ(d.depth, 6);
    EXPECT_EQ(d.points, 597u);
    EXPECT_EQ(d.cellsPerLevel, (std::vector<std::uint64_t>{1, 8, 40, 152, 439, 572, 591}));
    EXPECT_EQ(tree.totalCells(), 1803u);
    EXPECT_EQ(tree.fileBytes(), 7548u);
    EXPECT_EQ(d.normalCode, NormalCodeKind::Octahedral16);
    EXPECT_FALSE(d.hasColour);
    EXPECT_EQ(d.box.origin, (std::array<double, 3>{1000.5146031045621, 1999.6232491905753, 49.9410641178697}));
    EXPECT_EQ(d.box.size, 0.47134976320285205);
    const auto ambient = tree.attribute("ambient");
    ASSERT_TRUE(ambient.has_value());
    EXPECT_EQ(ambient->type, AttributeType::Float32);
    EXPECT_EQ(ambient->components, 1);
    ASSERT_EQ(ambient->bytes.size(), 591u * 4);
    // What `ao --directions 16` wrote: the darkest leaf (index 67) sees half the sky; 41 leaves see less than all.
    std::size_t darkest = 0, shaded = 0;
    for (std::size_t leaf = 0; leaf < 591; ++leaf) {
        if (ambientAt(*ambient, leaf) < ambientAt(*ambient, darkest)) darkest = leaf;
        shaded += ambientAt(*ambient, leaf) < 1.0f;
    }
    EXPECT_EQ(darkest, 67u);
    EXPECT_EQ(ambientAt(*ambient, darkest), 0.5f);
    EXPECT_EQ(shaded, 41u);
    EXPECT_EQ(tree.normalCode(6, 0), 12324);
    EXPECT_EQ(tree.normalCode(6, 590), 38545);
}

TEST(PoctFixture, ACorruptedCopyIsRefusedByItsChecksum)
{
    std::vector<char> chars = stylos::test::readBytes(Fixture);
    std::vector<std::uint8_t> bytes(chars.begin(), chars.end());
    bytes[bytes.size() - 100] ^= 0x01; // inside the ambient layer, the last section
    auto opened = PackedOctree::fromBytes(std::move(bytes), "flipped.poct");
    ASSERT_FALSE(opened.ok());
    EXPECT_NE(opened.error().message.find("checksum mismatch in section \"ambient\""), std::string::npos)
        << opened.error().message;
}

TEST(PoctFixture, WritingItAgainGivesTheSameBytes)
{
    auto opened = PackedOctree::open(Fixture);
    ASSERT_TRUE(opened.ok()) << opened.error().message;
    const auto ambient = opened->attribute("ambient");
    ASSERT_TRUE(ambient.has_value());
    const AttributeLayer layer{"ambient", AttributeType::Float32, 1, {ambient->bytes.begin(), ambient->bytes.end()}};
    stylos::test::TempDir dir;
    auto written = stylos::core::octree::writePoct(opened->levels(), dir / "again.poct", {&layer, 1});
    ASSERT_TRUE(written.ok()) << written.error().message;
    EXPECT_EQ(*written, 7548u);
    EXPECT_EQ(stylos::test::readBytes(dir / "again.poct"), stylos::test::readBytes(Fixture));
}
