#include "stylos/core/io/TextReader.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using namespace stylos::core;
using namespace stylos::core::io;
using stylos::test::TempDir;
using stylos::test::writeText;

namespace {

using Cloud = PointBatch;

Result<Cloud> readAll(PointReader& reader, std::size_t maxPoints) { return stylos::test::readAllPoints(reader, maxPoints); }

class TextReaderTest : public ::testing::Test {
protected:
    /** Writes @p text as @p name and opens it. */
    std::unique_ptr<PointReader> open(const std::string& name, const std::string& text, const ReadOptions& options = {})
    {
        writeText(m_dir / name, text);
        auto reader = TextReader::open(m_dir / name, options);
        EXPECT_TRUE(reader.ok()) << (reader.ok() ? "" : reader.error().message);
        return reader.ok() ? std::move(reader).value() : nullptr;
    }

    Cloud load(const std::string& name, const std::string& text, const ReadOptions& options = {})
    {
        auto reader = open(name, text, options);
        if (!reader) return {};
        auto cloud = readAll(*reader, 1000);
        EXPECT_TRUE(cloud.ok()) << (cloud.ok() ? "" : cloud.error().message);
        return cloud.ok() ? std::move(cloud).value() : Cloud{};
    }

    /** The error opening or reading @p text gives; checks it names the file and @p position. */
    Error failure(const std::string& name, const std::string& text, const std::string& position,
                  const ReadOptions& options = {})
    {
        writeText(m_dir / name, text);
        return failureOf(name, position, options);
    }

    /** As failure(), for a file already written. */
    Error failureOf(const std::string& name, const std::string& position, const ReadOptions& options = {})
    {
        Error error{ErrorCode::Malformed, "(no error)"};
        auto reader = TextReader::open(m_dir / name, options);
        if (!reader) {
            error = reader.error();
        } else {
            auto cloud = readAll(*reader.value(), 1000);
            if (cloud.ok()) ADD_FAILURE() << name << " read without error";
            else error = cloud.error();
        }
        EXPECT_NE(error.message.find(name), std::string::npos) << error.message;
        if (!position.empty()) {
            EXPECT_NE(error.message.find(position + ":"), std::string::npos) << error.message;
        }
        return error;
    }

    TempDir m_dir;
};

} // namespace

TEST_F(TextReaderTest, ThreeColumnsExactValues)
{
    auto reader = open("a.xyz", "1 2 3\n-4.5 5e2 +6.25\n1234567.125 -0.001 7\n");
    ASSERT_TRUE(reader);
    EXPECT_EQ(reader->header().format, "xyz");
    EXPECT_FALSE(reader->header().declaredPoints.has_value());
    EXPECT_EQ(reader->header().schema, PointSchema{});
    auto cloud = readAll(*reader, 1000);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->positions, (std::vector<double>{1, 2, 3, -4.5, 500, 6.25, 1234567.125, -0.001, 7}));
    EXPECT_EQ(reader->bytesConsumed(), reader->fileBytes());
    EXPECT_EQ(reader->pointsSkipped(), 0u);
}

TEST_F(TextReaderTest, Separators)
{
    const std::vector<double> expected{1, 2, 3, 4, 5, 6};
    EXPECT_EQ(load("t.txt", "1\t2\t3\n  4 \t 5    6  \n").positions, expected);
    EXPECT_EQ(load("c.csv", "1,2,3\n4, 5 ,6\n").positions, expected);
    EXPECT_EQ(load("s.csv", "1;2;3\n4 ; 5;6;\n").positions, expected); // one trailing separator tolerated
}

TEST_F(TextReaderTest, FormatNameFromExtension)
{
    for (const std::string ext : {"xyz", "asc", "csv", "pts", "txt"}) {
        auto reader = open("f." + ext, "1 2 3\n");
        ASSERT_TRUE(reader);
        EXPECT_EQ(reader->header().format, ext);
    }
}

