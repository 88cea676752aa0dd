// LAS 1.4 export of an octree's leaves: the header (version, format 6, record length, count, scale, offset,
// bounds), every point's coordinates against its leaf centre (within half a 0.1 mm step), the classification
// = 64 + the material id (0 stays 0) and the tool-mark extra byte, the classification lookup and the legend VLR,
// Stylos's own LAS reader taking the file back, the same bytes twice, and the refusals (an id above 191,
// "ambient" absent, an unwritable folder) leaving nothing.
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/annotation/LeafLas.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointFileSummary.h"
#include "stylos/core/octree/OctreeBuild.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <memory>

using namespace stylos::core;

namespace {

template <typename T>
T at(const std::vector<char>& bytes, std::size_t offset)
{
    T v;
    std::memcpy(&v, bytes.data() + offset, sizeof v);
    return v;
}

struct Piece {
    std::unique_ptr<stylos::test::TempDir> dir;
    std::filesystem::path octree;
};

const Piece& piece()
{
    static Piece p = [] {
        Piece p;
        p.dir = std::make_unique<stylos::test::TempDir>();
        auto o = stylos::test::coarse(0.006, 3);
        o.writeNormals = true;
        const auto ply = *p.dir / "piece.ply";
        stylos::test::generate(synth::SyntheticKind::Fragment, o, ply);
        octree::BuildOptions build;
        build.depth = 7;
        build.threads = 1;
        const auto plain = *p.dir / "plain.poct";
        EXPECT_TRUE(octree::buildOctreeFile(ply, plain, build).ok());
        // Labels: material = leaf % 4 (0..3), toolmark = leaf % 3.
        auto opened = octree::PackedOctree::open(plain);
        EXPECT_TRUE(opened.ok());
        const std::uint64_t leaves = annotation::leafCount(*opened);
        std::vector<std::uint8_t> material(leaves), toolmark(leaves);
        for (std::uint64_t i = 0; i < leaves; ++i) material[i] = std::uint8_t(i % 4), toolmark[i] = std::uint8_t(i % 3);
        const auto half = *p.dir / "half.poct";
        EXPECT_TRUE(annotation::writeLeafLabels(*opened, annotation::AnnotationLayer::Material, material, half).ok());
        auto halfOpened = octree::PackedOctree::open(half);
        p.octree = *p.dir / "piece.poct";
        EXPECT_TRUE(annotation::writeLeafLabels(*halfOpened, annotation::AnnotationLayer::Toolmark, toolmark, p.octree).ok());
        return p;
    }();
    return p;
}

} // namespace

