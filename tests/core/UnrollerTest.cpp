// unrollCloud: pixel placement, cut angle, wrapping, band, size limit, per-pixel rule, spacing,
// a generated fluted drum's grooves, cancel.
#include "stylos/core/unroll/Unroller.h"

#include "stylos/core/shading/FieldCoverage.h"

#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointReader.h"
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <memory>
#include <numbers>
#include <random>
#include <set>

using namespace stylos::core;
using namespace stylos::core::unroll;
using shading::PixelState;
using stylos::test::TempDir;

namespace {

constexpr double kPi = std::numbers::pi;

/** The cylinder of radius @p radius about +Z through the origin: e1 = X, e2 = Y. */
Surface zCylinder(double radius) { return Surface::cylinder(Axis{{0, 0, 0}, {0, 0, 1}}, radius).value(); }

/** Point at azimuth @p phi (from +X), height @p v, @p h above a Z cylinder of radius @p radius. */
Eigen::Vector3d onCylinder(double radius, double phi, double v, double h)
{
    return {(radius + h) * std::cos(phi), (radius + h) * std::sin(phi), v};
}

cloud::PointCloud cloudOf(const std::vector<Eigen::Vector3d>& points, double spacing = 0.0)
{
    cloud::PointCloud cloud;
    for (const auto& p : points) cloud.addWorld(p);
    cloud.spacing = spacing;
    cloud.source = "test.ply";
    return cloud;
}

/** A given pixel and cut, no hole filling, no coverage check: for the geometry of sparse hand-made clouds. */
UnrollOptions given(double pixel, double cut = 0.0)
{
    UnrollOptions o;
    o.pixelSize = pixel;
    o.cutAngle = cut;
    o.fillHoles = false;
    o.minCoverage = 0.0;
    return o;
}

/** A cylinder of radius @p R sampled on a jittered grid of @p d, 100 rows (seeded: always the same). */
std::vector<Eigen::Vector3d> jitteredCylinder(double R, double d, int rows = 100)
{
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> jitter(-0.25, 0.25);
    std::vector<Eigen::Vector3d> points;
    const int columns = int(2.0 * kPi * R / d);
    for (int c = 0; c < columns; ++c)
        for (int j = 0; j < rows; ++j)
            points.push_back(onCylinder(R, (c + jitter(random)) * d / R, (j + jitter(random)) * d, 0.0));
    return points;
}

Unrolled unrolled(const cloud::PointCloud& cloud, const Surface& surface, const UnrollOptions& options)
{
    auto result = unrollCloud(cloud, surface, options);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().message);
    if (!result.ok()) throw std::runtime_error("unrollCloud failed");
    return std::move(result).value();
}

/** The measured pixels of a field as (column, row) → height. */
std::map<std::pair<int, int>, float> measured(const shading::HeightField& field)
{
    std::map<std::pair<int, int>, float> pixels;
    for (int r = 0; r < field.height(); ++r)
        for (int c = 0; c < field.width(); ++c)
            if (field.stateAt(c, r) == PixelState::Measured) pixels[{c, r}] = field.heightAt(c, r);
    return pixels;
}

} // namespace