TEST_F(TextReaderTest, CommentsBlankLinesCrlfAndNoFinalNewline)
{
    const Cloud cloud = load("c.xyz", "# made by hand\r\n\r\n// another\r\n1 2 3\r\n   \r\n  # indented comment\r\n"
                                      "4 5 6\r\n// trailing\r\n7 8 9");
    EXPECT_EQ(cloud.positions, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
}

TEST_F(TextReaderTest, FourColumnsGiveIntensity)
{
    auto reader = open("i.xyz", "1 2 3 0.5\n4 5 6 -12\n");
    ASSERT_TRUE(reader);
    EXPECT_EQ(reader->header().schema.scalarNames, std::vector<std::string>{"intensity"});
    auto cloud = readAll(*reader, 1000);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->scalars[0], (std::vector<double>{0.5, -12}));
}

TEST_F(TextReaderTest, SixColumnsByteColors)
{
    auto reader = open("rgb.xyz", "1 2 3 255 0 128\n4 5 6 10 20 30\n");
    ASSERT_TRUE(reader);
    EXPECT_TRUE(reader->header().schema.hasColors);
    EXPECT_FALSE(reader->header().schema.hasNormals);
    auto cloud = readAll(*reader, 1000);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->colors, (std::vector<std::uint8_t>{255, 0, 128, 10, 20, 30}));
}

TEST_F(TextReaderTest, SixColumnsNormals)
{
    auto reader = open("n.xyz", "1 2 3 0 0 1\n4 5 6 0.6 -0.8 0\n");
    ASSERT_TRUE(reader);
    EXPECT_TRUE(reader->header().schema.hasNormals);
    EXPECT_FALSE(reader->header().schema.hasColors);
    auto cloud = readAll(*reader, 1000);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->normals, (std::vector<float>{0, 0, 1, 0.6f, -0.8f, 0}));
}

TEST_F(TextReaderTest, SixColumnsFloatColors)
{
    auto reader = open("f.xyz", "1 2 3 0.5 1.0 0\n4 5 6 0.2 0.2 0.2\n");
    ASSERT_TRUE(reader);
    EXPECT_TRUE(reader->header().schema.hasColors);
    auto cloud = readAll(*reader, 1000);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->colors, (std::vector<std::uint8_t>{128, 255, 0, 51, 51, 51}));
}

TEST_F(TextReaderTest, SevenColumnsPtsIntensityAndColors)
{
    auto reader = open("scan.pts", "2\n1 2 3 -1035 97 59 38\n4 5 6 12 255 0 1\n");
    ASSERT_TRUE(reader);
    const auto& header = reader->header();
    EXPECT_EQ(header.format, "pts");
    EXPECT_EQ(header.declaredPoints, std::optional<std::uint64_t>(2));
    EXPECT_TRUE(header.schema.hasColors);
    EXPECT_EQ(header.schema.scalarNames, std::vector<std::string>{"intensity"});
    auto cloud = readAll(*reader, 1000);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->positions, (std::vector<double>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(cloud->scalars[0], (std::vector<double>{-1035, 12}));
    EXPECT_EQ(cloud->colors, (std::vector<std::uint8_t>{97, 59, 38, 255, 0, 1}));
}

TEST_F(TextReaderTest, SevenColumnsFloatColors)
{
    const Cloud cloud = load("f.pts", "1 2 3 7 0.0 0.5 1.0\n");
    EXPECT_EQ(cloud.colors, (std::vector<std::uint8_t>{0, 128, 255}));
}

TEST_F(TextReaderTest, NineColumnsEitherOrder)
{
    const Cloud rgbFirst = load("a.xyz", "1 2 3 10 20 30 0 1 0\n4 5 6 40 50 60 0 0 -1\n");
    EXPECT_EQ(rgbFirst.colors, (std::vector<std::uint8_t>{10, 20, 30, 40, 50, 60}));
    EXPECT_EQ(rgbFirst.normals, (std::vector<float>{0, 1, 0, 0, 0, -1}));
    const Cloud normalsFirst = load("b.xyz", "1 2 3 0 1 0 10 20 30\n4 5 6 0.6 0.8 0 40 50 60\n");
    EXPECT_EQ(normalsFirst.colors, (std::vector<std::uint8_t>{10, 20, 30, 40, 50, 60}));
    EXPECT_EQ(normalsFirst.normals, (std::vector<float>{0, 1, 0, 0.6f, 0.8f, 0}));
}

TEST_F(TextReaderTest, OtherCountsGiveNamedScalars)
{
    auto reader = open("s.txt", "1 2 3 4 5\n");
    ASSERT_TRUE(reader);
    EXPECT_EQ(reader->header().schema.scalarNames, (std::vector<std::string>{"scalar_4", "scalar_5"}));
    auto cloud = readAll(*reader, 1000);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->scalars, (std::vector<std::vector<double>>{{4}, {5}}));
}

