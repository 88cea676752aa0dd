// Normals scan by scan (core/src/normals/ScanGroups.h): two registered scans of one sphere, a registration error
// apart, against the true normals of each scan's own sphere; held and tiled agree; a column that is not a scan
// column, or a single scan, leaves the estimation as it was.
#include "TestSupport.h"

#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/normals/NormalFileEstimation.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <span>
#include <vector>

using namespace stylos::core;
using namespace stylos::core::normals;
using stylos::test::TempDir;
namespace fs = std::filesystem;

namespace {

constexpr double Radius = 2.0;
/** Scan 1 sees the sphere shifted by this along x: on the sides facing ±x its sheet lies 8 cm off scan 0's,
 *  about the radius of a 16-point neighbourhood of the merged cloud (points 3.5 cm apart). */
constexpr std::array<double, 3> Shift{0.08, 0.0, 0.0};

struct TwoScans {
    io::PointBatch cloud;                   ///< x y z and the scan column
    std::vector<std::array<double, 3>> truth; ///< each point's true normal (its own scan's sphere)
};

/** @p scans scans of @p perScan points each, scan s shifted by s × Shift; scan 0's id is 0, scan s's s × @p idStep. */
TwoScans makeScans(std::size_t perScan, double idStep = 1.0, const char* column = "scan_id", int scans = 2)
{
    TwoScans s;
    s.cloud.reset(io::PointSchema{false, false, {column}}, 0);
    std::mt19937_64 random(5);
    std::normal_distribution<double> gauss;
    for (int scan = 0; scan < scans; ++scan)
        for (std::size_t i = 0; i < perScan; ++i) {
            double d[3] = {gauss(random), gauss(random), gauss(random)};
            const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            for (double& v : d) v /= length;
            for (int a = 0; a < 3; ++a)
                s.cloud.positions.push_back(100.0 + Radius * d[a] + scan * Shift[std::size_t(a)]);
            s.cloud.scalars[0].push_back(scan * idStep);
            s.truth.push_back({d[0], d[1], d[2]});
        }
    return s;
}

void writeScans(const fs::path& path, const io::PointBatch& cloud, const char* column = "scan_id")
{
    io::PlyWriterOptions options;
    options.scalarTypes = {io::PlyScalarType::Float64};
    auto writer = io::PlyWriter::create(path, io::PointSchema{false, false, {column}}, options);
    ASSERT_TRUE(writer) << writer.error().message;
    ASSERT_TRUE(writer->write(cloud));
    ASSERT_TRUE(writer->finish());
}

/** The output's normals by input position (the tiled output is in tile order). */
std::map<std::array<double, 3>, std::array<float, 3>> normalsByPosition(const fs::path& path)
{
    std::map<std::array<double, 3>, std::array<float, 3>> out;
    auto reader = io::openPointReader(path);
    EXPECT_TRUE(reader) << reader.error().message;
    if (!reader) return out;
    io::PointBatch batch;
    for (;;) {
        auto got = (*reader)->read(batch, 50000);
        EXPECT_TRUE(got);
        if (!got || *got == 0) break;
        for (std::size_t i = 0; i < batch.size(); ++i)
            out[{batch.positions[3 * i], batch.positions[3 * i + 1], batch.positions[3 * i + 2]}] = {
                batch.normals[3 * i], batch.normals[3 * i + 1], batch.normals[3 * i + 2]};
    }
    return out;
}

/** How many points' normals are more than @p degrees off their true normal (as axes: the sign aside). */
std::size_t countOff(const TwoScans& s, const std::map<std::array<double, 3>, std::array<float, 3>>& normals,
                     double degrees)
{
    std::size_t off = 0;
    for (std::size_t i = 0; i < s.truth.size(); ++i) {
        const auto found = normals.find({s.cloud.positions[3 * i], s.cloud.positions[3 * i + 1], s.cloud.positions[3 * i + 2]});
        EXPECT_NE(found, normals.end()) << "point " << i << " missing";
        if (found == normals.end()) continue;
        double dot = 0;
        for (int a = 0; a < 3; ++a) dot += double(found->second[std::size_t(a)]) * s.truth[i][std::size_t(a)];
        if (std::fabs(dot) < std::cos(degrees * 3.14159265358979 / 180.0)) ++off;
    }
    return off;
}

} // namespace