TEST(Unroller, PointsLandInKnownPixelsWithKnownHeights)
{
    // R = 0.5, s = 0.01: width ceil(π / 0.01) = 315. A point at the centre of column c has φ = (c + 0.5)·s / R.
    const double R = 0.5, s = 0.01;
    auto at = [&](int column, double v, double h) { return onCylinder(R, (column + 0.5) * s / R, v, h); };
    const auto cloud = cloudOf({at(10, 0.105, 0.001), at(20, 0.055, -0.002), at(300, 0.015, 0.0005)});
    const Unrolled u = unrolled(cloud, zCylinder(R), given(s));
    EXPECT_EQ(u.field.width(), 315);
    // v_top = s · ceil(0.105 / s) = 0.11; rows = floor((0.11 − 0.015) / s) + 1 = 10.
    EXPECT_NEAR(u.map.vTop(), 0.11, 1e-12);
    EXPECT_EQ(u.field.height(), 10);
    EXPECT_EQ(u.map.width(), 315);
    EXPECT_EQ(u.map.height(), 10);
    EXPECT_EQ(u.field.pixelSize(), s);
    const auto pixels = measured(u.field);
    ASSERT_EQ(pixels.size(), 3u);
    ASSERT_TRUE(pixels.count({10, 0}));
    ASSERT_TRUE(pixels.count({20, 5}));
    ASSERT_TRUE(pixels.count({300, 9}));
    EXPECT_NEAR(pixels.at({10, 0}), 0.001, 1e-7);
    EXPECT_NEAR(pixels.at({20, 5}), -0.002, 1e-7);
    EXPECT_NEAR(pixels.at({300, 9}), 0.0005, 1e-7);
    // The map gives back the pixel centres.
    const auto hit = u.map.pixelOf(at(20, 0.055, -0.002));
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->column, 20.5, 1e-5);
    EXPECT_NEAR(hit->row, 5.5, 1e-5);
    EXPECT_EQ(u.report.points, 3u);
    EXPECT_EQ(u.report.pointsUsed, 3u);
    EXPECT_EQ(u.report.pointsOffSurface, 0u);
    EXPECT_EQ(u.report.pointsHidden, 0u);
    EXPECT_EQ(u.report.pixelSize, s);
    EXPECT_EQ(u.report.cutAngle, 0.0);
    EXPECT_EQ(u.map.referenceDir(), Eigen::Vector3d::UnitX());
    EXPECT_GE(u.report.seconds, 0.0);
}

TEST(Unroller, GivenCutAngleShiftsTheColumnsAndWraps)
{
    const double R = 0.5, s = 0.01, cut = 1.0;
    // Just after the cut: column 0. Just before it (u = 2πR − 0.5 mm): the last, partial column 314.
    const auto cloud = cloudOf({onCylinder(R, cut + 0.0005 / R, 0.05, 0.0), onCylinder(R, cut - 0.0005 / R, 0.05, 0.001),
                                onCylinder(R, cut + kPi, 0.05, 0.002)});
    const Unrolled u = unrolled(cloud, zCylinder(R), given(s, cut));
    const auto pixels = measured(u.field);
    ASSERT_EQ(pixels.size(), 3u);
    EXPECT_TRUE(pixels.count({0, 0}));
    EXPECT_TRUE(pixels.count({314, 0}));
    EXPECT_TRUE(pixels.count({157, 0})); // half way round: u = πR = 1.5708 → column 157
    EXPECT_EQ(u.report.cutAngle, cut);
    // A cut given outside [0, 2π) is wrapped into it.
    const Unrolled w = unrolled(cloud, zCylinder(R), given(s, cut - 4.0 * kPi));
    EXPECT_NEAR(w.report.cutAngle, cut, 1e-12);
    EXPECT_EQ(measured(w.field), pixels);
}

TEST(Unroller, EveryPointLandsInThePixelThatPixelOfGives)
{
    // Half the points lie on column boundaries (u = c·s), where the fast azimuth must defer to the exact one.
    const double R = 0.5, s = 0.001, cut = 2.0;
    const UnrollMap reference(zCylinder(R), Eigen::Vector3d::UnitX(), cut, s, 3142, 200, 0.2);
    std::mt19937_64 random(17);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < 4000; ++k) {
        const double column = k % 2 ? std::floor(unit(random) * 3141.0) : unit(random) * 3141.59;
        points.push_back(reference.worldAtPixel(column, 200.0 * unit(random), 0.002 * (unit(random) - 0.5)));
    }
    points.push_back(reference.worldAtPixel(0.0, 10.0, 0.0));            // on the seam
    points.push_back(reference.worldAtPixel(3141.5926, 10.0, 0.0));      // just before it
    const auto cloud = cloudOf(points);
    const Unrolled u = unrolled(cloud, zCylinder(R), given(s, cut));
    std::set<std::pair<int, int>> expected;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const auto hit = u.map.pixelOf(cloud.world(i));
        ASSERT_TRUE(hit.has_value());
        expected.insert({std::min(int(std::floor(hit->column)), u.map.width() - 1), int(std::floor(hit->row))});
    }
    std::set<std::pair<int, int>> got;
    for (const auto& [pixel, h] : measured(u.field)) got.insert(pixel);
    EXPECT_EQ(got, expected);
    EXPECT_TRUE(got.count({0, 10}) || got.count({u.map.width() - 1, 10}));
}

