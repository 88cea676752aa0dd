#include "stylos/core/unroll/Surface.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace stylos::core::unroll {
namespace {

Axis tiltedAxis()
{
    return Axis{{1.0, -2.0, 0.5}, Eigen::Vector3d(0.2, 0.1, 1.0).normalized()};
}

TEST(SurfaceTest, CylinderAndConeCoordinates)
{
    const Surface cylinder = Surface::cylinder(tiltedAxis(), 0.55).value();
    const auto c = cylinder.meridianCoords(0.3, 0.56);
    ASSERT_TRUE(c);
    EXPECT_DOUBLE_EQ(c->v, 0.3);
    EXPECT_NEAR(c->h, 0.01, 1e-15);
    EXPECT_EQ(cylinder.meridianPoint(0.3, 0.01), Eigen::Vector2d(0.3, 0.56));

    const Surface cone = Surface::cone(tiltedAxis(), 0.5, -0.1, 0.48).value();
    const auto k = cone.meridianCoords(0.2, 0.5);
    ASSERT_TRUE(k);
    EXPECT_NEAR(k->h, 0.02, 1e-15); // r(0.2) = 0.48
    EXPECT_NEAR(cone.meridianPoint(0.2, 0.02).y(), 0.5, 1e-15);
    EXPECT_DOUBLE_EQ(cone.referenceRadius(), 0.48);
    EXPECT_DOUBLE_EQ(cone.axial(tiltedAxis().point + 0.7 * tiltedAxis().direction), 0.7);
}

TEST(SurfaceTest, JsonRoundTripsEveryKind)
{
    auto meridian = Meridian::create({{0.0, 0.5}, {0.12, 0.5}, {0.12, 0.34}, {0.6, 0.34}, {0.7, 0.0}}, 0.03).value();
    const Surface surfaces[] = {Surface::cylinder(tiltedAxis(), 0.55).value(),
                                Surface::cone(tiltedAxis(), 0.5, -0.1, 0.48).value(),
                                Surface::revolution(tiltedAxis(), meridian, 0.4).value()};
    for (const Surface& s : surfaces) {
        const nlohmann::json j = nlohmann::json::parse(s.toJson().dump());
        const auto back = Surface::fromJson(j, "x.json");
        ASSERT_TRUE(back.ok()) << back.error().message;
        EXPECT_EQ(back->kind(), s.kind());
        EXPECT_EQ(back->axis().point, s.axis().point);
        EXPECT_NEAR((back->axis().direction - s.axis().direction).norm(), 0.0, 1e-16);
        EXPECT_EQ(back->radius(), s.radius());
        EXPECT_EQ(back->slope(), s.slope());
        EXPECT_EQ(back->referenceRadius(), s.referenceRadius());
        const auto a = s.meridianCoords(0.3, 0.36), b = back->meridianCoords(0.3, 0.36);
        ASSERT_TRUE(a && b);
        EXPECT_NEAR(a->v, b->v, 1e-15);
        EXPECT_NEAR(a->h, b->h, 1e-15);
    }
    EXPECT_EQ(surfaces[2].toJson()["meridian"].size(), 5u);
}

TEST(SurfaceTest, FromJsonNamesTheFileAndTheKey)
{
    nlohmann::json j = Surface::cylinder(tiltedAxis(), 0.55).value().toJson();
    j.erase("radius");
    auto r = Surface::fromJson(j, "drum.png.json");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::Malformed);
    EXPECT_EQ(r.error().message, "drum.png.json: surface.radius: is missing or not a finite number");
    j["radius"] = -1.0;
    r = Surface::fromJson(j, "drum.png.json");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("positive"), std::string::npos) << r.error().message;
    j["radius"] = 0.5;
    j["kind"] = "sphere";
    r = Surface::fromJson(j, "d.json");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "d.json: surface.kind: is \"sphere\", not cylinder, cone or revolution");
    j["kind"] = "revolution";
    j["reach"] = 0.01;
    r = Surface::fromJson(j, "d.json");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "d.json: surface.meridian: is missing or not an array");
}

TEST(SurfaceTest, RefusesBadAxesAndRadii)
{
    EXPECT_FALSE(Surface::cylinder(Axis{{0, 0, 0}, {0, 0, 2}}, 1.0).ok());
    EXPECT_FALSE(Surface::cylinder(Axis{{NAN, 0, 0}, {0, 0, 1}}, 1.0).ok());
    EXPECT_FALSE(Surface::cylinder(Axis{}, 0.0).ok());
    EXPECT_FALSE(Surface::cone(Axis{}, 1.0, INFINITY, 1.0).ok());
    EXPECT_EQ(surfaceKindFromName("cone"), SurfaceKind::Cone);
    EXPECT_FALSE(surfaceKindFromName("Cone"));
}

} // namespace
} // namespace stylos::core::unroll
