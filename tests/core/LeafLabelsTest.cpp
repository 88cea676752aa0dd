// Per-leaf labels in a .poct: absent → zeros; written → reopened → the same bytes, the cells and other layers
// unchanged; in place; a wrong count refused naming the files, nothing written.
#include "AnnotationTestSupport.h"

#include "stylos/core/annotation/LeafLabels.h"

#include <gtest/gtest.h>

using namespace stylos::core::annotation;
namespace oct = stylos::core::octree;
namespace fs = std::filesystem;

namespace {

oct::PackedOctree openPoct(const fs::path& path)
{
    auto opened = oct::PackedOctree::open(path);
    EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error().message);
    return std::move(opened).value();
}

} // namespace

TEST(LeafLabels, AbsentLayerReadsAsZeros)
{
    const auto& drum = stylos::test::annotatedDrum();
    const auto octree = openPoct(drum.poct);
    const auto labels = readLeafLabels(octree, AnnotationLayer::Material);
    ASSERT_TRUE(labels.ok());
    EXPECT_EQ(labels->size(), leafCount(octree));
    EXPECT_TRUE(std::all_of(labels->begin(), labels->end(), [](auto v) { return v == 0; }));
}

TEST(LeafLabels, WriteReopenGivesTheSameBytes)
{
    const auto& drum = stylos::test::annotatedDrum();
    stylos::test::TempDir dir;
    const auto octree = openPoct(drum.poct);
    std::vector<std::uint8_t> material(leafCount(octree)), toolmark(leafCount(octree));
    for (std::size_t i = 0; i < material.size(); ++i) {
        material[i] = std::uint8_t((i * 37) % 256);
        toolmark[i] = std::uint8_t(i % 6);
    }
    ASSERT_TRUE(writeLeafLabels(octree, AnnotationLayer::Material, material, dir / "a.poct").ok());
    {
        const auto a = openPoct(dir / "a.poct");
        EXPECT_EQ(readLeafLabels(a, AnnotationLayer::Material).value(), material);
        // The toolmark layer goes in place, next to the material one.
        const auto written = writeLeafLabels(a, AnnotationLayer::Toolmark, toolmark, dir / "a.poct");
        ASSERT_TRUE(written.ok()) << written.error().message;
    }
    const auto a = openPoct(dir / "a.poct");
    EXPECT_EQ(readLeafLabels(a, AnnotationLayer::Material).value(), material);
    EXPECT_EQ(readLeafLabels(a, AnnotationLayer::Toolmark).value(), toolmark);
    for (int level = 0; level <= octree.depth(); ++level) {
        ASSERT_EQ(a.cellCount(level), octree.cellCount(level));
        const auto n0 = octree.levelNormalCodes(level), n1 = a.levelNormalCodes(level);
        EXPECT_TRUE(std::equal(n0.begin(), n0.end(), n1.begin()));
    }
    // Rewriting the material layer replaces it (one layer of that name).
    std::vector<std::uint8_t> ones(material.size(), 1);
    ASSERT_TRUE(writeLeafLabels(a, AnnotationLayer::Material, ones, dir / "b.poct").ok());
    const auto b = openPoct(dir / "b.poct");
    EXPECT_EQ(readLeafLabels(b, AnnotationLayer::Material).value(), ones);
    EXPECT_EQ(readLeafLabels(b, AnnotationLayer::Toolmark).value(), toolmark);
    int named = 0;
    for (const auto& view : b.attributes()) named += view.name == "material";
    EXPECT_EQ(named, 1);
}

TEST(LeafLabels, WrongCountIsRefusedAndNothingWritten)
{
    const auto& drum = stylos::test::annotatedDrum();
    stylos::test::TempDir dir;
    const auto octree = openPoct(drum.poct);
    const std::vector<std::uint8_t> labels(leafCount(octree) - 1, 2);
    const auto written = writeLeafLabels(octree, AnnotationLayer::Material, labels, dir / "out.poct");
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error().code, stylos::core::ErrorCode::InvalidArgument);
    EXPECT_NE(written.error().message.find("out.poct"), std::string::npos) << written.error().message;
    EXPECT_NE(written.error().message.find("drum.poct"), std::string::npos) << written.error().message;
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(LeafLabels, LayerOfTheWrongTypeIsMalformed)
{
    const auto& drum = stylos::test::annotatedDrum();
    stylos::test::TempDir dir;
    const auto octree = openPoct(drum.poct);
    oct::AttributeLayer wrong{"toolmark", oct::AttributeType::UInt16, 1, std::vector<std::uint8_t>(leafCount(octree) * 2)};
    ASSERT_TRUE(writeAttributePoct(octree, wrong, dir / "w.poct").ok());
    const auto labels = readLeafLabels(openPoct(dir / "w.poct"), AnnotationLayer::Toolmark);
    ASSERT_FALSE(labels.ok());
    EXPECT_EQ(labels.error().code, stylos::core::ErrorCode::Malformed);
    EXPECT_NE(labels.error().message.find("w.poct"), std::string::npos);
}

TEST(LeafLabels, BothLayersInOnePassOntoTheOpenedFile)
{
    const auto& drum = stylos::test::annotatedDrum();
    stylos::test::TempDir dir;
    fs::copy_file(drum.poct, dir / "own.poct");
    const auto octree = openPoct(dir / "own.poct");
    const std::size_t n = leafCount(octree);
    std::vector<std::uint8_t> material(n, 0), toolmark(n, 0);
    material[0] = 3;
    material[n - 1] = 1;
    toolmark[n / 2] = 5;
    std::vector<oct::AttributeLayer> layers{labelAttribute(AnnotationLayer::Material, material),
                                            labelAttribute(AnnotationLayer::Toolmark, toolmark)};
    const auto written = writeAttributesPoct(octree, layers, dir / "own.poct");
    ASSERT_TRUE(written.ok()) << written.error().message;
    // The opened octree still reads (it maps the replaced file) and still has no labels.
    EXPECT_EQ(readLeafLabels(octree, AnnotationLayer::Material).value(), std::vector<std::uint8_t>(n, 0));
    const auto reopened = openPoct(dir / "own.poct");
    EXPECT_EQ(readLeafLabels(reopened, AnnotationLayer::Material).value(), material);
    EXPECT_EQ(readLeafLabels(reopened, AnnotationLayer::Toolmark).value(), toolmark);
    // Written again with one layer changed: still one layer of each name, the other kept.
    material[1] = 2;
    const auto again = writeAttributesPoct(reopened, {labelAttribute(AnnotationLayer::Material, material)},
                                           dir / "own.poct");
    ASSERT_TRUE(again.ok()) << again.error().message;
    const auto last = openPoct(dir / "own.poct");
    EXPECT_EQ(readLeafLabels(last, AnnotationLayer::Material).value(), material);
    EXPECT_EQ(readLeafLabels(last, AnnotationLayer::Toolmark).value(), toolmark);
    // A layer given twice is refused, naming the output, and the file is untouched.
    const auto twice = writeAttributesPoct(last, {labelAttribute(AnnotationLayer::Material, material),
                                                  labelAttribute(AnnotationLayer::Material, material)},
                                           dir / "own.poct");
    ASSERT_FALSE(twice.ok());
    EXPECT_NE(twice.error().message.find("own.poct"), std::string::npos);
    EXPECT_NE(twice.error().message.find("given twice"), std::string::npos);
    EXPECT_EQ(readLeafLabels(openPoct(dir / "own.poct"), AnnotationLayer::Material).value(), material);
}
