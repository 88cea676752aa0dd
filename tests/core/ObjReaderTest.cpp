#include "stylos/core/io/ObjReader.h"

#include "stylos/core/io/PointFileFormat.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

using namespace stylos::core;
using namespace stylos::core::io;
using stylos::test::TempDir;
using stylos::test::writeText;

namespace {

using Vertices = PointBatch;

Result<Vertices> readAll(PointReader& reader, std::size_t maxPoints)
{
    return stylos::test::readAllPoints(reader, maxPoints);
}

class ObjReaderTest : public ::testing::Test {
protected:
    std::unique_ptr<PointReader> open(const std::string& text)
    {
        writeText(m_dir / "m.obj", text);
        auto reader = ObjReader::open(m_dir / "m.obj");
        EXPECT_TRUE(reader.ok()) << (reader.ok() ? "" : reader.error().message);
        return reader.ok() ? std::move(reader).value() : nullptr;
    }

    Vertices load(const std::string& text, std::size_t maxPoints = 1000)
    {
        auto reader = open(text);
        if (!reader) return {};
        auto all = readAll(*reader, maxPoints);
        EXPECT_TRUE(all.ok()) << (all.ok() ? "" : all.error().message);
        return all.ok() ? std::move(all).value() : Vertices{};
    }

    /** The error @p text gives, opening or reading; checks the message names the file and @p position. */
    Error failure(const std::string& text, const std::string& position)
    {
        writeText(m_dir / "bad.obj", text);
        Error error{ErrorCode::Malformed, "(no error)"};
        auto reader = ObjReader::open(m_dir / "bad.obj");
        if (!reader) {
            error = reader.error();
        } else {
            auto all = readAll(*reader.value(), 1000);
            if (all.ok()) ADD_FAILURE() << "read without error";
            else error = all.error();
        }
        EXPECT_NE(error.message.find("bad.obj"), std::string::npos) << error.message;
        if (!position.empty()) {
            EXPECT_NE(error.message.find(position + ":"), std::string::npos) << error.message;
        }
        return error;
    }

    TempDir m_dir;
};

const char* const cube = "# a square\n"
                         "mtllib m.mtl\n"
                         "o square\n"
                         "v 0 0 0\n"
                         "v 1.5 0 0\n"
                         "vt 0 0\n"
                         "v 1 1 0\n"
                         "  v -1e3 2 3.25\n"
                         "g side\n"
                         "usemtl stone\n"
                         "s off\n"
                         "f 1 2 3\n"
                         "f 1/1 3/1 4/1\n"
                         "vp 0.5\n";

} // namespace

TEST_F(ObjReaderTest, VerticesOnly)
{
    auto reader = open(cube);
    ASSERT_TRUE(reader);
    EXPECT_EQ(reader->header().format, "obj");
    EXPECT_EQ(reader->header().declaredPoints, std::optional<std::uint64_t>(4));
    EXPECT_EQ(reader->header().schema, PointSchema{});
    auto all = readAll(*reader, 1000);
    ASSERT_TRUE(all.ok());
    EXPECT_EQ(all->positions, (std::vector<double>{0, 0, 0, 1.5, 0, 0, 1, 1, 0, -1000, 2, 3.25}));
    EXPECT_EQ(reader->pointsRead(), 4u);
    EXPECT_EQ(reader->bytesConsumed(), reader->fileBytes());
}

