#include "stylos/core/unroll/Meridian.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace stylos::core::unroll {
namespace {

Meridian make(std::vector<Eigen::Vector2d> vertices, double reach)
{
    auto m = Meridian::create(std::move(vertices), reach);
    EXPECT_TRUE(m.ok()) << (m.ok() ? "" : m.error().message);
    return std::move(m).value();
}

/** A half circle of radius rho about (t, r) = (0, 0), from the bottom pole to the top pole. */
Meridian sphere(double rho, int segments, double reach)
{
    std::vector<Eigen::Vector2d> v;
    for (int i = 0; i <= segments; ++i) {
        const double a = -std::numbers::pi / 2 + std::numbers::pi * i / segments;
        v.emplace_back(rho * std::sin(a), rho * std::cos(a));
    }
    v.front().y() = 0.0; // exact poles
    v.back().y() = 0.0;
    return make(std::move(v), reach);
}

TEST(MeridianTest, StraightMeridianGivesAxialPositionAndRadialHeight)
{
    const Meridian m = make({{0.1, 0.5}, {0.3, 0.5}, {0.6, 0.5}}, 0.05);
    EXPECT_DOUBLE_EQ(m.length(), 0.5);
    const auto c = m.project(0.35, 0.52);
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->v, 0.25, 1e-15);
    EXPECT_NEAR(c->h, 0.02, 1e-15);
    const auto inside = m.project(0.2, 0.47);
    ASSERT_TRUE(inside);
    EXPECT_NEAR(inside->v, 0.1, 1e-15);
    EXPECT_NEAR(inside->h, -0.03, 1e-15);
    const Eigen::Vector2d p = m.point(0.25, 0.02);
    EXPECT_NEAR(p.x(), 0.35, 1e-15);
    EXPECT_NEAR(p.y(), 0.52, 1e-15);
}

TEST(MeridianTest, EndsExtendAlongTheirTangent)
{
    const Meridian m = make({{0.0, 0.5}, {1.0, 0.5}}, 0.1);
    const auto below = m.project(-0.04, 0.51);
    ASSERT_TRUE(below);
    EXPECT_NEAR(below->v, -0.04, 1e-15);
    EXPECT_NEAR(below->h, 0.01, 1e-15);
    const auto above = m.project(1.05, 0.45);
    ASSERT_TRUE(above);
    EXPECT_NEAR(above->v, 1.05, 1e-15);
    EXPECT_NEAR(above->h, -0.05, 1e-15);
    EXPECT_FALSE(m.project(0.5, 0.65)); // 0.15 from the meridian, reach 0.1
    EXPECT_FALSE(m.project(1.2, 0.5));
}

TEST(MeridianTest, SphereHeightsAreRadialAndTheMapInvertsExactly)
{
    const double rho = 0.4;
    const Meridian m = sphere(rho, 720, 0.05);
    EXPECT_NEAR(m.length(), std::numbers::pi * rho, 1e-5); // the polygon is slightly shorter than the arc
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> angle(-1.4, 1.4), height(-0.03, 0.03);
    for (int i = 0; i < 2000; ++i) {
        const double a = angle(random), h = height(random);
        const Eigen::Vector2d p((rho + h) * std::sin(a), (rho + h) * std::cos(a));
        const auto c = m.project(p.x(), p.y());
        ASSERT_TRUE(c);
        // Polygon vs circle: the chord sags by rho·(1 − cos(π/1440)) = 0.95 µm.
        EXPECT_NEAR(c->h, h, 1.0e-6);
        EXPECT_NEAR(c->v, rho * (a + std::numbers::pi / 2), 1.5e-6); // the chords are 0.8 ppm short
        const Eigen::Vector2d back = m.point(c->v, c->h);
        EXPECT_NEAR(back.x(), p.x(), 1e-12);
        EXPECT_NEAR(back.y(), p.y(), 1e-12);
    }
}

TEST(MeridianTest, CornerOfAPlinthRoundTripsOnBothSides)
{
    // Up a plinth side, in along its top, up a body: two corners, one convex, one concave.
    const Meridian m = make({{0.0, 0.5}, {0.12, 0.5}, {0.12, 0.34}, {0.6, 0.34}}, 0.03);
    // On the coarse plinth top both vertex normals bisect their corners: (1, 1)/√2 all along.
    const auto coarse = m.project(0.125, 0.42);
    ASSERT_TRUE(coarse);
    EXPECT_NEAR(coarse->v, 0.205, 1e-12);
    EXPECT_NEAR(coarse->h, 0.005 * std::sqrt(2.0), 1e-12);
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> v(0.0, m.length()), h(-0.01, 0.01);
    for (int i = 0; i < 3000; ++i) {
        const double vi = v(random), hi = h(random);
        const Eigen::Vector2d p = m.point(vi, hi);
        const auto c = m.project(p.x(), p.y());
        ASSERT_TRUE(c);
        const Eigen::Vector2d back = m.point(c->v, c->h);
        EXPECT_NEAR(back.x(), p.x(), 1e-12) << "v " << vi << " h " << hi;
        EXPECT_NEAR(back.y(), p.y(), 1e-12) << "v " << vi << " h " << hi;
    }
    // Normals bisect the corners; where both ends of a segment have its own normal (the middle
    // segment of the plinth top, facing +t) a point 5 mm above it is 5 mm out, 0.2 along.
    const Meridian fine = make({{0.0, 0.5}, {0.12, 0.5}, {0.12, 0.46}, {0.12, 0.38}, {0.12, 0.34}, {0.6, 0.34}}, 0.03);
    const auto top = fine.project(0.125, 0.42);
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->v, 0.12 + 0.08, 1e-12);
    EXPECT_NEAR(top->h, 0.005, 1e-12);
}

TEST(MeridianTest, RefusesBadVertices)
{
    EXPECT_EQ(Meridian::create({{0, 1}}, 0.1).error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(Meridian::create({{0, 1}, {0, 1}}, 0.1).error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(Meridian::create({{0, 1}, {1, -0.1}}, 0.1).error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(Meridian::create({{0, 1}, {NAN, 1}}, 0.1).error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(Meridian::create({{0, 1}, {1, 1}}, 0.0).error().code, ErrorCode::InvalidArgument);
    const auto m = Meridian::create({{0, 1}, {1, -0.1}}, 0.1);
    EXPECT_NE(m.error().message.find("vertex 1 has a negative radius"), std::string::npos) << m.error().message;
}

} // namespace
} // namespace stylos::core::unroll