TEST(Unroller, RevolutionSurfaceUsesArcLengthAlongTheMeridian)
{
    // A drum side (r = 0.3 from t = 0 to 0.2) turning into its top face (t = 0.2, r from 0.3 to 0.1).
    auto meridian = Meridian::create({{0.0, 0.3}, {0.2, 0.3}, {0.2, 0.1}}, 0.05);
    ASSERT_TRUE(meridian.ok()) << meridian.error().message;
    const Surface surface = Surface::revolution(Axis{{0, 0, 0}, {0, 0, 1}}, std::move(meridian).value(), 0.3).value();
    const double phi = 1.05; // u = 0.315: column 31
    const auto side = Eigen::Vector3d(0.302 * std::cos(phi), 0.302 * std::sin(phi), 0.055);  // v 0.055, h 0.002
    const auto top = Eigen::Vector3d(0.145 * std::cos(phi), 0.145 * std::sin(phi), 0.201);   // v 0.355, h 0.001
    const auto cloud = cloudOf({side, top, Eigen::Vector3d(0.3, 0.0, 0.5), Eigen::Vector3d(0.0, 0.0, 0.1)});
    const Unrolled u = unrolled(cloud, surface, given(0.01));
    EXPECT_EQ(u.report.pointsUsed, 2u);
    EXPECT_EQ(u.report.pointsOffSurface, 2u); // beyond the meridian's reach
    // (v, h) as the meridian gives them (its normal field turns toward the corner, so h is not quite
    // the radial height): about (0.055, 0.002) and (0.355, 0.001).
    const auto sideVh = surface.meridianCoords(0.055, 0.302), topVh = surface.meridianCoords(0.201, 0.145);
    ASSERT_TRUE(sideVh && topVh);
    EXPECT_NEAR(sideVh->v, 0.055, 0.001);
    EXPECT_NEAR(topVh->v, 0.355, 0.001);
    // v_top = s · ceil(0.355 / s) = 0.36: the top point in row 0, the side point in row 30.
    EXPECT_NEAR(u.map.vTop(), 0.36, 1e-12);
    const auto pixels = measured(u.field);
    ASSERT_EQ(pixels.size(), 2u);
    ASSERT_TRUE(pixels.count({31, 30}));
    ASSERT_TRUE(pixels.count({31, 0}));
    EXPECT_NEAR(pixels.at({31, 30}), sideVh->h, 1e-6);
    EXPECT_NEAR(pixels.at({31, 0}), topVh->h, 1e-6);
    EXPECT_NEAR(sideVh->h, 0.002, 1e-4);
    EXPECT_NEAR(topVh->h, 0.001, 1e-4);
}

TEST(Unroller, DefaultCutIsInTheMiddleOfTheGap)
{
    const double R = 0.5;
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < 1440; ++k) { // every 0.25°, none in [100°, 140°)
        const double degrees = k * 0.25;
        if (degrees >= 100.0 && degrees < 140.0) continue;
        for (int j = 0; j <= 20; ++j) points.push_back(onCylinder(R, degrees * kPi / 180.0, 0.01 * j, 0.0));
    }
    UnrollOptions options = given(0.005);
    options.cutAngle.reset();
    const Unrolled u = unrolled(cloudOf(points), zCylinder(R), options);
    EXPECT_NEAR(u.report.cutAngle * 180.0 / kPi, 120.0, 0.5);
    // The seam is in the gap: the first and last columns are empty, the columns either side of the gap full.
    const int last = u.field.width() - 1;
    for (int r = 0; r < u.field.height(); ++r) {
        EXPECT_FALSE(u.field.hasHeight(0, r));
        EXPECT_FALSE(u.field.hasHeight(last, r));
    }
    // The same cloud turned by 90°: the cut turns with it.
    std::vector<Eigen::Vector3d> turned;
    for (const auto& p : points) turned.emplace_back(-p.y(), p.x(), p.z());
    const Unrolled t = unrolled(cloudOf(turned), zCylinder(R), options);
    EXPECT_NEAR(t.report.cutAngle * 180.0 / kPi, 210.0, 0.5);
}

