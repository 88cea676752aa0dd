// PlyReader: every encoding, element order, scalar type, lists, and every kind of bad header or data.
#include "TestSupport.h"

#include "stylos/core/io/PlyReader.h"
#include "stylos/core/io/PointFileFormat.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace stylos::core;
using namespace stylos::core::io;
using stylos::test::TempDir;

namespace {

struct AllPoints {
    PointSchema schema;
    PointBatch points; // concatenated
    std::uint64_t skipped = 0;
    std::string format;
};

Result<AllPoints> readAll(const std::filesystem::path& path, std::size_t batchSize = 1000)
{
    auto reader = openPointReader(path);
    if (!reader) return reader.error();
    auto points = stylos::test::readAllPoints(**reader, batchSize);
    if (!points) return points.error();
    return AllPoints{(*reader)->header().schema, std::move(*points), (*reader)->pointsSkipped(),
                     (*reader)->header().format};
}

template <typename T>
void putLE(std::string& out, T v)
{
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    out.append(b, sizeof(T));
}

template <typename T>
void putBE(std::string& out, T v)
{
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    for (std::size_t i = sizeof(T); i-- > 0;) out.push_back(b[i]);
}

const char* asciiCube = "ply\n"
                        "format ascii 1.0\n"
                        "comment made by hand\n"
                        "element camera 1\n"
                        "property float view_px\n"
                        "element vertex 3\n"
                        "property double x\n"
                        "property double y\n"
                        "property double z\n"
                        "property float nx\n"
                        "property float ny\n"
                        "property float nz\n"
                        "property uchar red\n"
                        "property uchar green\n"
                        "property uchar blue\n"
                        "property ushort intensity\n"
                        "element face 1\n"
                        "property list uchar int vertex_indices\n"
                        "end_header\n"
                        "1.5\n"
                        "1000000.25 -2 3.5 0 0 1 255 0 7 1000\n"
                        "4 5 6 1 0 0 1 2 3 0\n"
                        "7 8 9 0 1 0 10 20 30 65535\n"
                        "3 0 1 2\n";

} // namespace

TEST(PlyReader, AsciiWithElementsBeforeAndAfterVertex)
{
    TempDir dir;
    stylos::test::writeText(dir / "a.ply", asciiCube);
    auto all = readAll(dir / "a.ply");
    ASSERT_TRUE(all) << all.error().message;
    EXPECT_EQ(all->format, "ply-ascii");
    EXPECT_TRUE(all->schema.hasNormals);
    EXPECT_TRUE(all->schema.hasColors);
    ASSERT_EQ(all->schema.scalarNames, std::vector<std::string>{"intensity"});
    ASSERT_EQ(all->points.size(), 3u);
    EXPECT_EQ(all->points.positions[0], 1000000.25);
    EXPECT_EQ(all->points.positions[1], -2.0);
    EXPECT_EQ(all->points.positions[8], 9.0);
    EXPECT_EQ(all->points.normals[2], 1.0f);
    EXPECT_EQ(all->points.colors[0], 255);
    EXPECT_EQ(all->points.colors[2], 7);
    EXPECT_EQ(all->points.colors[8], 30);
    EXPECT_EQ(all->points.scalars[0][2], 65535.0);
}