TEST_F(TextReaderTest, CsvHeaderLine)
{
    auto reader = open("h.csv", "X,Y,Z,Intensity,R,G,B\n1,2,3,0.25,1,2,3\n");
    ASSERT_TRUE(reader);
    EXPECT_EQ(reader->header().schema.scalarNames, std::vector<std::string>{"intensity"});
    auto cloud = readAll(*reader, 1000);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->positions, (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(cloud->scalars[0], std::vector<double>{0.25});
    EXPECT_EQ(cloud->colors, (std::vector<std::uint8_t>{1, 2, 3})); // integers: 0-255, not unit floats
}

TEST_F(TextReaderTest, HeaderReordersColumns)
{
    const Cloud cloud = load("h.txt", "Z Y X temperature\n3 2 1 20.5\n");
    EXPECT_EQ(cloud.positions, (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(cloud.scalars, (std::vector<std::vector<double>>{{20.5}}));
}

TEST_F(TextReaderTest, CommentHeaderWithFloatColors)
{
    auto reader = open("cc.asc", "//X Y Z Rf Gf Bf\n1 2 3 1 0 1\n");
    ASSERT_TRUE(reader);
    EXPECT_TRUE(reader->header().schema.hasColors);
    auto cloud = readAll(*reader, 1000);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->colors, (std::vector<std::uint8_t>{255, 0, 255})); // Rf: floats even when 0 and 1
}

TEST_F(TextReaderTest, CommentHeaderOfAnotherWidthIsIgnored)
{
    const Cloud cloud = load("c.xyz", "# x y z nx ny nz\n1 2 3\n");
    EXPECT_EQ(cloud.positions, (std::vector<double>{1, 2, 3}));
    EXPECT_TRUE(cloud.normals.empty());
}

TEST_F(TextReaderTest, OverrideColumns)
{
    ReadOptions options;
    options.columns = "x,y,z,i,r,g,b";
    auto reader = open("o.txt", "1 2 3 4 5 6 7\n", options);
    ASSERT_TRUE(reader);
    auto cloud = readAll(*reader, 1000);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->scalars[0], std::vector<double>{4});
    EXPECT_EQ(cloud->colors, (std::vector<std::uint8_t>{5, 6, 7}));

    options.columns = "_,z,y,x,nx,ny,nz,reflectance";
    const Cloud other = load("p.txt", "99 3 2 1 0 0 1 0.7\n", options);
    EXPECT_EQ(other.positions, (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(other.normals, (std::vector<float>{0, 0, 1}));
    EXPECT_EQ(other.scalars, (std::vector<std::vector<double>>{{0.7}}));

    options.columns = "x,y,z,r,g,b"; // data that detection would take for normals
    EXPECT_EQ(load("q.txt", "1 2 3 0 0 1\n", options).colors, (std::vector<std::uint8_t>{0, 0, 1}));
}

TEST_F(TextReaderTest, OverrideWinsOverHeader)
{
    ReadOptions options;
    options.columns = "y,x,z";
    EXPECT_EQ(load("h.csv", "X,Y,Z\n1,2,3\n", options).positions, (std::vector<double>{2, 1, 3}));
}

TEST_F(TextReaderTest, PtsBlocks)
{
    auto reader = open("b.pts", "2\n1 2 3 5\n4 5 6 5\n1\n7 8 9 5\n0\n3\n1 1 1 1\n2 2 2 2\n3 3 3 3\n");
    ASSERT_TRUE(reader);
    EXPECT_EQ(reader->header().declaredPoints, std::optional<std::uint64_t>(2));
    auto cloud = readAll(*reader, 1);
    ASSERT_TRUE(cloud.ok()) << cloud.error().message;
    EXPECT_EQ(cloud->size(), 6u);
    EXPECT_EQ(reader->header().declaredPoints, std::optional<std::uint64_t>(6)); // final after the end
    EXPECT_EQ(cloud->positions[6], 7);
}

TEST_F(TextReaderTest, NanAndInfSkippedAndCounted)
{
    auto reader = open("n.xyz", "1 2 3\nnan 0 0\n0 inf 0\n0 0 -INF\n4 5 6\n0 0 NaN\n1e999 0 0\n");
    ASSERT_TRUE(reader);
    auto cloud = readAll(*reader, 1);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->positions, (std::vector<double>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(reader->pointsRead(), 2u);
    EXPECT_EQ(reader->pointsSkipped(), 5u);
}

TEST_F(TextReaderTest, NanPointsStillCountInPtsBlocks)
{
    auto reader = open("n.pts", "3\n1 2 3\nnan nan nan\n4 5 6\n");
    ASSERT_TRUE(reader);
    auto cloud = readAll(*reader, 1000);
    ASSERT_TRUE(cloud.ok());
    EXPECT_EQ(cloud->size(), 2u);
    EXPECT_EQ(reader->pointsSkipped(), 1u);
}

TEST_F(TextReaderTest, ByteColorsClamped)
{
    EXPECT_EQ(load("c.pts", "1 2 3 0 300 -4 12.6\n").colors, (std::vector<std::uint8_t>{255, 0, 13}));
}

TEST_F(TextReaderTest, BatchSizesGiveTheSamePoints)
{
    std::string text = "# header comment\n";
    for (int i = 0; i < 2500; ++i) {
        text += std::to_string(i * 0.5) + " " + std::to_string(-i) + " " + std::to_string(i % 7) + " 0 0 1\n";
        if (i % 100 == 3) text += "nan 0 0 0 0 1\n\n";
    }
    writeText(m_dir / "big.xyz", text);
    std::vector<Cloud> clouds;
    for (const std::size_t maxPoints : {std::size_t(1), std::size_t(1000), std::size_t(1) << 30}) {
        auto reader = TextReader::open(m_dir / "big.xyz", {});
        ASSERT_TRUE(reader.ok());
        auto cloud = readAll(*reader.value(), maxPoints);
        ASSERT_TRUE(cloud.ok());
        EXPECT_EQ(reader.value()->pointsSkipped(), 25u);
        clouds.push_back(std::move(cloud).value());
    }
    ASSERT_EQ(clouds[0].size(), 2500u);
    EXPECT_EQ(clouds[0].positions[3 * 2499], 2499 * 0.5);
    for (const Cloud& c : clouds) {
        EXPECT_EQ(c.positions, clouds[0].positions);
        EXPECT_EQ(c.normals, clouds[0].normals);
    }
}

TEST_F(TextReaderTest, FactoryPassesOptions)
{
    writeText(m_dir / "f.xyz", "1 2 3 4\n");
    ReadOptions options;
    options.columns = "x,y,z,height";
    auto reader = openPointReader(m_dir / "f.xyz", options);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    EXPECT_EQ(reader.value()->header().schema.scalarNames, std::vector<std::string>{"height"});
}

TEST_F(TextReaderTest, RealKittenXyzWithNormals)
{
    SKIP_WITHOUT_SHARED_DATA();
    auto reader = TextReader::open(stylos::test::sharedData() / "formats" / "cgal_kitten.xyz", {});
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    const auto& header = reader.value()->header();
    EXPECT_EQ(header.format, "xyz");
    EXPECT_TRUE(header.schema.hasNormals);
    EXPECT_FALSE(header.schema.hasColors);
    auto cloud = readAll(*reader.value(), 4096);
    ASSERT_TRUE(cloud.ok()) << cloud.error().message;
    ASSERT_EQ(cloud->size(), 5210u);
    EXPECT_EQ(reader.value()->pointsSkipped(), 0u);
    EXPECT_EQ(cloud->positions[0], -0.0721898);
    EXPECT_EQ(cloud->positions[1], -0.159749);
    EXPECT_EQ(cloud->positions[2], -0.108444);
    EXPECT_EQ(cloud->normals[0], 0.340472f);
    EXPECT_EQ(cloud->normals[1], 0.937712f);
    EXPECT_EQ(cloud->normals[2], -0.0690972f);
}

TEST_F(TextReaderTest, RealLeicaPts)
{
    SKIP_WITHOUT_SHARED_DATA();
    auto reader = TextReader::open(stylos::test::sharedData() / "formats" / "pdal_test.pts", {});
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    const auto& header = reader.value()->header();
    EXPECT_EQ(header.format, "pts");
    EXPECT_EQ(header.declaredPoints, std::optional<std::uint64_t>(19));
    EXPECT_TRUE(header.schema.hasColors);
    EXPECT_FALSE(header.schema.hasNormals);
    EXPECT_EQ(header.schema.scalarNames, std::vector<std::string>{"intensity"});
    auto cloud = readAll(*reader.value(), 5);
    ASSERT_TRUE(cloud.ok()) << cloud.error().message;
    ASSERT_EQ(cloud->size(), 19u);
    EXPECT_EQ(cloud->positions[0], 3.980972);
    EXPECT_EQ(cloud->positions[1], -2.006119);
    EXPECT_EQ(cloud->positions[2], -0.010086);
    EXPECT_EQ(cloud->scalars[0][0], -1035);
    EXPECT_EQ(cloud->colors[0], 97);
    EXPECT_EQ(cloud->colors[1], 59);
    EXPECT_EQ(cloud->colors[2], 38);
}

TEST_F(TextReaderTest, ByteOrderMarkIgnored)
{
    EXPECT_EQ(load("bom.csv", "\xEF\xBB\xBFX,Y,Z\n1,2,3\n").positions, (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(load("bom.xyz", "\xEF\xBB\xBF" "1 2 3\n").positions, (std::vector<double>{1, 2, 3}));
}

TEST_F(TextReaderTest, QuotedCsvHeader)
{
    const Cloud cloud = load("q.csv", "\"X\",\"Y\",\"Z\",\"Reflectance\"\n1,2,3,0.5\n");
    EXPECT_EQ(cloud.positions, (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(cloud.scalars, (std::vector<std::vector<double>>{{0.5}}));
}

// ---- Errors ----

TEST_F(TextReaderTest, WrongColumnCount)
{
    const Error e = failure("w.xyz", "1 2 3\n4 5 6\n# ok\n7 8\n", "line 4");
    EXPECT_EQ(e.code, ErrorCode::Malformed);
    EXPECT_NE(e.message.find("2 columns where 3 are expected"), std::string::npos) << e.message;
    EXPECT_EQ(failure("x.xyz", "1 2 3\n4 5 6 7\n", "line 2").code, ErrorCode::Malformed);
    EXPECT_EQ(failure("h.csv", "x,y,z\n1,2,3,4\n", "line 2").code, ErrorCode::Malformed);
}

TEST_F(TextReaderTest, NotANumber)
{
    const Error e = failure("n.xyz", "1 2 3\n4 abc 6\n", "line 2");
    EXPECT_EQ(e.code, ErrorCode::Malformed);
    EXPECT_NE(e.message.find("column 2 is not a number: \"abc\""), std::string::npos) << e.message;
    EXPECT_EQ(failure("e.csv", "1,2,3\n4,,6\n", "line 2").code, ErrorCode::Malformed);
    EXPECT_EQ(failure("f.xyz", "1.5.2 2 3\n", "line 1").code, ErrorCode::Malformed);     // first data line
    EXPECT_EQ(failure("g.xyz", "1 2 3\nx y z\n", "line 2").code, ErrorCode::Malformed); // header after data
    EXPECT_EQ(failure("s.xyz", "1 2 3\n4 +-5 6\n", "line 2").code, ErrorCode::Malformed);
    // Far beyond the sampled lines.
    std::string text;
    for (int i = 0; i < 200; ++i) text += "1 2 3\n";
    EXPECT_EQ(failure("late.xyz", text + "1 2 3q\n", "line 201").code, ErrorCode::Malformed);
}

TEST_F(TextReaderTest, HeaderWithoutCoordinates)
{
    EXPECT_EQ(failure("h.csv", "a,b,c\n1,2,3\n", "line 1").code, ErrorCode::Malformed);
    EXPECT_EQ(failure("t.txt", "hello world\n", "line 1").code, ErrorCode::Malformed);
}

TEST_F(TextReaderTest, TooFewColumnsForAPoint)
{
    EXPECT_EQ(failure("two.xyz", "1.5 2\n", "line 1").code, ErrorCode::Malformed);
}

TEST_F(TextReaderTest, NoData)
{
    EXPECT_EQ(failure("e.xyz", "", "").code, ErrorCode::Empty);
    EXPECT_EQ(failure("c.xyz", "# only\n\n// comments\n", "").code, ErrorCode::Empty);
    EXPECT_EQ(failure("h.csv", "x,y,z\n", "").code, ErrorCode::Empty);
    EXPECT_EQ(failure("z.pts", "0\n", "").code, ErrorCode::Empty);
    EXPECT_EQ(failure("t.pts", "5\n", "line 1").code, ErrorCode::Truncated);
}

TEST_F(TextReaderTest, PtsCountMismatch)
{
    Error e = failure("few.pts", "3\n1 2 3\n4 5 6\n", "line 3");
    EXPECT_EQ(e.code, ErrorCode::Truncated);
    EXPECT_NE(e.message.find("2 of the 3 points announced at line 1"), std::string::npos) << e.message;
    e = failure("more.pts", "2\n1 2 3\n4 5 6\n7 8 9\n", "line 4");
    EXPECT_EQ(e.code, ErrorCode::Malformed);
    e = failure("block.pts", "2\n1 2 3\n4 5 6\n3\n1 2 3\n2\n1 1 1\n2 2 2\n", "line 6");
    EXPECT_EQ(e.code, ErrorCode::Truncated);
    EXPECT_NE(e.message.find("announced at line 4"), std::string::npos) << e.message;
    EXPECT_EQ(failure("last.pts", "1\n1 2 3\n2\n1 2 3\n4 5 6\n7 8 9\n", "line 6").code, ErrorCode::Malformed);
}

TEST_F(TextReaderTest, BadOverride)
{
    ReadOptions options;
    for (const std::string spec : {"x,y", "x,y,z,nx", "x,y,z,r,g", "x,x,y,z", "x,y,z,,i", "x,y,z,i,intensity"}) {
        options.columns = spec;
        EXPECT_EQ(failure("o.xyz", "1 2 3 4 5 6\n", "", options).code, ErrorCode::InvalidArgument) << spec;
    }
    options.columns = "x,y,z,i";
    EXPECT_EQ(failure("p.xyz", "1 2 3\n", "line 1", options).code, ErrorCode::Malformed);
}

TEST_F(TextReaderTest, LineOver64MiB)
{
    // Once among the first lines (found when opening), once far down (found when reading).
    for (const int before : {1, 100}) {
        const std::string name = "long" + std::to_string(before) + ".xyz";
        {
            std::ofstream out(m_dir / name, std::ios::binary);
            for (int i = 0; i < before; ++i) out << "1 2 3\n";
            const std::string chunk(1 << 20, '7');
            for (int i = 0; i < 65; ++i) out << chunk;
            out << " 2 3\n4 5 6\n";
        }
        const Error e = failureOf(name, "line " + std::to_string(before + 1));
        EXPECT_EQ(e.code, ErrorCode::Malformed);
        EXPECT_NE(e.message.find("64 MiB"), std::string::npos) << e.message;
    }
}
