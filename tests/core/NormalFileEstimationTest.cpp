// estimateNormalsForFile: the tiled path agrees with the in-memory one, attributes pass through,
// nothing is left on disk whatever happens, and a real scan comes out facing outward.
#include "TestSupport.h"

#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/normals/NormalFileEstimation.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <vector>

using namespace stylos::core;
using namespace stylos::core::normals;
using stylos::test::TempDir;
namespace fs = std::filesystem;

namespace {

/** A noisy random sphere of radius 2 m far from the origin, with colours and an "index" scalar. */
io::PointBatch makeCloud(std::size_t n)
{
    io::PointBatch cloud;
    cloud.reset(io::PointSchema{false, true, {"index"}}, n);
    std::mt19937_64 random(21);
    std::normal_distribution<double> gauss;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = gauss(random), y = gauss(random), z = gauss(random);
        const double scale = 2.0 * (1.0 + 0.001 * gauss(random)) / std::sqrt(x * x + y * y + z * z);
        cloud.positions.insert(cloud.positions.end(), {4000.0 + x * scale, -300.0 + y * scale, 20.0 + z * scale});
        cloud.colors.insert(cloud.colors.end(), {std::uint8_t(i), std::uint8_t(i >> 8), 7});
        cloud.scalars[0].push_back(double(i));
    }
    return cloud;
}

void writeCloud(const fs::path& path, const io::PointBatch& cloud)
{
    io::PlyWriterOptions options;
    options.scalarTypes = {io::PlyScalarType::Float64};
    auto writer = io::PlyWriter::create(path, io::PointSchema{false, true, {"index"}}, options);
    ASSERT_TRUE(writer) << writer.error().message;
    ASSERT_TRUE(writer->write(cloud));
    ASSERT_TRUE(writer->finish());
}

io::PointBatch readCloud(const fs::path& path, io::PointSchema* schema = nullptr)
{
    io::PointBatch all, batch;
    auto reader = io::openPointReader(path);
    EXPECT_TRUE(reader) << reader.error().message;
    if (!reader) return all;
    if (schema) *schema = (*reader)->header().schema;
    for (;;) {
        auto got = (*reader)->read(batch, 50000);
        EXPECT_TRUE(got) << got.error().message;
        if (!got || *got == 0) break;
        all.positions.insert(all.positions.end(), batch.positions.begin(), batch.positions.end());
        all.normals.insert(all.normals.end(), batch.normals.begin(), batch.normals.end());
        all.colors.insert(all.colors.end(), batch.colors.begin(), batch.colors.end());
        all.scalars.resize(batch.scalars.size());
        for (std::size_t s = 0; s < batch.scalars.size(); ++s)
            all.scalars[s].insert(all.scalars[s].end(), batch.scalars[s].begin(), batch.scalars[s].end());
    }
    return all;
}

std::size_t filesIn(const fs::path& folder)
{
    return static_cast<std::size_t>(std::distance(fs::recursive_directory_iterator(folder), {}));
}

} // namespace

