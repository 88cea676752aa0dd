// PlyWriter: round trips through PlyReader, atomic output, bad arguments.
#include "TestSupport.h"

#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/io/PointFileFormat.h"

#include <gtest/gtest.h>

using namespace stylos::core;
using namespace stylos::core::io;
using stylos::test::TempDir;

TEST(PlyWriter, RoundTripWithNormalsColoursAndScalars)
{
    TempDir dir;
    PointSchema schema{true, true, {"intensity", "scan_id", "gps_time"}};
    PlyWriterOptions options;
    options.scalarTypes = {PlyScalarType::UInt16, PlyScalarType::UInt8, PlyScalarType::Float64};
    options.comments = {"written by a test"};
    auto writer = PlyWriter::create(dir / "out.ply", schema, options);
    ASSERT_TRUE(writer) << writer.error().message;

    PointBatch batch;
    batch.reset(schema, 2);
    batch.positions = {123456.789012345, -1.0, 2.0, 3.0, 4.0, 5.0};
    batch.normals = {0, 0, 1, 1, 0, 0};
    batch.colors = {1, 2, 3, 250, 251, 252};
    batch.scalars = {{1000, 65535}, {7, 3}, {1e9 + 0.123456, 2.5}};
    ASSERT_TRUE(writer->write(batch));
    ASSERT_TRUE(writer->write(batch));
    EXPECT_FALSE(std::filesystem::exists(dir / "out.ply")) << "visible before finish()";
    ASSERT_TRUE(writer->finish());
    EXPECT_EQ(writer->pointsWritten(), 4u);

    auto reader = openPointReader(dir / "out.ply");
    ASSERT_TRUE(reader) << reader.error().message;
    EXPECT_EQ((*reader)->header().schema, schema);
    EXPECT_EQ((*reader)->header().declaredPoints, 4u);
    PointBatch back;
    auto got = (*reader)->read(back, 10);
    ASSERT_TRUE(got) << got.error().message;
    ASSERT_EQ(*got, 4u);
    EXPECT_EQ(back.positions[0], 123456.789012345);
    EXPECT_EQ(back.positions[9], 3.0);
    EXPECT_EQ(back.normals[5], 0.0f);
    EXPECT_EQ(back.colors[5], 252);
    EXPECT_EQ(back.scalars[0][1], 65535.0);
    EXPECT_EQ(back.scalars[1][2], 7.0);
    EXPECT_EQ(back.scalars[2][0], 1e9 + 0.123456);
    auto end = (*reader)->read(back, 10);
    ASSERT_TRUE(end);
    EXPECT_EQ(*end, 0u);
    // Nothing but the result is left in the folder.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}

TEST(PlyWriter, AbandonedWriterLeavesNothing)
{
    TempDir dir;
    {
        auto writer = PlyWriter::create(dir / "gone.ply", PointSchema{});
        ASSERT_TRUE(writer);
        PointBatch batch;
        batch.reset(PointSchema{}, 1);
        batch.positions = {1, 2, 3};
        ASSERT_TRUE(writer->write(batch));
    }
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
}

TEST(PlyWriter, RefusesBadArgumentsAndUnwritablePlaces)
{
    TempDir dir;
    auto badName = PlyWriter::create(dir / "x.ply", PointSchema{false, false, {"two words"}});
    ASSERT_FALSE(badName);
    EXPECT_EQ(badName.error().code, ErrorCode::InvalidArgument);
    auto noDir = PlyWriter::create(dir / "no/such/dir/x.ply", PointSchema{});
    ASSERT_FALSE(noDir);
    EXPECT_EQ(noDir.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(noDir.error().message.find("x.ply"), std::string::npos);

    auto writer = PlyWriter::create(dir / "y.ply", PointSchema{true, false, {}});
    ASSERT_TRUE(writer);
    PointBatch wrong;
    wrong.reset(PointSchema{}, 1);
    wrong.positions = {1, 2, 3};
    auto s = writer->write(wrong);
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().code, ErrorCode::InvalidArgument);
}