TEST(PlyReader, BinaryLittleAndBigEndianEveryScalarType)
{
    for (const bool big : {false, true}) {
        std::string h = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                        " 1.0\n"
                        "element range_grid 2\nproperty list uchar int vertex_indices\n"
                        "element vertex 2\n"
                        "property char c\nproperty uchar uc\nproperty short s\nproperty ushort us\n"
                        "property int i\nproperty uint ui\nproperty float x\nproperty double y\nproperty float32 z\n"
                        "property float red\nproperty float green\nproperty float blue\n"
                        "end_header\n";
        std::string d;
        auto put = [&](auto v) { big ? putBE(d, v) : putLE(d, v); };
        // range_grid: one list of 2 items, one empty list
        put(std::uint8_t(2)); put(std::int32_t(7)); put(std::int32_t(8));
        put(std::uint8_t(0));
        for (int k = 0; k < 2; ++k) {
            put(std::int8_t(-5 - k)); put(std::uint8_t(200 + k)); put(std::int16_t(-30000)); put(std::uint16_t(60000));
            put(std::int32_t(-2000000000)); put(std::uint32_t(4000000000u)); put(1.5f + k); put(-2.25 - k);
            put(3.0f); put(1.0f); put(0.5f); put(0.0f);
        }
        TempDir dir;
        stylos::test::writeText(dir / "b.ply", h + d);
        auto all = readAll(dir / "b.ply");
        ASSERT_TRUE(all) << all.error().message;
        EXPECT_EQ(all->format, big ? "ply-binary-be" : "ply-binary-le");
        ASSERT_EQ(all->points.size(), 2u);
        const std::vector<std::string> names{"c", "uc", "s", "us", "i", "ui"};
        EXPECT_EQ(all->schema.scalarNames, names);
        EXPECT_EQ(all->points.scalars[0][1], -6.0);
        EXPECT_EQ(all->points.scalars[1][1], 201.0);
        EXPECT_EQ(all->points.scalars[2][0], -30000.0);
        EXPECT_EQ(all->points.scalars[3][0], 60000.0);
        EXPECT_EQ(all->points.scalars[4][0], -2000000000.0);
        EXPECT_EQ(all->points.scalars[5][0], 4000000000.0);
        EXPECT_EQ(all->points.positions[3], 2.5);
        EXPECT_EQ(all->points.positions[4], -3.25);
        EXPECT_EQ(all->points.positions[5], 3.0);
        EXPECT_EQ(all->points.colors[0], 255);
        EXPECT_EQ(all->points.colors[1], 128);
        EXPECT_EQ(all->points.colors[2], 0);
    }
}

TEST(PlyReader, BinaryFacesAfterVertexAreSkippedAndChecked)
{
    std::string h = "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 2\nproperty list uchar uint vertex_indices\nend_header\n";
    std::string d;
    putLE(d, 1.f); putLE(d, 2.f); putLE(d, 3.f);
    putLE(d, std::uint8_t(3)); putLE(d, 0u); putLE(d, 0u); putLE(d, 0u);
    putLE(d, std::uint8_t(1)); putLE(d, 0u);
    TempDir dir;
    stylos::test::writeText(dir / "f.ply", h + d);
    auto all = readAll(dir / "f.ply");
    ASSERT_TRUE(all) << all.error().message;
    EXPECT_EQ(all->points.size(), 1u);

    // The second face list is cut short: the reader notices after the vertices.
    stylos::test::writeText(dir / "g.ply", h + d.substr(0, d.size() - 2));
    auto bad = readAll(dir / "g.ply");
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().code, ErrorCode::Truncated);
    EXPECT_NE(bad.error().message.find("face"), std::string::npos) << bad.error().message;
}

