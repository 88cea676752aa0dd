// UnrollMap: the map between a développée and 3D, both ways, and its JSON sidecar.
#include "stylos/core/unroll/UnrollMap.h"

#include "TestSupport.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <random>

using namespace stylos::core;
using namespace stylos::core::unroll;
using stylos::test::TempDir;

namespace {

constexpr double kPi = std::numbers::pi;

Axis tiltedAxis()
{
    return Axis{{1.5, -2.0, 0.75}, Eigen::Vector3d(0.3, -0.2, 1.0).normalized()};
}

/** An ovoid meridian (the omphalos' kind of profile) from the bottom (t = 0) to the top, outer side left. */
Meridian ovoid()
{
    std::vector<Eigen::Vector2d> vertices;
    for (int k = 0; k <= 40; ++k) {
        const double a = -0.45 * kPi + 0.9 * kPi * k / 40.0; // latitude, −81° .. 81°
        vertices.emplace_back(0.3 + 0.35 * std::sin(a), 0.28 * std::cos(a));
    }
    auto m = Meridian::create(std::move(vertices), 0.04);
    EXPECT_TRUE(m.ok()) << (m.ok() ? "" : m.error().message);
    return std::move(m).value();
}

/** A map whose rows cover v ∈ [vTop − 0.6 m, vTop]. */
UnrollMap mapOn(const Surface& surface, double cut = 1.0, double pixel = 0.001, double vTop = 0.55)
{
    const int width = int(std::ceil(2.0 * kPi * surface.referenceRadius() / pixel));
    const int height = int(0.6 / pixel);
    return UnrollMap(surface, defaultReferenceDir(surface.axis().direction), cut, pixel, width, height, vTop);
}

/** A world point at azimuth @p phi (from e1), axial @p t and distance @p r from the axis, built by hand. */
Eigen::Vector3d worldPoint(const UnrollMap& map, double phi, double t, double r)
{
    const Axis& axis = map.surface().axis();
    const Eigen::Vector3d e1 = map.referenceDir();
    const Eigen::Vector3d e2 = axis.direction.cross(e1);
    return axis.point + t * axis.direction + r * (std::cos(phi) * e1 + std::sin(phi) * e2);
}

/** World → pixel → world (same h) and pixel centre → world → pixel, on random points near the surface. */
void checkRoundTrips(const UnrollMap& map, double vMin, double vMax)
{
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Surface& surface = map.surface();
    for (int k = 0; k < 2000; ++k) {
        const double v = vMin + (vMax - vMin) * unit(random);
        const double phi = 2.0 * kPi * unit(random);
        const double h = -0.02 + 0.04 * unit(random);
        // (t, r) from the surface's own meridian map, the point placed by hand about the axis.
        const Eigen::Vector2d tr = surface.meridianPoint(v, h);
        const Eigen::Vector3d world = worldPoint(map, phi, tr.x(), tr.y());
        const auto hit = map.pixelOf(world);
        ASSERT_TRUE(hit.has_value()) << "point " << k;
        EXPECT_GE(hit->column, 0.0);
        EXPECT_LT(hit->column, map.circumference() / map.pixelSize());
        const Eigen::Vector3d back = map.worldAtPixel(hit->column, hit->row, hit->h);
        ASSERT_LT((back - world).norm(), 1e-9) << "point " << k << " at azimuth " << phi;
        ASSERT_NEAR(hit->h, h, 1e-9);
        const double period = map.circumference() / map.pixelSize();
        const double expected = std::fmod(phi - map.cutAngle() + 4.0 * kPi, 2.0 * kPi) / (2.0 * kPi) * period;
        if (expected > 1e-6 && expected < period - 1e-6) {
            ASSERT_NEAR(hit->column, expected, 1e-6);
        }
        ASSERT_NEAR(hit->row, (map.vTop() - v) / map.pixelSize(), 1e-6);

        const int column = int(unit(random) * (map.width() - 1)); // full columns only
        const int row = int(unit(random) * map.height());
        const Eigen::Vector3d centre = map.worldAtPixel(column + 0.5, row + 0.5, h);
        const auto again = map.pixelOf(centre);
        ASSERT_TRUE(again.has_value());
        ASSERT_NEAR(again->column, column + 0.5, 1e-6) << "pixel " << column << ", " << row;
        ASSERT_NEAR(again->row, row + 0.5, 1e-6) << "pixel " << column << ", " << row;
        ASSERT_NEAR(again->h, h, 1e-9);
    }
}

/** Same map: every number exact, but the axis (Surface::fromJson normalises its direction again). */
void expectSameMap(const UnrollMap& back, const UnrollMap& map)
{
    EXPECT_EQ(back.surface().kind(), map.surface().kind());
    EXPECT_EQ(back.surface().axis().point, map.surface().axis().point);
    EXPECT_LT((back.surface().axis().direction - map.surface().axis().direction).norm(), 1e-15);
    EXPECT_EQ(back.surface().radius(), map.surface().radius());
    EXPECT_EQ(back.surface().slope(), map.surface().slope());
    EXPECT_EQ(back.surface().referenceRadius(), map.surface().referenceRadius());
    EXPECT_EQ(back.referenceDir(), map.referenceDir());
    EXPECT_EQ(back.cutAngle(), map.cutAngle());
    EXPECT_EQ(back.pixelSize(), map.pixelSize());
    EXPECT_EQ(back.width(), map.width());
    EXPECT_EQ(back.height(), map.height());
    EXPECT_EQ(back.vTop(), map.vTop());
}

} // namespace