TEST(Unroller, AFragmentsImageIsItsArcWithADegreeEachSide)
{
    // Points on [300°, 360°) ∪ [0°, 40°): a 100° fragment across the reference direction. With the default cut
    // the image spans the arc from 300° − 1° over 102°, its left edge the cut, every point inside it.
    const double R = 0.5, pixel = 0.005;
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < 400; ++k) { // every 0.25°
        const double degrees = 300.0 + k * 0.25;
        for (int j = 0; j <= 20; ++j) points.push_back(onCylinder(R, degrees * kPi / 180.0, 0.01 * j, 0.0));
    }
    UnrollOptions options = given(pixel);
    options.cutAngle.reset();
    const Unrolled u = unrolled(cloudOf(points), zCylinder(R), options);
    EXPECT_NEAR(u.report.cutAngle * 180.0 / kPi, 299.0, 1e-9);
    EXPECT_NEAR(u.report.arc * 180.0 / kPi, 102.0, 1e-9);
    EXPECT_EQ(u.field.width(), int(std::ceil(R * u.report.arc / pixel))); // 179, not the turn's 629
    EXPECT_EQ(u.map.width(), u.field.width());
    // 1° (1.75 pixels) empty each side, then the points: the first and last point columns as pixelOf() gives.
    const auto first = u.map.pixelOf(onCylinder(R, 300.0 * kPi / 180.0, 0.1, 0.0));
    const auto last = u.map.pixelOf(onCylinder(R, (300.0 + 399 * 0.25) * kPi / 180.0, 0.1, 0.0));
    ASSERT_TRUE(first && last);
    EXPECT_NEAR(first->column, R * kPi / 180.0 / pixel, 1e-6);
    EXPECT_LT(last->column, double(u.field.width()));
    for (int r = 0; r < u.field.height(); ++r) EXPECT_FALSE(u.field.hasHeight(0, r)) << r;
    const auto columnHasHeights = [&](int c) {
        int n = 0;
        for (int r = 0; r < u.field.height(); ++r) n += u.field.hasHeight(c, r);
        return n;
    };
    EXPECT_GT(columnHasHeights(int(first->column)), 15);
    EXPECT_GT(columnHasHeights(int(last->column)), 15);
    EXPECT_EQ(columnHasHeights(u.field.width() - 1), 0);
    EXPECT_EQ(u.report.pointsHidden, 0u); // every point landed
    EXPECT_EQ(u.report.pointsUsed, points.size());
    EXPECT_EQ(u.report.pointsOffSurface, 0u);
    // Asked not to crop, or given a cut: the whole turn.
    options.cropToPoints = false;
    EXPECT_EQ(unrolled(cloudOf(points), zCylinder(R), options).field.width(), int(std::ceil(2 * kPi * R / pixel)));
    UnrollOptions cut = given(pixel, 299.0 * kPi / 180.0);
    const Unrolled c = unrolled(cloudOf(points), zCylinder(R), cut);
    EXPECT_EQ(c.field.width(), int(std::ceil(2 * kPi * R / pixel)));
    EXPECT_DOUBLE_EQ(c.report.arc, 2 * kPi);
}

TEST(Unroller, ADrumWithAGapUnderHalfTheTurnKeepsTheWholeTurn)
{
    // 170° empty (under half the turn): a broken drum, unrolled whole with the seam in its gap.
    const double R = 0.5, pixel = 0.005;
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < 760; ++k) // 0° … 190°
        for (int j = 0; j <= 20; ++j) points.push_back(onCylinder(R, k * 0.25 * kPi / 180.0, 0.01 * j, 0.0));
    UnrollOptions options = given(pixel);
    options.cutAngle.reset();
    const Unrolled u = unrolled(cloudOf(points), zCylinder(R), options);
    EXPECT_DOUBLE_EQ(u.report.arc, 2 * kPi);
    EXPECT_EQ(u.field.width(), int(std::ceil(2 * kPi * R / pixel)));
}

TEST(Unroller, PointsOutsideTheBandAreDroppedAndCounted)
{
    const double R = 0.5; // default band 0.15 × 0.5 = 75 mm
    const auto cloud = cloudOf({onCylinder(R, 1.0, 0.1, 0.07), onCylinder(R, 1.1, 0.1, -0.074),
                                onCylinder(R, 1.2, 0.1, 0.08), onCylinder(R, 1.3, 0.1, -0.2), Eigen::Vector3d(0, 0, 0.1)});
    const Unrolled u = unrolled(cloud, zCylinder(R), given(0.01));
    EXPECT_EQ(u.report.band, 0.075);
    EXPECT_EQ(u.report.pointsUsed, 2u);
    EXPECT_EQ(u.report.pointsOffSurface, 3u);
    EXPECT_EQ(measured(u.field).size(), 2u);

    UnrollOptions narrow = given(0.01);
    narrow.band = 0.0705;
    const Unrolled n = unrolled(cloud, zCylinder(R), narrow);
    EXPECT_EQ(n.report.pointsUsed, 1u);
    EXPECT_EQ(n.report.pointsOffSurface, 4u);

    narrow.band = 0.01;
    auto none = unrollCloud(cloud, zCylinder(R), narrow);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(none.error().message.find("test.ply: none of the 5 points lies within 10 mm"), std::string::npos)
        << none.error().message;
}