TEST(NormalFileEstimation, TinyBudgetTilesAgreeWithInMemory)
{
    TempDir dir;
    const auto cloud = makeCloud(30000);
    writeCloud(dir / "in.ply", cloud);
    std::vector<float> expected(cloud.positions.size());
    ASSERT_TRUE(estimateNormals(cloud.positions, expected));

    NormalFileOptions options;
    options.memoryBudget = 256u << 10; // ~1,600 points per tile: forces dozens of tiles
    options.normals.threads = 2;
    options.temporaryDirectory = dir.path();
    auto report = estimateNormalsForFile(dir / "in.ply", dir / "out.ply", options);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_GE(report->tiles, 16u);
    EXPECT_GT(report->margin, 0.0);
    EXPECT_GT(report->haloPoints, 0u);
    EXPECT_LT(report->peakTilePoints, 30000u / 4);
    EXPECT_EQ(report->normals.points, 30000u);
    EXPECT_EQ(report->normals.truncated, 0u);
    EXPECT_EQ(filesIn(dir.path()), 2u) << "temporary files left behind";

    io::PointSchema schema;
    const auto out = readCloud(dir / "out.ply", &schema);
    EXPECT_EQ(schema, (io::PointSchema{true, true, {"index"}}));
    ASSERT_EQ(out.size(), 30000u);
    // Match by position; the passed-through index and colour must agree with that position.
    std::map<std::array<double, 3>, std::size_t> where;
    for (std::size_t i = 0; i < cloud.size(); ++i)
        where[{cloud.positions[3 * i], cloud.positions[3 * i + 1], cloud.positions[3 * i + 2]}] = i;
    std::vector<bool> seen(cloud.size(), false);
    for (std::size_t j = 0; j < out.size(); ++j) {
        const auto found = where.find({out.positions[3 * j], out.positions[3 * j + 1], out.positions[3 * j + 2]});
        ASSERT_NE(found, where.end()) << "output point " << j << " is not an input point";
        const std::size_t i = found->second;
        ASSERT_FALSE(seen[i]) << "input point " << i << " written twice";
        seen[i] = true;
        EXPECT_EQ(out.scalars[0][j], double(i));
        EXPECT_EQ(out.colors[3 * j], std::uint8_t(i));
        for (int d = 0; d < 3; ++d) ASSERT_NEAR(out.normals[3 * j + d], expected[3 * i + d], 1e-6) << "point " << i;
    }
}

TEST(NormalFileEstimation, CloudThatFitsIsOnePieceInInputOrder)
{
    TempDir dir;
    const auto cloud = makeCloud(5000);
    writeCloud(dir / "in.ply", cloud);
    std::vector<float> expected(cloud.positions.size()), quality(cloud.size());
    ASSERT_TRUE(estimateNormals(cloud.positions, expected, {}, nullptr, quality));

    NormalFileOptions options;
    options.writeQuality = true;
    SilentProgress progress;
    auto report = estimateNormalsForFile(dir / "in.ply", dir / "out.ply", options, &progress);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_EQ(report->tiles, 0u);
    EXPECT_EQ(progress.last(), 1.0);
    io::PointSchema schema;
    const auto out = readCloud(dir / "out.ply", &schema);
    EXPECT_EQ(schema, (io::PointSchema{true, true, {"index", "surface_variation"}}));
    ASSERT_EQ(out.positions, cloud.positions);
    EXPECT_EQ(out.normals, expected);
    for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_EQ(out.scalars[1][i], double(quality[i]));
    EXPECT_EQ(filesIn(dir.path()), 2u);
}

TEST(NormalFileEstimation, CancelLeavesNothing)
{
    TempDir dir;
    writeCloud(dir / "in.ply", makeCloud(20000));
    NormalFileOptions options;
    options.memoryBudget = 256u << 10;
    options.temporaryDirectory = dir.path();
    SilentProgress before;
    before.cancel();
    auto report = estimateNormalsForFile(dir / "in.ply", dir / "out.ply", options, &before);
    ASSERT_FALSE(report);
    EXPECT_EQ(report.error().code, ErrorCode::Cancelled);
    EXPECT_EQ(filesIn(dir.path()), 1u);

    // Cancelled while tiles are being estimated (temporary files exist at that moment).
    struct CancelInPassThree final : ProgressSink {
        std::atomic<bool> cancel{false};
        void update(double fraction) override
        {
            if (fraction > 0.6) cancel = true;
        }
        bool isCancelRequested() const override { return cancel; }
    } midway;
    report = estimateNormalsForFile(dir / "in.ply", dir / "out.ply", options, &midway);
    ASSERT_FALSE(report);
    EXPECT_EQ(report.error().code, ErrorCode::Cancelled);
    EXPECT_EQ(filesIn(dir.path()), 1u);
}

