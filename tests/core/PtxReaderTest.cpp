// PtxReader: scans with their 4×4 transforms (row-vector convention, checked against the fixture whose
// second scan repeats the first one's points already transformed), (0, 0, 0) points dropped and counted,
// colour, one scan chosen, and every error path with its line number.
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointFileSummary.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace stylos::core;
using namespace stylos::core::io;
using stylos::test::TempDir;

namespace {

const std::string kHeader = "2\n1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

std::string readError(const fs::path& path, ErrorCode expected, const ReadOptions& options = {})
{
    auto reader = openPointReader(path, options);
    if (!reader) {
        EXPECT_EQ(int(reader.error().code), int(expected)) << reader.error().message;
        return reader.error().message;
    }
    PointBatch batch;
    for (;;) {
        auto got = (*reader)->read(batch, 2);
        if (!got) {
            EXPECT_EQ(int(got.error().code), int(expected)) << got.error().message;
            return got.error().message;
        }
        if (*got == 0) break;
    }
    ADD_FAILURE() << path << " was read without an error";
    return {};
}

} // namespace

TEST(PtxReader, TransformIsRowVectorAndZeroPointsAreMissing)
{
    TempDir dir;
    // Rotation 90° about z written as Leica does (p' = p · M): M's first row is the image of x, (0 1 0).
    stylos::test::writeText(dir / "a.ptx", kHeader +
                                               "0 1 0 0\n-1 0 0 0\n0 0 1 0\n100 200 300 1\n"
                                               "1 2 3 0.5 10 20 30\n0 0 0 0.5 0 0 0\n"
                                               "3\n1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"
                                               "7 8 9 0.25 1 2 3\n0 0 0 0 0 0 0\n-1 -2 -3 1 4 5 6\n");
    auto reader = openPointReader(dir / "a.ptx");
    ASSERT_TRUE(reader) << reader.error().message;
    EXPECT_TRUE((*reader)->header().schema.hasColors);
    auto all = stylos::test::readAllPoints(**reader, 2);
    ASSERT_TRUE(all) << all.error().message;
    // (1, 2, 3) · M = (−2, 1, 3) + (100, 200, 300).
    EXPECT_EQ(all->positions, (std::vector<double>{98, 201, 303, 7, 8, 9, -1, -2, -3}));
    EXPECT_EQ(all->colors, (std::vector<std::uint8_t>{10, 20, 30, 1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(all->scalars[0], (std::vector<double>{0.5, 0.25, 1}));
    // Each point's scan, for what keeps the scans apart (normals estimated scan by scan).
    EXPECT_EQ((*reader)->header().schema.scalarNames, (std::vector<std::string>{"intensity", "scan_index"}));
    ASSERT_EQ(all->scalars.size(), 2u);
    EXPECT_EQ(all->scalars[1], (std::vector<double>{0, 1, 1}));
    EXPECT_EQ((*reader)->pointsMissing(), 2u);
    EXPECT_EQ((*reader)->header().declaredPoints, 5u);
    ASSERT_EQ((*reader)->scans().size(), 2u);
    EXPECT_EQ((*reader)->scans()[0].pose, (std::array<double, 12>{0, -1, 0, 100, 1, 0, 0, 200, 0, 0, 1, 300}));

    ReadOptions second;
    second.scan = 1;
    auto one = summarizePointFile(dir / "a.ptx", second);
    ASSERT_TRUE(one) << one.error().message;
    EXPECT_EQ(one->points, 2u);
    EXPECT_EQ(one->attributes, (std::vector<std::string>{"color", "intensity"})); // one scan: no scan column
    EXPECT_EQ(one->missing, 1u);
    EXPECT_EQ(one->declaredPoints, 3u);
    ReadOptions third;
    third.scan = 2;
    const std::string message = readError(dir / "a.ptx", ErrorCode::InvalidArgument, third);
    EXPECT_NE(message.find("scan 2 does not exist: the file has 2 scan(s)"), std::string::npos) << message;
}

TEST(PtxReader, ErrorsNameTheLine)
{
    TempDir dir;
    const std::string identity = "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
    struct Case { const char* name; std::string text; ErrorCode code; const char* where; };
    const Case cases[] = {
        {"cut.ptx", kHeader + identity + "1 2 3 0.5\n", ErrorCode::Truncated, ": line 12: the file ends inside scan 0 after 1 of its 2 points"},
        {"word.ptx", kHeader + identity + "1 2 x 0.5\n4 5 6 0\n", ErrorCode::Malformed, ": line 11: column 3 is not a number"},
        {"count.ptx", kHeader + identity + "1 2 3 0.5\n4 5 6\n", ErrorCode::Malformed, ": line 12: a point line has 3 values"},
        {"matrix.ptx", kHeader + "1 0 0\n" + identity.substr(8), ErrorCode::Malformed, ": line 7: a transform row needs 4 numbers"},
        {"rows.ptx", "2\nabc\n", ErrorCode::Malformed, ": line 2: expected the row count"},
        {"header.ptx", "2\n1\n0 0 0\n", ErrorCode::Truncated, ": line 3: the file ends inside a scan header"},
        {"blank.ptx", "\n\n", ErrorCode::Empty, ": the file holds no scan"},
    };
    for (const Case& c : cases) {
        stylos::test::writeText(dir / c.name, c.text);
        const std::string message = readError(dir / c.name, c.code);
        EXPECT_EQ(message.rfind((dir / c.name).string() + c.where, 0), 0u) << c.name << ": " << message;
    }
}

TEST(PtxReader, SharedFixtures)
{
    SKIP_WITHOUT_SHARED_DATA();
    const fs::path formats = stylos::test::sharedData() / "formats" / "ptx";
    auto multiple = summarizePointFile(formats / "multiple-and-transform.ptx");
    ASSERT_TRUE(multiple) << multiple.error().message;
    EXPECT_EQ(multiple->points, 8u);
    EXPECT_EQ(multiple->declaredPoints, 8u);
    ASSERT_EQ(multiple->scans.size(), 2u);
    // Scan 0's points, transformed (x + 600000, y + 800000, 2 z + 400), are exactly scan 1's untransformed
    // ones: both scans read alone give the same bounds.
    ReadOptions first, second;
    first.scan = 0;
    second.scan = 1;
    auto a = summarizePointFile(formats / "multiple-and-transform.ptx", first);
    auto b = summarizePointFile(formats / "multiple-and-transform.ptx", second);
    ASSERT_TRUE(a && b);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR((*a->min)[k], (*b->min)[k], 1e-9) << k;
        EXPECT_NEAR((*a->max)[k], (*b->max)[k], 1e-9) << k;
    }
    EXPECT_EQ(*b->min, (std::array<double, 3>{636699.38, 848991.01, 425.39}));
    EXPECT_EQ(*b->max, (std::array<double, 3>{637012.24, 849106.66, 446.39}));

    auto colour = summarizePointFile(formats / "1.2-with-color.ptx");
    ASSERT_TRUE(colour) << colour.error().message;
    EXPECT_EQ(colour->declaredPoints, 15u * 71u);
    EXPECT_EQ(colour->points + colour->missing, 15u * 71u);
    EXPECT_EQ(colour->attributes, (std::vector<std::string>{"color", "intensity", "scan_index"}));
}
