// Writing the skydome's values: the PLY of the leaf centres reads back through the project's PLY reader
// with the same centres and values; the "ambient" layer reads back through PackedOctree::attribute, in a
// new file (cells and other layers copied) or in place (replacing an older layer); a wrong value count,
// an unwritable folder and a cancel fail cleanly and leave nothing.
#include "PoctTestSupport.h"
#include "ReferenceOctree.h"
#include "TestSupport.h"
#include "stylos/core/ao/AoExport.h"
#include "stylos/core/io/PlyReader.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

using namespace stylos::core;
using namespace stylos::core::octree;
using stylos::test::ReferenceOctree;
using stylos::test::TempDir;

namespace {

std::size_t entriesIn(const std::filesystem::path& dir)
{
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

/** A random wavy sheet with normals and colours, depth 5, written with a "class" layer after the colour. */
PackedOctree sheetOctree(const TempDir& dir, const std::string& name = "sheet.poct")
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> p;
    std::vector<float> n;
    std::vector<std::uint8_t> c;
    for (int i = 0; i < 3000; ++i) {
        const double x = u(rng), y = u(rng);
        p.insert(p.end(), {x + 10.0, y - 5.0, 0.2 * x * y});
        n.insert(n.end(), {float(-0.2 * y), float(-0.2 * x), 1.0f});
        c.insert(c.end(), {std::uint8_t(rng()), std::uint8_t(rng()), std::uint8_t(rng())});
    }
    const ReferenceOctree tree(p, n, c, 5);
    const std::uint64_t leaves = tree.description().cellsPerLevel.back();
    const std::vector<AttributeLayer> layers{{"class", AttributeType::UInt16, 1, std::vector<std::uint8_t>(2 * leaves, 9)}};
    const auto written = writePoct(tree, dir / name, layers);
    EXPECT_TRUE(written.ok()) << (written.ok() ? "" : written.error().message);
    auto opened = PackedOctree::open(dir / name);
    EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error().message);
    return std::move(opened).value();
}

/** Distinct values in [0, 1], exactly representable, one per leaf. */
std::vector<float> rampValues(std::uint64_t leaves, float offset = 0.0f)
{
    std::vector<float> v(leaves);
    for (std::uint64_t i = 0; i < leaves; ++i) v[i] = float((i * 37 + 11) % 1024) / 1024.0f * (1.0f - offset) + offset;
    return v;
}

std::vector<float> layerValues(const PackedOctree& octree)
{
    const auto layer = octree.attribute("ambient");
    EXPECT_TRUE(layer.has_value());
    if (!layer) return {};
    EXPECT_EQ(layer->type, AttributeType::Float32);
    EXPECT_EQ(layer->components, 1);
    std::vector<float> v(layer->bytes.size() / sizeof(float));
    std::memcpy(v.data(), layer->bytes.data(), layer->bytes.size());
    return v;
}

std::vector<std::string> layerNames(const PackedOctree& octree)
{
    std::vector<std::string> names;
    for (const auto& a : octree.attributes()) names.push_back(a.name);
    return names;
}

} // namespace

TEST(AoExport, PlyRoundTripThroughThePlyReader)
{
    TempDir dir;
    const auto octree = sheetOctree(dir);
    const std::uint64_t leaves = octree.cellCount(octree.depth());
    const auto values = rampValues(leaves);
    const auto written = ao::writeAmbientPly(octree, values, dir / "ao.ply");
    ASSERT_TRUE(written.ok()) << written.error().message;
    EXPECT_EQ(written.value(), leaves);

    auto reader = io::PlyReader::open(dir / "ao.ply");
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    EXPECT_EQ((*reader)->header().format, "ply-binary-le");
    EXPECT_FALSE((*reader)->header().schema.hasNormals);
    EXPECT_EQ((*reader)->header().schema.scalarNames, std::vector<std::string>{"ambient"});
    auto points = stylos::test::readAllPoints(**reader, 1000);
    ASSERT_TRUE(points.ok()) << points.error().message;
    ASSERT_EQ(points->size(), leaves);
    std::size_t i = 0;
    octree.forEachCell(octree.depth(), [&](const CellView& cell) {
        for (int a = 0; a < 3; ++a) EXPECT_EQ(points->positions[3 * i + a], cell.centre[a]) << i; // doubles, exact
        EXPECT_EQ(points->scalars[0][i], double(values[i])) << i;
        ++i;
        return true;
    });
    EXPECT_EQ(i, leaves);
    // 4 + 2 + 1 header lines of properties; records of 3 doubles + 1 float.
    const auto bytes = stylos::test::readBytes(dir / "ao.ply");
    const std::string text(bytes.begin(), bytes.end());
    EXPECT_NE(text.find("property double x\nproperty double y\nproperty double z\nproperty float ambient\nend_header\n"),
              std::string::npos);
    EXPECT_EQ(bytes.size() - (text.find("end_header\n") + 11), leaves * 28);
}