TEST(UnrollMap, ReferenceDirectionIsWorldXMadePerpendicularOrYNearTheXAxis)
{
    EXPECT_EQ(defaultReferenceDir(Eigen::Vector3d::UnitZ()), Eigen::Vector3d::UnitX());
    EXPECT_EQ(defaultReferenceDir(Eigen::Vector3d::UnitX()), Eigen::Vector3d::UnitY());
    EXPECT_EQ(defaultReferenceDir(-Eigen::Vector3d::UnitX()), Eigen::Vector3d::UnitY());
    const Eigen::Vector3d a = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
    EXPECT_LT((defaultReferenceDir(a) - Eigen::Vector3d(1.0, -1.0, 0.0).normalized()).norm(), 1e-15);
    const Eigen::Vector3d tilted = tiltedAxis().direction;
    const Eigen::Vector3d e1 = defaultReferenceDir(tilted);
    EXPECT_NEAR(e1.norm(), 1.0, 1e-15);
    EXPECT_NEAR(e1.dot(tilted), 0.0, 1e-15);
}

TEST(UnrollMap, KnownPointsHaveKnownSurfaceCoordinatesAndPixels)
{
    const Surface cylinder = Surface::cylinder(Axis{{0, 0, 0}, {0, 0, 1}}, 0.5).value();
    const UnrollMap map(cylinder, Eigen::Vector3d::UnitX(), kPi / 2, 0.01, 315, 60, 0.6);
    EXPECT_EQ(map.secondDir(), Eigen::Vector3d::UnitY());
    // On +Y (azimuth π/2 = the cut): u = 0. Counter-clockwise about +Z from there, u grows.
    auto at = [&](double x, double y, double z) { return *map.surfaceCoords({x, y, z}); };
    EXPECT_LT((at(0.0, 0.52, 0.3) - Eigen::Vector3d(0.0, 0.3, 0.02)).norm(), 1e-15);
    EXPECT_LT((at(-0.5, 0.0, 0.1) - Eigen::Vector3d(0.25 * kPi, 0.1, 0.0)).norm(), 1e-15);
    EXPECT_LT((at(0.5, 0.0, 0.1) - Eigen::Vector3d(0.75 * kPi, 0.1, 0.0)).norm(), 1e-15);
    EXPECT_LT((at(0.0, -0.49, 0.0) - Eigen::Vector3d(0.5 * kPi, 0.0, -0.01)).norm(), 1e-15);
    // Just before the cut: u just below 2πR (never 2πR).
    const Eigen::Vector3d late = at(std::sin(1e-6) * 0.5, std::cos(1e-6) * 0.5, 0.0);
    EXPECT_NEAR(late.x(), kPi - 0.5e-6, 1e-12);
    // Pixels: column = u / s, row = (v_top − v) / s.
    const auto hit = map.pixelOf({-0.5, 0.0, 0.1});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->column, 25.0 * kPi, 1e-12);
    EXPECT_NEAR(hit->row, 50.0, 1e-12);
    EXPECT_NEAR(hit->h, 0.0, 1e-15);
    EXPECT_LT((map.worldAtPixel(25.0 * kPi, 50.0, 0.0) - Eigen::Vector3d(-0.5, 0.0, 0.1)).norm(), 1e-15);
    EXPECT_FALSE(map.pixelOf({std::nan(""), 0.0, 0.0}).has_value());
}

TEST(UnrollMap, CylinderRoundTripsAreExact)
{
    const Surface cylinder = Surface::cylinder(tiltedAxis(), 0.55).value();
    checkRoundTrips(mapOn(cylinder), -0.1, 0.6);
}

TEST(UnrollMap, ConeRoundTripsAreExact)
{
    const Surface cone = Surface::cone(tiltedAxis(), 0.5, -0.08, 0.48).value();
    checkRoundTrips(mapOn(cone, 4.0), -0.1, 0.6);
}

TEST(UnrollMap, RevolutionRoundTripsAreExact)
{
    const Surface omphalos = Surface::revolution(tiltedAxis(), ovoid(), 0.22).value();
    // v along the meridian, a little away from its ends: the image rows cover [L − 0.65, L − 0.05].
    const double length = omphalos.meridian()->length();
    ASSERT_GT(length, 0.75);
    const UnrollMap map = mapOn(omphalos, 0.3, 0.001, length - 0.05);
    checkRoundTrips(map, 0.05, length - 0.05);
    // Beyond the meridian's reach there are no coordinates.
    EXPECT_FALSE(map.surfaceCoords(worldPoint(map, 0.3, 0.3, 0.45)).has_value());
}