TEST(Unroller, AnImageTooLargeIsRefusedWithTheSizeItWouldHave)
{
    const auto cloud = cloudOf({onCylinder(0.5, 0.0, 0.0, 0.0), onCylinder(0.5, 1.0, 0.002, 0.0)});
    auto wide = unrollCloud(cloud, zCylinder(0.5), given(0.00005));
    ASSERT_FALSE(wide.ok());
    EXPECT_EQ(wide.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(wide.error().message.find("test.ply: the développée would be 62832 × "), std::string::npos)
        << wide.error().message;
    EXPECT_NE(wide.error().message.find(" pixels (pixel size 0.05 mm); the limit is 32768 a side: give a larger "
                                        "--pixel-size"), std::string::npos) << wide.error().message;
    const auto tall = cloudOf({onCylinder(0.01, 0.0, 0.0, 0.0), onCylinder(0.01, 1.0, 40.0, 0.0)});
    auto high = unrollCloud(tall, zCylinder(0.01), given(0.001));
    ASSERT_FALSE(high.ok());
    EXPECT_NE(high.error().message.find("would be 63 × 4000"), std::string::npos)
        << high.error().message;
    // Just under the limit in width passes.
    EXPECT_TRUE(unrollCloud(cloud, zCylinder(0.5), given(2.0 * kPi * 0.5 / 32767.5)).ok());
}

TEST(Unroller, PointsBehindTheOutermostOneInAPixelChangeNothing)
{
    const double R = 0.5, s = 0.01; // tolerance 2 s = 20 mm
    const double phi = 10.5 * s / R;
    const auto front = onCylinder(R, phi, 0.055, 0.001);
    const auto alone = unrolled(cloudOf({front, onCylinder(R, 0.5, 0.005, 0.0)}), zCylinder(R), given(s));
    // A bed-face point 30 mm behind the rim in the same pixel, before and after the front point.
    const auto behind = onCylinder(R, phi + 0.002 / R, 0.053, -0.029);
    const auto both = unrolled(cloudOf({behind, front, onCylinder(R, 0.5, 0.005, 0.0), behind}), zCylinder(R), given(s));
    EXPECT_EQ(measured(both.field), measured(alone.field));
    EXPECT_EQ(both.report.pointsHidden, 2u);
    EXPECT_EQ(both.report.pointsUsed, 4u);
    // Points within the tolerance of the outermost one are averaged.
    const auto close = unrolled(cloudOf({front, onCylinder(R, phi, 0.056, 0.003), onCylinder(R, 0.5, 0.005, 0.0)}),
                                zCylinder(R), given(s));
    const auto pixels = measured(close.field);
    ASSERT_EQ(pixels.size(), 2u);
    EXPECT_NEAR(pixels.begin()->second, 0.002, 1e-7);
    // A tolerance of 0 keeps only the outermost one.
    UnrollOptions strict = given(s);
    strict.depthTolerance = 0.0;
    const auto sharp = unrolled(cloudOf({front, onCylinder(R, phi, 0.056, 0.003), onCylinder(R, 0.5, 0.005, 0.0)}),
                                zCylinder(R), strict);
    EXPECT_NEAR(measured(sharp.field).begin()->second, 0.003, 1e-7);
}

TEST(Unroller, PixelSizeDefaultsToTheCloudSpacingOrItsEstimate)
{
    // A cylinder sampled on a jittered grid of 3 mm, with a second "scan" over a third of it.
    const double R = 0.3, d = 0.003;
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> jitter(-0.25, 0.25);
    std::vector<Eigen::Vector3d> points;
    const int columns = int(2.0 * kPi * R / d);
    for (int pass = 0; pass < 2; ++pass)
        for (int c = 0; c < (pass == 0 ? columns : columns / 3); ++c)
            for (int j = 0; j < 100; ++j)
                points.push_back(onCylinder(R, (c + 0.37 * pass + jitter(random)) * d / R, (j + jitter(random)) * d, 0.0));
    UnrollOptions options;
    options.fillHoles = false;
    const Unrolled estimated = unrolled(cloudOf(points), zCylinder(R), options);
    EXPECT_NEAR(estimated.report.pixelSize, d, 0.05 * d);
    EXPECT_EQ(estimated.report.samplingSpacing, estimated.report.pixelSize);
    // A stated leaf edge (a .poct): never less than three edges, else the density's spacing.
    const Unrolled coarse = unrolled(cloudOf(points, 0.0025), zCylinder(R), options);
    EXPECT_EQ(coarse.report.pixelSize, 3.0 * 0.0025);
    EXPECT_EQ(coarse.field.pixelSize(), 3.0 * 0.0025);
    const Unrolled fine = unrolled(cloudOf(points, 0.0005), zCylinder(R), options);
    EXPECT_EQ(fine.report.pixelSize, estimated.report.pixelSize);

    auto few = unrollCloud(cloudOf({onCylinder(R, 0.0, 0.0, 0.0), onCylinder(R, 1.0, 0.1, 0.0)}), zCylinder(R), options);
    ASSERT_FALSE(few.ok());
    EXPECT_NE(few.error().message.find("test.ply: cannot estimate the sampling spacing from 2 points"), std::string::npos)
        << few.error().message;
}

TEST(Unroller, BadArgumentsAreRefused)
{
    const auto cloud = cloudOf({onCylinder(0.5, 0.0, 0.0, 0.0)});
    auto expectInvalid = [&](const cloud::PointCloud& c, const UnrollOptions& o, const std::string& part) {
        auto r = unrollCloud(c, zCylinder(0.5), o);
        ASSERT_FALSE(r.ok()) << part;
        EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument);
        EXPECT_NE(r.error().message.find(part), std::string::npos) << r.error().message;
    };
    expectInvalid(cloudOf({}), given(0.01), "test.ply: the cloud has no points");
    expectInvalid(cloud, given(0.0), "pixel size");
    expectInvalid(cloud, given(std::nan("")), "pixel size");
    expectInvalid(cloud, given(0.01, INFINITY), "cut angle");
    UnrollOptions o = given(0.01);
    o.band = -1.0;
    expectInvalid(cloud, o, "band");
    o = given(0.01);
    o.depthTolerance = -0.001;
    expectInvalid(cloud, o, "depth tolerance");
    o = given(0.01);
    o.fillHoles = true;
    o.holes.maxArea = 0;
    expectInvalid(cloud, o, "hole filling");
}