TEST(NormalScans, EachPointsNeighboursComeFromItsOwnScan)
{
    TempDir dir;
    const TwoScans s = makeScans(20000);
    writeScans(dir / "in.ply", s.cloud);

    NormalFileOptions options;
    options.normals.threads = 2;
    auto report = estimateNormalsForFile(dir / "in.ply", dir / "scans.ply", options);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_EQ(report->scans, 2u);
    EXPECT_EQ(report->scanColumn, "scan_id");
    EXPECT_EQ(report->tiles, 0u);
    EXPECT_EQ(report->normals.points, 40000u);
    const auto scans = normalsByPosition(dir / "scans.ply");
    EXPECT_EQ(countOff(s, scans, 5.0), 0u);

    // The same cloud estimated whole: where the sheets are a neighbourhood apart the plane is fitted across them.
    options.perScan = false;
    auto whole = estimateNormalsForFile(dir / "in.ply", dir / "whole.ply", options);
    ASSERT_TRUE(whole) << whole.error().message;
    EXPECT_EQ(whole->scans, 0u);
    EXPECT_EQ(whole->scanColumn, "");
    EXPECT_GT(countOff(s, normalsByPosition(dir / "whole.ply"), 20.0), 1000u);
}

TEST(NormalScans, TiledAgreesWithHeld)
{
    // Five scans: each is a fifth of the merged cloud's density, so its neighbourhoods reach √5 times farther
    // than the merged cloud's; the halo must hold them (no point truncated, the same normals as in one piece).
    TempDir dir;
    const TwoScans s = makeScans(6000, 1.0, "scan_id", 5);
    writeScans(dir / "in.ply", s.cloud);
    NormalFileOptions options;
    options.normals.threads = 2;
    options.temporaryDirectory = dir.path();
    auto held = estimateNormalsForFile(dir / "in.ply", dir / "held.ply", options);
    ASSERT_TRUE(held) << held.error().message;
    options.memoryBudget = 1u << 20; // a few thousand points per tile
    auto tiled = estimateNormalsForFile(dir / "in.ply", dir / "tiled.ply", options);
    ASSERT_TRUE(tiled) << tiled.error().message;
    EXPECT_GE(tiled->tiles, 8u);
    EXPECT_EQ(tiled->scans, 5u);
    EXPECT_EQ(tiled->normals.truncated, 0u);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), {}), 3) << "temporary files left behind";
    const auto a = normalsByPosition(dir / "held.ply"), b = normalsByPosition(dir / "tiled.ply");
    ASSERT_EQ(a.size(), 30000u);
    ASSERT_EQ(b.size(), 30000u);
    for (const auto& [p, n] : a) {
        const auto found = b.find(p);
        ASSERT_NE(found, b.end());
        for (int d = 0; d < 3; ++d) ASSERT_NEAR(found->second[std::size_t(d)], n[std::size_t(d)], 1e-6);
    }
    EXPECT_EQ(countOff(s, b, 5.0), 0u);
}