TEST(UnrollMap, JsonRoundTripGivesTheSameMap)
{
    const Surface omphalos = Surface::revolution(tiltedAxis(), ovoid(), 0.22).value();
    for (const Surface& surface : {Surface::cylinder(tiltedAxis(), 0.55).value(), Surface::cone(tiltedAxis(), 0.5, -0.08, 0.48).value(), omphalos}) {
        const UnrollMap map = mapOn(surface, 2.25, 0.0007);
        const nlohmann::json json = map.toJson();
        EXPECT_EQ(json["format"], "stylos-unroll");
        EXPECT_EQ(json["version"], 1);
        // Through text, as on disk.
        auto back = UnrollMap::fromJson(nlohmann::json::parse(json.dump(2)), "map.json");
        ASSERT_TRUE(back.ok()) << back.error().message;
        expectSameMap(*back, map);
        const Eigen::Vector3d p = map.worldAtPixel(123.5, 45.5, 0.001);
        const auto hit = back->pixelOf(p);
        ASSERT_TRUE(hit.has_value());
        EXPECT_NEAR(hit->column, 123.5, 1e-6);
        EXPECT_NEAR(hit->row, 45.5, 1e-6);
    }
}

TEST(UnrollMap, SidecarIsWrittenAtomicallyAndReadBack)
{
    TempDir dir;
    const UnrollMap map = mapOn(Surface::cylinder(tiltedAxis(), 0.55).value());
    ASSERT_TRUE(map.writeSidecar(dir / "drum.png.json").ok());
    EXPECT_FALSE(std::filesystem::exists(dir / "drum.png.json.part"));
    auto back = UnrollMap::readSidecar(dir / "drum.png.json");
    ASSERT_TRUE(back.ok()) << back.error().message;
    expectSameMap(*back, map);

    // Into a folder that does not exist: WriteFailed naming the path, nothing left behind.
    const auto missing = dir / "no" / "such" / "x.json";
    const Status failed = map.writeSidecar(missing);
    ASSERT_FALSE(failed.ok());
    EXPECT_EQ(failed.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(failed.error().message.find(missing.string()), std::string::npos) << failed.error().message;
}

TEST(UnrollMap, ReadingABadSidecarNamesTheFileAndTheKey)
{
    TempDir dir;
    const auto path = dir / "map.json";
    auto missing = UnrollMap::readSidecar(path);
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
    EXPECT_NE(missing.error().message.find(path.string()), std::string::npos);

    auto directory = UnrollMap::readSidecar(dir.path());
    ASSERT_FALSE(directory.ok());
    EXPECT_EQ(directory.error().code, ErrorCode::Unreadable);

    stylos::test::writeText(path, "{\"format\": \"stylos-unroll\", ");
    auto truncated = UnrollMap::readSidecar(path);
    ASSERT_FALSE(truncated.ok());
    EXPECT_EQ(truncated.error().code, ErrorCode::Malformed);
    EXPECT_NE(truncated.error().message.find(path.string() + ": line 1, column "), std::string::npos) << truncated.error().message;

    const nlohmann::json good = mapOn(Surface::cylinder(tiltedAxis(), 0.55).value()).toJson();
    struct Case {
        const char* key;
        nlohmann::json value; // null: remove the key
        const char* where;    // expected in the message after the path
    };
    const std::vector<Case> cases = {
        {"format", "stylos-poct", "format"},
        {"format", nullptr, "format"},
        {"version", 2, "version"},
        {"version", "1", "version"},
        {"version", nullptr, "version"},
        {"surface", nullptr, "surface"},
        {"reference_dir", nullptr, "reference_dir"},
        {"reference_dir", {1.0, 2.0}, "reference_dir"},
        {"reference_dir", {0.0, 0.0, 1.0}, "reference_dir"}, // not perpendicular to this axis
        {"cut_angle", "north", "cut_angle"},
        {"pixel_size", 0.0, "pixel_size"},
        {"pixel_size", nullptr, "pixel_size"},
        {"width", 0, "width"},
        {"width", 40000, "width"},
        {"width", 12.5, "width"},
        {"height", nullptr, "height"},
        {"v_top", nullptr, "v_top"},
    };
    for (const Case& c : cases) {
        nlohmann::json bad = good;
        if (c.value.is_null()) bad.erase(c.key);
        else bad[c.key] = c.value;
        stylos::test::writeText(path, bad.dump());
        auto result = UnrollMap::readSidecar(path);
        ASSERT_FALSE(result.ok()) << c.key << " = " << c.value.dump();
        EXPECT_EQ(result.error().code, ErrorCode::Malformed) << c.key;
        EXPECT_NE(result.error().message.find(path.string() + ": " + c.where), std::string::npos)
            << c.key << ": " << result.error().message;
    }
    // A bad key inside the surface is named with its path in the object.
    nlohmann::json bad = good;
    bad["surface"].erase("radius");
    auto result = UnrollMap::fromJson(bad, "map.json");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::Malformed);
    EXPECT_NE(result.error().message.find("map.json: surface.radius"), std::string::npos) << result.error().message;
}