TEST(Unroller, ResultDoesNotDependOnTheThreadCount)
{
    std::mt19937_64 random(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < 300000; ++k)
        points.push_back(onCylinder(0.4, 2.0 * kPi * unit(random), 0.3 * unit(random), 0.004 * (unit(random) - 0.5)));
    const auto cloud = cloudOf(points);
    UnrollOptions one = given(0.003);
    one.fillHoles = true;
    one.threads = 1;
    UnrollOptions three = one;
    three.threads = 3;
    const Unrolled a = unrolled(cloud, zCylinder(0.4), one);
    const Unrolled b = unrolled(cloud, zCylinder(0.4), three);
    ASSERT_EQ(a.field.pixelCount(), b.field.pixelCount());
    EXPECT_TRUE(std::equal(a.field.heights().begin(), a.field.heights().end(), b.field.heights().begin()));
    EXPECT_TRUE(std::equal(a.field.states().begin(), a.field.states().end(), b.field.states().begin()));
    EXPECT_GT(a.report.filledFraction, 0.0);
    EXPECT_LT(a.report.filledFraction, 0.5);
    EXPECT_EQ(a.report.filledFraction, b.report.filledFraction);
    EXPECT_EQ(a.report.pointsHidden, b.report.pointsHidden);
}

TEST(Unroller, CancelStopsWithCancelled)
{
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < 200000; ++k) points.push_back(onCylinder(0.4, k * 1e-4, 0.3 * (k % 97) / 97.0, 0.0));
    const auto cloud = cloudOf(points);
    SilentProgress before;
    before.cancel();
    auto r = unrollCloud(cloud, zCylinder(0.4), given(0.002), &before);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::Cancelled);

    // Cancelled from the first progress report on, whichever stage it comes from.
    class CancelAt final : public ProgressSink {
    public:
        explicit CancelAt(double at) : m_at(at) {}
        void update(double f) override { if (f >= m_at) m_cancel = true; }
        bool isCancelRequested() const override { return m_cancel; }
    private:
        double m_at;
        std::atomic<bool> m_cancel{false};
    };
    for (double at : {0.0, 0.5, 0.95}) {
        CancelAt sink(at);
        UnrollOptions o = given(0.002);
        o.fillHoles = true;
        auto c = unrollCloud(cloud, zCylinder(0.4), o, &sink);
        ASSERT_FALSE(c.ok()) << at;
        EXPECT_EQ(c.error().code, ErrorCode::Cancelled) << at;
    }
    SilentProgress done;
    ASSERT_TRUE(unrollCloud(cloud, zCylinder(0.4), given(0.002), &done).ok());
    EXPECT_EQ(done.last(), 1.0);
}