TEST(NormalFileEstimation, BudgetTooSmallForADensePileIsOutOfBudget)
{
    // 6,000 copies of one point cannot be split into tiles: the message says what would be needed.
    TempDir dir;
    io::PointBatch pile;
    pile.reset(io::PointSchema{false, true, {"index"}}, 6000);
    for (int i = 0; i < 6000; ++i) {
        pile.positions.insert(pile.positions.end(), {1.0, 2.0, 3.0});
        pile.colors.insert(pile.colors.end(), {0, 0, 0});
        pile.scalars[0].push_back(i);
    }
    writeCloud(dir / "in.ply", pile);
    NormalFileOptions options;
    options.memoryBudget = 64u << 10;
    options.temporaryDirectory = dir.path();
    auto report = estimateNormalsForFile(dir / "in.ply", dir / "out.ply", options);
    ASSERT_FALSE(report);
    EXPECT_EQ(report.error().code, ErrorCode::OutOfBudget);
    EXPECT_NE(report.error().message.find("KiB"), std::string::npos) << report.error().message;
    EXPECT_EQ(filesIn(dir.path()), 1u);
}

TEST(NormalFileEstimation, BadInputsAreReported)
{
    TempDir dir;
    auto missing = estimateNormalsForFile(dir / "absent.ply", dir / "out.ply");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
    NormalFileOptions tiny;
    tiny.memoryBudget = 1000;
    EXPECT_EQ(estimateNormalsForFile(dir / "absent.ply", dir / "out.ply", tiny).error().code,
              ErrorCode::InvalidArgument);
    stylos::test::writeText(dir / "bad.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 10\n"
                                             "property float x\nproperty float y\nproperty float z\nend_header\n");
    auto truncated = estimateNormalsForFile(dir / "bad.ply", dir / "out.ply");
    ASSERT_FALSE(truncated);
    EXPECT_EQ(truncated.error().code, ErrorCode::Truncated);
    EXPECT_EQ(filesIn(dir.path()), 1u);
}

TEST(NormalFileEstimation, IgeaScanFacesOutwardTiledOrNot)
{
    // The real scan (134,345 points), in one piece and in tiles: normals face away from the centroid,
    // and the tiled run gives the same normals except where it reports a truncated neighbourhood.
    SKIP_WITHOUT_SHARED_DATA();
    TempDir dir;
    std::vector<io::PointBatch> outputs;
    std::uint64_t truncated = 0;
    for (std::size_t budget : {std::size_t(256) << 20, std::size_t(4) << 20}) {
        NormalFileOptions options;
        options.memoryBudget = budget;
        auto report = estimateNormalsForFile(stylos::test::sharedData() / "scans" / "igea_134k.ply", dir / "igea.ply", options);
        ASSERT_TRUE(report) << report.error().message;
        EXPECT_EQ(report->tiles == 0, budget > (64u << 20));
        truncated = report->normals.truncated;
        outputs.push_back(readCloud(dir / "igea.ply"));
        const io::PointBatch& out = outputs.back();
        ASSERT_EQ(out.size(), 134345u);
        std::size_t outward = 0;
        for (std::size_t i = 0; i < out.size(); ++i) {
            double dot = 0;
            for (int d = 0; d < 3; ++d) dot += out.normals[3 * i + d] * (out.positions[3 * i + d] - report->normals.centre[d]);
            outward += dot >= 0;
        }
        EXPECT_GE(double(outward) / double(out.size()), 0.9) << "budget " << (budget >> 20) << " MiB";
    }
    EXPECT_LT(truncated, 134u) << "more than 0.1 % of neighbourhoods cut by tiles";
    std::map<std::array<double, 3>, std::size_t> where;
    const io::PointBatch &whole = outputs[0], &tiled = outputs[1];
    for (std::size_t i = 0; i < whole.size(); ++i)
        where[{whole.positions[3 * i], whole.positions[3 * i + 1], whole.positions[3 * i + 2]}] = i;
    std::size_t different = 0;
    for (std::size_t j = 0; j < tiled.size(); ++j) {
        const auto found = where.find({tiled.positions[3 * j], tiled.positions[3 * j + 1], tiled.positions[3 * j + 2]});
        ASSERT_NE(found, where.end());
        for (int d = 0; d < 3; ++d)
            if (std::abs(tiled.normals[3 * j + d] - whole.normals[3 * found->second + d]) > 1e-6f) {
                ++different;
                break;
            }
    }
    EXPECT_LE(different, truncated);
}