TEST(NormalScans, NoScansToKeepApartLeavesTheCloudWhole)
{
    TempDir dir;
    NormalFileOptions options;
    options.normals.threads = 2;
    // Reference: the two sheets estimated whole.
    const TwoScans s = makeScans(5000);
    writeScans(dir / "in.ply", s.cloud);
    options.perScan = false;
    ASSERT_TRUE(estimateNormalsForFile(dir / "in.ply", dir / "whole.ply", options));
    const auto whole = normalsByPosition(dir / "whole.ply");
    options.perScan = true;
    // Ids that are not scan ids (not integers), one scan only, and a column of another name.
    for (const auto& [idStep, column] : {std::pair{0.5, "scan_id"}, std::pair{0.0, "scan"}, std::pair{1.0, "intensity"}}) {
        const TwoScans t = makeScans(5000, idStep, column);
        writeScans(dir / "t.ply", t.cloud, column);
        auto report = estimateNormalsForFile(dir / "t.ply", dir / "t-n.ply", options);
        ASSERT_TRUE(report) << report.error().message;
        EXPECT_EQ(report->scans, 0u) << column << " " << idStep;
        EXPECT_EQ(report->scanColumn, "");
        EXPECT_EQ(normalsByPosition(dir / "t-n.ply"), whole) << column << " " << idStep;
    }
    // The column is found whatever its case and is written through.
    const TwoScans u = makeScans(5000, 1.0, "Scan_Index");
    writeScans(dir / "u.ply", u.cloud, "Scan_Index");
    auto report = estimateNormalsForFile(dir / "u.ply", dir / "u-n.ply", options);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_EQ(report->scans, 2u);
    EXPECT_EQ(report->scanColumn, "Scan_Index");
    auto reader = io::openPointReader(dir / "u-n.ply");
    ASSERT_TRUE(reader);
    EXPECT_EQ((*reader)->header().schema, (io::PointSchema{true, false, {"Scan_Index"}}));
}

TEST(NormalScans, EachScanGetsExactlyWhatItWouldAlone)
{
    // Scan ids far apart (0 and 65535), a third scan of 5 points (fewer than k), the quality written: each scan's
    // normals and surface variation are estimateNormals' on that scan alone (with the whole cloud's centroid).
    TempDir dir;
    TwoScans s = makeScans(4000, 65535.0);
    const std::array<double, 15> tiny{101, 100, 100, 101.01, 100, 100, 101, 100.01, 100, 101, 100, 100.01, 101.01, 100.01, 100};
    s.cloud.positions.insert(s.cloud.positions.end(), tiny.begin(), tiny.end());
    s.cloud.scalars[0].insert(s.cloud.scalars[0].end(), 5, 7.0);
    writeScans(dir / "in.ply", s.cloud);
    NormalFileOptions options;
    options.normals.threads = 2;
    options.writeQuality = true;
    auto report = estimateNormalsForFile(dir / "in.ply", dir / "out.ply", options);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_EQ(report->scans, 3u);
    EXPECT_EQ(report->normals.points, 8005u);
    EXPECT_EQ(report->normals.truncated, 0u);

    io::PointBatch out;
    {
        auto reader = io::openPointReader(dir / "out.ply");
        ASSERT_TRUE(reader);
        ASSERT_TRUE((*reader)->read(out, 100000));
    }
    ASSERT_EQ(out.size(), 8005u);
    ASSERT_EQ(out.positions, s.cloud.positions); // in one piece: the input order
    std::array<double, 3> centroid{};
    for (std::size_t i = 0; i < 8005; ++i)
        for (int a = 0; a < 3; ++a) centroid[std::size_t(a)] += s.cloud.positions[3 * i + a] / 8005.0;
    NormalOptions alone;
    alone.centre = centroid;
    for (const auto& [first, count] : {std::pair<std::size_t, std::size_t>{0, 4000}, {4000, 4000}, {8000, 5}}) {
        const std::span<const double> positions(&s.cloud.positions[3 * first], 3 * count);
        std::vector<float> normals(3 * count), quality(count);
        ASSERT_TRUE(estimateNormals(positions, normals, alone, nullptr, quality));
        for (std::size_t j = 0; j < count; ++j) {
            for (int a = 0; a < 3; ++a) ASSERT_EQ(out.normals[3 * (first + j) + a], normals[3 * j + a]) << first + j;
            ASSERT_EQ(out.scalars[1][first + j], double(quality[j])) << first + j;
        }
    }
}