TEST(AoExport, NewPoctKeepsTheCellsAndTheOtherLayers)
{
    TempDir dir;
    const auto octree = sheetOctree(dir);
    const std::uint64_t leaves = octree.cellCount(octree.depth());
    const auto values = rampValues(leaves);
    const auto written = ao::writeAmbientPoct(octree, values, dir / "with-ao.poct");
    ASSERT_TRUE(written.ok()) << written.error().message;
    auto result = PackedOctree::open(dir / "with-ao.poct");
    ASSERT_TRUE(result.ok()) << result.error().message;
    EXPECT_EQ(written.value(), result->fileBytes());
    EXPECT_EQ(result->description(), octree.description());
    for (int l = 0; l <= octree.depth(); ++l) {
        const auto a = octree.levelNormalCodes(l), b = result->levelNormalCodes(l);
        EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << l;
        const auto ma = octree.levelMasks(l), mb = result->levelMasks(l);
        EXPECT_TRUE(std::equal(ma.begin(), ma.end(), mb.begin(), mb.end())) << l;
    }
    EXPECT_EQ(layerNames(*result), (std::vector<std::string>{"colour", "class", "ambient"}));
    for (const char* name : {"colour", "class"}) {
        const auto a = octree.attribute(name)->bytes, b = result->attribute(name)->bytes;
        EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << name;
    }
    EXPECT_EQ(layerValues(*result), values);
    EXPECT_FALSE(octree.attribute("ambient").has_value()); // the source is untouched

    // Again from the file that has a layer: replaced where it stood, not added.
    const auto again = rampValues(leaves, 0.5f);
    ASSERT_TRUE(ao::writeAmbientPoct(*result, again, dir / "again.poct").ok());
    auto second = PackedOctree::open(dir / "again.poct");
    ASSERT_TRUE(second.ok()) << second.error().message;
    EXPECT_EQ(layerNames(*second), (std::vector<std::string>{"colour", "class", "ambient"}));
    EXPECT_EQ(layerValues(*second), again);
}

TEST(AoExport, InPlaceAddsThenReplacesTheLayerAndKeepsTheCellBytes)
{
    TempDir dir;
    const std::uint64_t leaves = sheetOctree(dir).cellCount(5);
    for (float offset : {0.0f, 0.25f}) {
        auto octree = PackedOctree::open(dir / "sheet.poct");
        ASSERT_TRUE(octree.ok());
        const auto values = rampValues(leaves, offset);
        const auto written = ao::writeAmbientPoct(*octree, values, dir / "sheet.poct");
        ASSERT_TRUE(written.ok()) << written.error().message;
        auto reopened = PackedOctree::open(dir / "sheet.poct");
        ASSERT_TRUE(reopened.ok()) << reopened.error().message;
        EXPECT_EQ(layerNames(*reopened), (std::vector<std::string>{"colour", "class", "ambient"}));
        EXPECT_EQ(layerValues(*reopened), values);
        // The cells and the other layers are the same bytes.
        for (int l = 0; l <= 5; ++l) {
            const auto a = octree->levelNormalCodes(l), b = reopened->levelNormalCodes(l);
            ASSERT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << l;
            const auto ma = octree->levelMasks(l), mb = reopened->levelMasks(l);
            ASSERT_TRUE(std::equal(ma.begin(), ma.end(), mb.begin(), mb.end())) << l;
        }
        for (const char* name : {"colour", "class"}) {
            const auto a = octree->attribute(name)->bytes, b = reopened->attribute(name)->bytes;
            EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << name;
        }
    }
    EXPECT_EQ(entriesIn(dir.path()), 1u);
}

TEST(AoExport, WrongCountUnwritableFolderAndCancelLeaveNothing)
{
    TempDir dir;
    const auto octree = sheetOctree(dir);
    const std::uint64_t leaves = octree.cellCount(octree.depth());
    const auto few = rampValues(leaves - 1);
    for (const char* name : {"a.ply", "a.poct"}) {
        const auto path = dir / name;
        const auto r = std::string(name).ends_with(".ply") ? ao::writeAmbientPly(octree, few, path)
                                                           : ao::writeAmbientPoct(octree, few, path);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument);
        EXPECT_NE(r.error().message.find(std::to_string(leaves) + " leaves"), std::string::npos) << r.error().message;
    }
    const auto values = rampValues(leaves);
    const auto missing = dir / "missing" / "x.ply";
    const auto r = ao::writeAmbientPly(octree, values, missing);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(r.error().message.find("missing"), std::string::npos) << r.error().message;

    SilentProgress cancelled;
    cancelled.cancel();
    const auto ply = ao::writeAmbientPly(octree, values, dir / "c.ply", &cancelled);
    ASSERT_FALSE(ply.ok());
    EXPECT_EQ(ply.error().code, ErrorCode::Cancelled);
    const auto poct = ao::writeAmbientPoct(octree, values, dir / "c.poct", &cancelled);
    ASSERT_FALSE(poct.ok());
    EXPECT_EQ(poct.error().code, ErrorCode::Cancelled);
    EXPECT_EQ(entriesIn(dir.path()), 1u); // sheet.poct only
}

TEST(AoExport, LayerHoldsTheFloatsLittleEndian)
{
    const std::vector<float> values{0.0f, 0.5f, 1.0f};
    const auto layer = ao::ambientLayer(values);
    EXPECT_EQ(layer.name, "ambient");
    EXPECT_EQ(layer.type, AttributeType::Float32);
    EXPECT_EQ(layer.components, 1);
    EXPECT_EQ(layer.bytes, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0, 0x3F, 0, 0, 0x80, 0x3F}));
}