TEST_F(ObjReaderTest, HomogeneousWeightIgnored)
{
    EXPECT_EQ(load("v 1 2 3 1.0\nv 4 5 6 0.5\n").positions, (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

TEST_F(ObjReaderTest, FloatVertexColors)
{
    auto reader = open("v 1 2 3 1 0 0.5\nv 4 5 6 0.2 0.2 0.2\n");
    ASSERT_TRUE(reader);
    EXPECT_TRUE(reader->header().schema.hasColors);
    auto all = readAll(*reader, 1000);
    ASSERT_TRUE(all.ok());
    EXPECT_EQ(all->colors, (std::vector<std::uint8_t>{255, 0, 128, 51, 51, 51}));
}

TEST_F(ObjReaderTest, ByteVertexColors)
{
    EXPECT_EQ(load("v 1 2 3 255 0 1\nv 4 5 6 10 20 30\n").colors, (std::vector<std::uint8_t>{255, 0, 1, 10, 20, 30}));
}

TEST_F(ObjReaderTest, NormalsWhenCountsMatch)
{
    // Normals after all vertices (the usual layout), CRLF line ends, no final newline.
    auto reader = open("v 1 2 3\r\nv 4 5 6\r\nv 7 8 9\r\nvt 0 0\r\nvn 0 0 1\r\nvn 0 1 0\r\nvn 1 0 0\r\nf 1//1 2//2 3//3");
    ASSERT_TRUE(reader);
    EXPECT_TRUE(reader->header().schema.hasNormals);
    auto all = readAll(*reader, 2);
    ASSERT_TRUE(all.ok());
    EXPECT_EQ(all->positions, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
    EXPECT_EQ(all->normals, (std::vector<float>{0, 0, 1, 0, 1, 0, 1, 0, 0}));
}

TEST_F(ObjReaderTest, InterleavedNormals)
{
    const Vertices all = load("vn 0 0 1\nv 1 2 3\nv 4 5 6\nvn 0 -1 0\n");
    EXPECT_EQ(all.normals, (std::vector<float>{0, 0, 1, 0, -1, 0}));
}

TEST_F(ObjReaderTest, NormalsIgnoredWhenCountsDiffer)
{
    auto reader = open("v 1 2 3\nv 4 5 6\nvn 0 0 1\n");
    ASSERT_TRUE(reader);
    EXPECT_FALSE(reader->header().schema.hasNormals);
    auto all = readAll(*reader, 1000);
    ASSERT_TRUE(all.ok());
    EXPECT_TRUE(all->normals.empty());
    EXPECT_EQ(all->positions.size(), 6u);
}

TEST_F(ObjReaderTest, NonFiniteVerticesSkippedWithTheirNormals)
{
    auto reader = open("v 1 2 3\nv nan 0 0\nv 4 5 6\nv 0 inf 0\nvn 1 0 0\nvn 0 1 0\nvn 0 0 1\nvn 1 0 0\n");
    ASSERT_TRUE(reader);
    auto all = readAll(*reader, 1);
    ASSERT_TRUE(all.ok());
    EXPECT_EQ(all->positions, (std::vector<double>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(all->normals, (std::vector<float>{1, 0, 0, 0, 0, 1}));
    EXPECT_EQ(reader->pointsRead(), 2u);
    EXPECT_EQ(reader->pointsSkipped(), 2u);
}

TEST_F(ObjReaderTest, BatchSizesGiveTheSamePoints)
{
    std::string text;
    for (int i = 0; i < 3000; ++i) text += "v " + std::to_string(i) + " " + std::to_string(i * 0.25) + " 1\nf 1 2 3\n";
    for (int i = 0; i < 3000; ++i) text += "vn 0 0 " + std::string(i % 2 ? "1" : "-1") + "\n";
    const Vertices one = load(text, 1);
    const Vertices many = load(text, 1000);
    ASSERT_EQ(one.positions.size(), 9000u);
    EXPECT_EQ(one.positions, many.positions);
    EXPECT_EQ(one.normals, many.normals);
    EXPECT_EQ(one.positions[3 * 2999 + 1], 2999 * 0.25);
    EXPECT_EQ(one.normals[3 * 2999 + 2], 1.0f);
}

TEST_F(ObjReaderTest, FactoryOpensObj)
{
    writeText(m_dir / "f.obj", "v 1 2 3\n");
    auto reader = openPointReader(m_dir / "f.obj");
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    EXPECT_EQ(reader.value()->header().format, "obj");
}

TEST_F(ObjReaderTest, Errors)
{
    Error e = failure("v 1 2 3\nf 1 2 3\nv 1 x 3\n", "line 3");
    EXPECT_EQ(e.code, ErrorCode::Malformed);
    EXPECT_NE(e.message.find("not a number: \"x\""), std::string::npos) << e.message;
    EXPECT_EQ(failure("v 1 2\n", "line 1").code, ErrorCode::Malformed);
    EXPECT_EQ(failure("v 1 2 3\nv 1 2\n", "line 2").code, ErrorCode::Malformed);
    EXPECT_EQ(failure("v 1 2 3 1 1 1\nv 1 2 3\n", "line 2").code, ErrorCode::Malformed); // colours, then none
    EXPECT_EQ(failure("v 1 2 3\nvn 0 0\n", "line 2").code, ErrorCode::Malformed);
    EXPECT_EQ(failure("v 1 2 3\n# c\nvn 0 zero 1\n", "line 3").code, ErrorCode::Malformed);
    EXPECT_EQ(failure("# only faces\nf 1 2 3\nvn 0 0 1\n", "").code, ErrorCode::Empty);
    EXPECT_EQ(failure("", "").code, ErrorCode::Empty);
}
