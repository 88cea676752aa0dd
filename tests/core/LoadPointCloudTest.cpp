// loadPointCloud: every point of a file (origin rounded to the metre, positions relative to it, normals
// kept), the cells of a .poct as points with the leaf edge as spacing, and the error paths.
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"

#include <gtest/gtest.h>

namespace stylos::core::cloud {
namespace {

using test::TempDir;

/** A PLY of @p n points at (1000.25 + i, −20.5, 3 + i/1000) with normal (0, 0, 1). */
std::filesystem::path writeSmallPly(const TempDir& dir, std::size_t n)
{
    io::PointSchema schema;
    schema.hasNormals = true;
    const auto path = dir / "small.ply";
    auto writer = io::PlyWriter::create(path, schema);
    EXPECT_TRUE(writer.ok());
    io::PointBatch batch;
    batch.reset(schema, n);
    for (std::size_t i = 0; i < n; ++i) {
        batch.positions.insert(batch.positions.end(), {1000.25 + double(i), -20.5, 3.0 + double(i) / 1000.0});
        batch.normals.insert(batch.normals.end(), {0.0f, 0.0f, 1.0f});
    }
    EXPECT_TRUE(writer->write(batch).ok());
    EXPECT_TRUE(writer->finish().ok());
    return path;
}

TEST(LoadPointCloudTest, PointFileKeepsEveryPointRelativeToARoundOrigin)
{
    TempDir dir;
    const auto path = writeSmallPly(dir, 100);
    const auto cloud = loadPointCloud(path);
    ASSERT_TRUE(cloud.ok()) << cloud.error().message;
    ASSERT_EQ(cloud->size(), 100u);
    EXPECT_EQ(cloud->origin, Eigen::Vector3d(1000.0, -21.0, 3.0)); // the first point rounded (halves away from zero)
    for (std::size_t i = 0; i < 100; ++i) {
        EXPECT_NEAR((cloud->world(i) - Eigen::Vector3d(1000.25 + double(i), -20.5, 3.0 + double(i) / 1000.0)).norm(), 0.0, 1e-5);
        EXPECT_EQ(cloud->normal(i), Eigen::Vector3d(0, 0, 1));
    }
    EXPECT_EQ(cloud->spacing, 0.0);
    EXPECT_EQ(cloud->source, path.string());
    CloudLoadOptions noNormals;
    noNormals.keepNormals = false;
    EXPECT_FALSE(loadPointCloud(path, noNormals)->hasNormals());
}

TEST(LoadPointCloudTest, OctreeCellsBecomePointsWithTheLeafEdgeAsSpacing)
{
    TempDir dir;
    const auto scan = dir / "drum.ply";
    auto options = test::coarse(0.02);
    options.writeNormals = true;
    test::generate(synth::SyntheticKind::Drum, options, scan);
    octree::BuildOptions build;
    build.depth = 7;
    const auto report = octree::buildOctreeFile(scan, dir / "drum.poct", build);
    ASSERT_TRUE(report.ok()) << report.error().message;
    const auto tree = octree::PackedOctree::open(dir / "drum.poct");
    ASSERT_TRUE(tree.ok());

    const auto cloud = loadPointCloud(dir / "drum.poct");
    ASSERT_TRUE(cloud.ok()) << cloud.error().message;
    EXPECT_EQ(cloud->size(), report->leaves);
    EXPECT_TRUE(cloud->hasNormals());
    EXPECT_DOUBLE_EQ(cloud->spacing, tree->box().cellSize(7));
    std::size_t i = 0;
    tree->forEachCell(7, [&](const octree::CellView& cell) {
        EXPECT_NEAR((cloud->world(i) - Eigen::Vector3d(cell.centre[0], cell.centre[1], cell.centre[2])).norm(), 0.0, 1e-6);
        EXPECT_NEAR((cloud->normal(i) - Eigen::Vector3d(cell.normal[0], cell.normal[1], cell.normal[2])).norm(), 0.0, 1e-7);
        ++i;
        return true;
    });
    CloudLoadOptions coarser;
    coarser.octreeLevel = 4;
    EXPECT_EQ(loadPointCloud(dir / "drum.poct", coarser)->size(), tree->cellCount(4));
    coarser.octreeLevel = 8;
    const auto deep = loadPointCloud(dir / "drum.poct", coarser);
    ASSERT_FALSE(deep.ok());
    EXPECT_EQ(deep.error().message, (dir / "drum.poct").string() + ": level 8 is deeper than the octree (depth 7)");
}

TEST(LoadPointCloudTest, ErrorsNameTheFile)
{
    TempDir dir;
    EXPECT_EQ(loadPointCloud(dir / "missing.ply").error().code, ErrorCode::NotFound);
    const auto path = writeSmallPly(dir, 1000);
    CloudLoadOptions budget;
    budget.maxBytes = 1000 * 24 - 1;
    const auto over = loadPointCloud(path, budget);
    ASSERT_FALSE(over.ok());
    EXPECT_EQ(over.error().code, ErrorCode::OutOfBudget);
    EXPECT_EQ(over.error().message.rfind(path.string() + ": loading 1000 points needs", 0), 0u) << over.error().message;
    budget.maxBytes = 1000 * 24;
    EXPECT_TRUE(loadPointCloud(path, budget).ok());
    SilentProgress cancelled;
    cancelled.cancel();
    EXPECT_EQ(loadPointCloud(path, {}, &cancelled).error().code, ErrorCode::Cancelled);
}

} // namespace
} // namespace stylos::core::cloud