TEST(PlyReader, NonFinitePointsAreSkippedAndCounted)
{
    TempDir dir;
    stylos::test::writeText(dir / "n.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                            "property float z\nend_header\n1 2 3\nnan 0 0\n0 inf 0\n4 5 6\n");
    auto all = readAll(dir / "n.ply", 1);
    ASSERT_TRUE(all) << all.error().message;
    EXPECT_EQ(all->points.size(), 2u);
    EXPECT_EQ(all->skipped, 2u);
    EXPECT_EQ(all->points.positions[3], 4.0);
}

TEST(PlyReader, BatchSizeDoesNotChangeThePoints)
{
    TempDir dir;
    stylos::test::writeText(dir / "a.ply", asciiCube);
    auto one = readAll(dir / "a.ply", 1);
    auto many = readAll(dir / "a.ply", 100000);
    ASSERT_TRUE(one && many);
    EXPECT_EQ(one->points.positions, many->points.positions);
    EXPECT_EQ(one->points.colors, many->points.colors);
}

struct BadPly {
    const char* name;
    std::string text;
    ErrorCode code;
    const char* where; // expected position text
};

TEST(PlyReader, BadInputGivesOneLineErrorsWithPosition)
{
    const std::string v3 = "element vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
    const std::vector<BadPly> cases = {
        {"nomagic", "plx\nformat ascii 1.0\n" + v3, ErrorCode::Malformed, "byte 0"},
        {"remark", "ply\nformat ascii 1.0\nremark hi\n" + v3 + "1 2 3\n4 5 6\n", ErrorCode::Malformed, "line 3"},
        {"encoding", "ply\nformat binary_middle_endian 1.0\n" + v3, ErrorCode::Malformed, "line 2"},
        {"version", "ply\nformat ascii 2.0\n" + v3, ErrorCode::Unsupported, "line 2"},
        {"noformat", "ply\n" + v3, ErrorCode::Malformed, "line 6"},
        {"noend", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n", ErrorCode::Truncated, "line 4"},
        {"badtype", "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\nend_header\n", ErrorCode::Malformed, "line 4"},
        {"badcount", "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", ErrorCode::Malformed, "line 3"},
        {"noz", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n",
         ErrorCode::Malformed, "line 6"},
        {"novertex", "ply\nformat ascii 1.0\nelement face 0\nend_header\n", ErrorCode::Malformed, "line 4"},
        {"fewer", "ply\nformat ascii 1.0\n" + v3 + "1 2 3\n", ErrorCode::Truncated, "line 8"},
        {"more", "ply\nformat ascii 1.0\n" + v3 + "1 2 3\n4 5 6\n7 8 9\n", ErrorCode::Malformed, "line 10"},
        {"shortline", "ply\nformat ascii 1.0\n" + v3 + "1 2 3\n4 5\n", ErrorCode::Malformed, "line 9"},
        {"longline", "ply\nformat ascii 1.0\n" + v3 + "1 2 3 4\n4 5 6\n", ErrorCode::Malformed, "line 8"},
        {"nan-text", "ply\nformat ascii 1.0\n" + v3 + "1 2 x\n4 5 6\n", ErrorCode::Malformed, "line 8"},
        {"bin-short", "ply\nformat binary_little_endian 1.0\n" + v3 + std::string(20, '\0'), ErrorCode::Truncated, "byte"},
        {"bin-long", "ply\nformat binary_little_endian 1.0\n" + v3 + std::string(25, '\0'), ErrorCode::Malformed, "byte"},
    };
    TempDir dir;
    for (const auto& c : cases) {
        const auto path = dir / (std::string(c.name) + ".ply");
        stylos::test::writeText(path, c.text);
        auto all = readAll(path);
        ASSERT_FALSE(all) << c.name;
        EXPECT_EQ(all.error().code, c.code) << c.name << ": " << all.error().message;
        EXPECT_EQ(all.error().message.rfind(path.string(), 0), 0u) << all.error().message;
        EXPECT_NE(all.error().message.find(c.where), std::string::npos) << c.name << ": " << all.error().message;
        EXPECT_EQ(all.error().message.find('\n'), std::string::npos) << all.error().message;
    }
}

TEST(PlyReader, EmptyAndMissingFiles)
{
    TempDir dir;
    stylos::test::writeText(dir / "empty.ply", "");
    auto empty = openPointReader(dir / "empty.ply");
    ASSERT_FALSE(empty);
    EXPECT_EQ(empty.error().code, ErrorCode::Empty);
    auto missing = openPointReader(dir / "missing.ply");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
    auto directory = openPointReader(dir.path());
    ASSERT_FALSE(directory);
    EXPECT_EQ(directory.error().code, ErrorCode::Unreadable);
}

TEST(PlyReader, RealScansGiveTheirHeaderCounts)
{
    SKIP_WITHOUT_SHARED_DATA();
    const auto data = stylos::test::sharedData();
    const std::vector<std::pair<std::string, std::uint64_t>> files = {
        {"scans/happy_buddha_1.1M.ply", 1099005},
        {"scans/lion_takanawa_342k.ply", 341989},
        {"scans/igea_134k.ply", 134345},
        {"formats/bun000_ascii_rangegrid.ply", 40256},
        {"formats/minimal-ply-1.0_ascii-unmodified-unknown.ply", 0},
        {"formats/minimal-ply-1.0_binary-unmodified-unknown.ply", 0},
    };
    for (const auto& [name, count] : files) {
        auto all = readAll(data / name, 1 << 16);
        ASSERT_TRUE(all) << all.error().message;
        EXPECT_EQ(all->points.size() + all->skipped, count) << name;
    }
    auto lion = readAll(data / "scans/lion_takanawa_342k.ply");
    ASSERT_TRUE(lion);
    EXPECT_TRUE(lion->schema.hasColors);
    auto buddha = readAll(data / "scans/happy_buddha_1.1M.ply", 1 << 16);
    ASSERT_TRUE(buddha);
    EXPECT_EQ(buddha->schema.scalarNames, std::vector<std::string>{"scan_id"});
}

TEST(PlyReader, InvalidFixturesAreRefused)
{
    SKIP_WITHOUT_SHARED_DATA();
    for (const char* name : {"cube-ply-1.0_ascii-comment_renamed_to_remark-invalid.ply",
                             "cube-ply-1.0_binary-comment_renamed_to_remark-invalid.ply"}) {
        const auto path = stylos::test::sharedData() / "formats/invalid" / name;
        auto all = readAll(path);
        ASSERT_FALSE(all) << name;
        EXPECT_EQ(all.error().code, ErrorCode::Malformed);
        EXPECT_NE(all.error().message.find("unknown header keyword \"remark\""), std::string::npos)
            << all.error().message;
    }
}

TEST(PlyReader, BinaryNonFinitePointsAreDroppedWithTheirAttributes)
{
    std::string h = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                    "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                    "property int label\nend_header\n";
    std::string d;
    const float nan = std::nanf(""), inf = INFINITY;
    const float xs[4][3] = {{1, 2, 3}, {nan, 0, 0}, {0, 0, inf}, {4, 5, 6}};
    for (int i = 0; i < 4; ++i) {
        for (float v : xs[i]) putLE(d, v);
        putLE(d, std::uint8_t(10 * i)); putLE(d, std::uint8_t(1)); putLE(d, std::uint8_t(2));
        putLE(d, std::int32_t(100 + i));
    }
    TempDir dir;
    stylos::test::writeText(dir / "nan.ply", h + d);
    auto all = readAll(dir / "nan.ply");
    ASSERT_TRUE(all) << all.error().message;
    ASSERT_EQ(all->points.size(), 2u);
    EXPECT_EQ(all->skipped, 2u);
    EXPECT_EQ(all->points.positions, (std::vector<double>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(all->points.colors, (std::vector<std::uint8_t>{0, 1, 2, 30, 1, 2}));
    EXPECT_EQ(all->points.scalars[0], (std::vector<double>{100, 103}));
}

// Found by PlyReaderFuzzer (tests/fuzz): a float colour holding NaN was cast to uchar (undefined behaviour;
// UBSan: "nan is outside the range of representable values of type 'unsigned char'"). NaN now gives 0, as a
// negative value does; above the range gives 255 (float colours are 0..1, scaled by 255).
TEST(PlyReader, FuzzRegressionANanColourIsZeroNotUndefinedBehaviour)
{
    TempDir dir;
    stylos::test::writeText(dir / "c.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                           "property float z\nproperty float red\nproperty float green\n"
                                           "property float blue\nend_header\n"
                                           "0 0 0 nan 300 -5\n1 0 0 0.4 254.6 inf\n2 0 0 -nan 1 2\n");
    auto all = readAll(dir / "c.ply");
    ASSERT_TRUE(all.ok()) << all.error().message;
    ASSERT_EQ(all->points.size(), 3u);
    EXPECT_EQ(all->points.colors, (std::vector<std::uint8_t>{0, 255, 0, 102, 255, 255, 0, 255, 255})); // float: 0..1 × 255

    // The input the fuzzer found: its colours come before the end of the file, which then stops it.
    const auto found = std::filesystem::path(STYLOS_TEST_DATA) / "fuzz" / "ply" / "nan-colour.ply";
    auto read = readAll(found);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().code, ErrorCode::Truncated);
    EXPECT_EQ(read.error().message, found.string() + ": byte 3122: the file ends inside vertex 24 of 60");
}