TEST(LeafLas, HeaderPointsAndClassesAreExact)
{
    const Piece& p = piece();
    auto octree = octree::PackedOctree::open(p.octree);
    ASSERT_TRUE(octree.ok());
    const auto las = *p.dir / "leaves.las";
    const auto written = annotation::exportLeafLas(*octree, {"material", "toolmark"}, annotation::Legend::defaults(), las);
    ASSERT_TRUE(written.ok()) << written.error().message;
    const std::uint64_t leaves = annotation::leafCount(*octree);
    EXPECT_EQ(written.value(), leaves);

    const auto bytes = stylos::test::readBytes(las);
    ASSERT_GE(bytes.size(), 375u);
    EXPECT_EQ(std::string(bytes.data(), 4), "LASF");
    EXPECT_EQ(bytes[24], 1);
    EXPECT_EQ(bytes[25], 4);
    EXPECT_EQ(at<std::uint8_t>(bytes, 104), 6);
    const auto recordLength = at<std::uint16_t>(bytes, 105);
    EXPECT_EQ(recordLength, 31); // 30 + the tool-mark byte
    EXPECT_EQ(at<std::uint64_t>(bytes, 247), leaves);
    EXPECT_EQ(at<std::uint16_t>(bytes, 90), 0); // no creation day: the same bytes every time
    const auto offsetToPoints = at<std::uint32_t>(bytes, 96);
    EXPECT_EQ(bytes.size(), offsetToPoints + leaves * recordLength);
    const double scale = at<double>(bytes, 131), offset[3] = {at<double>(bytes, 155), at<double>(bytes, 163), at<double>(bytes, 171)};
    EXPECT_DOUBLE_EQ(scale, 0.0001);
    // The VLRs: the classification lookup names class 65 "preserved marbl" (15 characters), the legend's JSON.
    const std::string text(bytes.begin(), bytes.begin() + offsetToPoints);
    EXPECT_NE(text.find(std::string("\x41preserved marbl", 16)), std::string::npos);
    EXPECT_NE(text.find("\"stylos-legend\""), std::string::npos);
    EXPECT_NE(text.find("toolmark"), std::string::npos);

    std::uint64_t checked = 0;
    octree->forEachCell(octree->depth(), [&](const octree::CellView& c) {
        const std::size_t r = offsetToPoints + std::size_t(c.index) * recordLength;
        for (int k = 0; k < 3; ++k) {
            const double v = at<std::int32_t>(bytes, r + 4 * std::size_t(k)) * scale + offset[k];
            EXPECT_NEAR(v, c.centre[std::size_t(k)], 0.5 * scale + 1e-9);
        }
        EXPECT_EQ(std::uint8_t(bytes[r + 14]), 0x11);
        const std::uint8_t m = std::uint8_t(c.index % 4);
        EXPECT_EQ(std::uint8_t(bytes[r + 16]), m == 0 ? 0 : 64 + m);
        EXPECT_EQ(std::uint8_t(bytes[r + 30]), std::uint8_t(c.index % 3));
        ++checked;
        return !HasFailure();
    });
    EXPECT_EQ(checked, leaves);

    // Stylos's own reader takes it back, and a second export is the same bytes.
    auto summary = io::summarizePointFile(las);
    ASSERT_TRUE(summary.ok()) << summary.error().message;
    EXPECT_EQ(summary->points, leaves);
    // Its extra bytes too, as the Extra Bytes VLR names them: the tool-mark byte of every point (it listed none).
    ASSERT_FALSE(summary->attributes.empty());
    EXPECT_EQ(summary->attributes.back(), "toolmark");
    auto reader = io::openPointReader(las);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    auto all = stylos::test::readAllPoints(**reader, 1000);
    ASSERT_TRUE(all.ok()) << all.error().message;
    const auto& names = (*reader)->header().schema.scalarNames;
    const auto column = std::size_t(std::find(names.begin(), names.end(), "toolmark") - names.begin());
    ASSERT_LT(column, names.size());
    ASSERT_EQ(all->scalars[column].size(), leaves);
    for (std::uint64_t i = 0; i < leaves; ++i) ASSERT_EQ(all->scalars[column][i], double(i % 3)) << i;
    const auto again = *p.dir / "again.las";
    ASSERT_TRUE(annotation::exportLeafLas(*octree, {"material", "toolmark"}, annotation::Legend::defaults(), again).ok());
    EXPECT_EQ(stylos::test::readBytes(again), bytes);
}

TEST(LeafLas, RefusalsLeaveNothing)
{
    const Piece& p = piece();
    auto octree = octree::PackedOctree::open(p.octree);
    ASSERT_TRUE(octree.ok());
    const auto out = *p.dir / "bad.las";
    auto r = annotation::exportLeafLas(*octree, {"ambient"}, annotation::Legend::defaults(), out);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("ambient"), std::string::npos);
    EXPECT_NE(r.error().message.find("piece.poct"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_FALSE(annotation::exportLeafLas(*octree, {"material", "material"}, annotation::Legend::defaults(), out).ok());
    r = annotation::exportLeafLas(*octree, {"material"}, annotation::Legend::defaults(), *p.dir / "no" / "such" / "x.las");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::WriteFailed);

    const std::uint64_t leaves = annotation::leafCount(*octree);
    const auto high = *p.dir / "high.poct";
    ASSERT_TRUE(annotation::writeLeafLabels(*octree, annotation::AnnotationLayer::Material,
                                            std::vector<std::uint8_t>(leaves, 200), high).ok());
    auto highOpened = octree::PackedOctree::open(high);
    r = annotation::exportLeafLas(*highOpened, {"material"}, annotation::Legend::defaults(), out);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("200"), std::string::npos) << r.error().message;
    EXPECT_FALSE(std::filesystem::exists(out));
}