// A generated fluted drum (48 grooves, random pose, noise, broken region, bed faces), unrolled about a
// cylinder on its true axis with its true radius: the mean profile of h across u, taken on rows above
// the broken region and below the claw band, has exactly 48 minima, 2πR/48 apart.
TEST(Unroller, GeneratedDrumShowsItsGroovesAtTheRightSpacing)
{
    TempDir dir;
    const auto options = stylos::test::coarse(0.004, 21);
    const auto report = stylos::test::generate(synth::SyntheticKind::Drum, options, dir / "drum.ply");
    std::ifstream truthFile(report.truthPath);
    const nlohmann::json truth = nlohmann::json::parse(truthFile);
    Axis axis;
    for (int i = 0; i < 3; ++i) {
        axis.point[i] = truth["axis"]["point"][i].get<double>();
        axis.direction[i] = truth["axis"]["direction"][i].get<double>();
    }
    axis.direction.normalize();
    const double radius = truth["radius"].get<double>();
    const int grooves = truth["grooves"]["count"].get<int>();
    ASSERT_EQ(grooves, 48);

    auto reader = io::openPointReader(dir / "drum.ply");
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    auto batch = stylos::test::readAllPoints(**reader, 65536);
    ASSERT_TRUE(batch.ok()) << batch.error().message;
    cloud::PointCloud cloud;
    cloud.origin = axis.point;
    cloud.source = "drum.ply";
    for (std::size_t i = 0; i < batch->size(); ++i)
        cloud.addWorld({batch->positions[3 * i], batch->positions[3 * i + 1], batch->positions[3 * i + 2]});

    const Unrolled u = unrolled(cloud, Surface::cylinder(axis, radius).value(), UnrollOptions{});
    EXPECT_NEAR(u.report.pixelSize, options.spacing, 0.15 * options.spacing); // estimated
    EXPECT_GT(u.report.pointsOffSurface, 0u); // the centres of the bed faces
    EXPECT_LT(u.report.filledFraction, 0.5);
    const double s = u.map.pixelSize();

    // Mean h per column over the rows with v in [0.30, 0.40] m (the broken region ends at 0.28 m).
    std::vector<double> profile(std::size_t(u.field.width()), 0.0);
    for (int c = 0; c < u.field.width(); ++c) {
        int n = 0;
        for (int r = 0; r < u.field.height(); ++r) {
            const double v = u.map.vTop() - (r + 0.5) * s;
            if (v < 0.30 || v > 0.40 || !u.field.hasHeight(c, r)) continue;
            profile[std::size_t(c)] += u.field.heightAt(c, r);
            ++n;
        }
        ASSERT_GT(n, 0) << "column " << c << " has no data";
        profile[std::size_t(c)] /= n;
    }
    // Grooves: runs (circular) of columns below half the groove depth, each centred on a minimum.
    const double depth = truth["grooves"]["depth"].get<double>();
    const std::size_t w = profile.size();
    std::size_t start = 0;
    while (profile[start] < -0.5 * depth) ++start; // begin on a fillet
    std::vector<double> minima;                     // run centres, columns, unwrapped
    std::size_t first = 0;
    bool inside = false;
    for (std::size_t k = 1; k <= w; ++k) {
        const bool below = profile[(start + k) % w] < -0.5 * depth;
        if (below && !inside) first = start + k;
        if (!below && inside) minima.push_back(0.5 * double(first + start + k - 1));
        inside = below;
    }
    EXPECT_EQ(minima.size(), std::size_t(grooves));
    const double pitch = 2.0 * kPi * radius / grooves / s; // columns
    for (std::size_t k = 1; k < minima.size(); ++k)
        EXPECT_NEAR(minima[k] - minima[k - 1], pitch, 2.0) << "between grooves " << k - 1 << " and " << k;
    for (double m : minima) EXPECT_NEAR(profile[std::size_t(std::lround(m)) % w], -depth, 0.25 * depth) << m;
}

TEST(Unroller, TheDefaultPixelCoversTheSurface)
{
    const auto points = jitteredCylinder(0.3, 0.003);
    const Unrolled made = unrolled(cloudOf(points), zCylinder(0.3), UnrollOptions{});
    EXPECT_NEAR(made.report.samplingSpacing, 0.003, 0.05 * 0.003);
    EXPECT_GE(made.report.coverage, 0.9);
    EXPECT_LE(made.report.coverage, 1.0);
}

TEST(Unroller, APixelNearTheSpacingLeavesNoGapInsideTheSurface)
{
    // Pixels a little under the spacing leave one-pixel gaps between the samples, joined into networks larger than
    // the holes filled (256 pixels) and reaching the border: they read as cracks on the développée (the tour's 4 mm
    // fragment at 3.53 mm pixels). Every empty pixel within the footprint is filled now, the edge's included.
    const auto points = jitteredCylinder(0.3, 0.003);
    UnrollOptions options;
    options.pixelSize = 0.0026;
    const Unrolled made = unrolled(cloudOf(points), zCylinder(0.3), options);
    const auto footprint = shading::footprintMask(made.field, 1);
    std::size_t inside = 0, empty = 0;
    for (std::size_t i = 0; i < footprint.size(); ++i) {
        inside += footprint[i];
        empty += footprint[i] && made.field.states()[i] == shading::PixelState::Empty ? 1 : 0;
    }
    EXPECT_GT(inside, 0.9 * double(made.field.pixelCount()));
    EXPECT_EQ(empty, 0u);
    EXPECT_GT(made.report.filledFraction, 0.1); // there were gaps to fill
}

TEST(Unroller, APixelFarBelowTheSpacingIsRefusedBeforeRasterising)
{
    // 0.3 mm pixels on points 3 mm apart: 0.01 points a pixel, refused at once (no 5.9 M-pixel raster).
    UnrollOptions o;
    o.pixelSize = 0.0003;
    auto r = unrollCloud(cloudOf(jitteredCylinder(0.3, 0.003)), zCylinder(0.3), o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument);
    const std::string& m = r.error().message;
    EXPECT_NE(m.find("test.ply: a pixel of 0.3 mm would leave the développée mostly empty (about 1.0 % of its pixels"),
              std::string::npos) << m;
    EXPECT_NE(m.find(": give a pixel size of at least 2.993 mm (the sampling spacing)"), std::string::npos) << m;
}

TEST(Unroller, APixelThatCoversLittleOfTheSurfaceIsRefusedWithItsCoverage)
{
    // 1.2 mm pixels on points 3 mm apart: 0.16 points a pixel passes the prediction, but the empty pixels
    // join up to the border and cannot be filled: the raster covers a fraction of the footprint.
    UnrollOptions o;
    o.pixelSize = 0.0012;
    auto r = unrollCloud(cloudOf(jitteredCylinder(0.3, 0.003)), zCylinder(0.3), o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument);
    const std::string& m = r.error().message;
    EXPECT_NE(m.find("test.ply: a pixel of 1.2 mm covers only "), std::string::npos) << m;
    EXPECT_NE(m.find("covers only 16.0 % of the surface: give a pixel size of at least 2.993 mm"), std::string::npos) << m;
    // Asked not to check, the same pixel gives that image.
    o.minCoverage = 0.0;
    auto unchecked = unrollCloud(cloudOf(jitteredCylinder(0.3, 0.003)), zCylinder(0.3), o);
    ASSERT_TRUE(unchecked.ok());
    EXPECT_LT(unchecked->report.coverage, 0.5);
    EXPECT_GT(unchecked->report.coverage, 0.0);
}
