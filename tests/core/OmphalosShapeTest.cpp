// OmphalosShape: the meridian, the ovoid's profile, the raised net.
#include "stylos/core/synth/OmphalosShape.h"
#include "stylos/core/synth/Random.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace stylos::core::synth;

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
}

TEST(SynthOmphalosShape, MeridianRunsFromThePlinthToTheApexByArcLength)
{
    const OmphalosShape shape(OmphalosParameters{});
    const OmphalosParameters& p = shape.parameters();
    EXPECT_NEAR(shape.height(), 1.2, 1e-12);
    const auto start = shape.meridian(0.0);
    EXPECT_NEAR(start.r, p.plinthRadius, 1e-12);
    EXPECT_NEAR(start.z, 0.0, 1e-12);
    EXPECT_NEAR(start.nr, 1.0, 1e-9); // plinth side faces outwards
    const auto apex = shape.meridian(shape.meridianLength());
    EXPECT_NEAR(apex.r, 0.0, 1e-9);
    EXPECT_NEAR(apex.z, shape.height(), 1e-6);
    EXPECT_NEAR(apex.nz, 1.0, 1e-3);
    const auto plinthTop = shape.meridian(p.plinthHeight + 0.05);
    EXPECT_NEAR(plinthTop.z, p.plinthHeight, 1e-12);
    EXPECT_NEAR(plinthTop.nz, 1.0, 1e-9);
    const double ds = 0.001;
    for (double s = 0.0; s + ds < shape.meridianLength(); s += ds) {
        const auto a = shape.meridian(s);
        const auto b = shape.meridian(s + ds);
        const double step = std::hypot(b.r - a.r, b.z - a.z);
        ASSERT_LE(step, ds * (1.0 + 1e-6));
        ASSERT_GE(step, 0.7 * ds); // only the plinth's corners cut a little
        ASSERT_NEAR(std::hypot(a.nr, a.nz), 1.0, 1e-9);
    }
}

TEST(SynthOmphalosShape, OvoidFollowsItsProfile)
{
    const OmphalosShape shape(OmphalosParameters{});
    for (double s = shape.bodyStart() + 0.001; s < shape.meridianLength() - 0.01; s += 0.0037) {
        const auto m = shape.meridian(s);
        ASSERT_NEAR(m.r, shape.bodyRadius(m.z), 1e-6) << s; // steep near the apex: z errors show in r
    }
    EXPECT_EQ(shape.bodyRadius(shape.parameters().plinthHeight - 0.01), 0.0);
    nlohmann::json truth;
    shape.describe(truth);
    const auto& z = truth["profile"]["z"];
    const auto& r = truth["profile"]["r"];
    ASSERT_EQ(z.size(), r.size());
    for (std::size_t i = 0; i < z.size(); ++i) ASSERT_DOUBLE_EQ(r[i].get<double>(), shape.bodyRadius(z[i].get<double>()));
}

TEST(SynthOmphalosShape, NetStandsProudInALatticeOfBands)
{
    Random random(4);
    const OmphalosShape shape(OmphalosParameters::random(random));
    const OmphalosParameters& p = shape.parameters();
    nlohmann::json truth;
    shape.describe(truth);
    const double sMin = truth["net"]["sMin"].get<double>();
    const double sMax = truth["net"]["sMax"].get<double>();
    const double mesh = truth["net"]["meshLength"].get<double>();
    // The bands cross at θ = phase + 2πk/M, s = sMin + j·mesh (j even) and midway (j odd, shifted).
    for (int k = 0; k < p.meshesAround; ++k)
        EXPECT_NEAR(shape.netHeight(p.netPhase + kTwoPi * k / p.meshesAround, sMin + 2.0 * mesh), p.bandHeight, 1e-12);
    int bare = 0, samples = 0;
    for (double s = sMin; s <= sMax; s += 0.005)
        for (double theta = 0.0; theta < kTwoPi; theta += 0.01) {
            const double h = shape.netHeight(theta, s);
            ASSERT_GE(h, 0.0);
            ASSERT_LE(h, p.bandHeight);
            bare += h == 0.0;
            ++samples;
        }
    EXPECT_GT(bare, samples / 3); // lozenges of bare stone between the bands
    EXPECT_LT(bare, samples);
    EXPECT_EQ(shape.netHeight(1.0, shape.bodyStart()), 0.0); // below the net
    EXPECT_EQ(shape.netHeight(1.0, shape.meridianLength()), 0.0); // the apex is bare
}

TEST(SynthOmphalosShape, OnePatchWithOutwardNormals)
{
    const OmphalosShape shape(OmphalosParameters{});
    const auto patches = shape.patches();
    ASSERT_EQ(patches.size(), 1u);
    const SurfacePatch& patch = *patches[0];
    EXPECT_TRUE(patch.columns(0.5).wraps);
    for (double s = 0.01; s < shape.meridianLength(); s += 0.05) {
        const double r = shape.meridian(s).r;
        for (const double theta : {0.3, 2.0, 4.5}) {
            const Eigen::Vector3d p = patch.position(theta * r, s);
            const Eigen::Vector3d n = patch.normal(theta * r, s);
            ASSERT_NEAR(n.norm(), 1.0, 1e-9);
            // Outwards, as the bare meridian's normal (the net's bands tilt it a little).
            const auto m = shape.meridian(s);
            const Eigen::Vector3d out(m.nr * std::cos(theta), m.nr * std::sin(theta), m.nz);
            ASSERT_GT(n.dot(out), 0.7) << s;
            ASSERT_NEAR(std::atan2(p.y(), p.x()), std::remainder(theta, 2.0 * std::numbers::pi), 1e-9);
            ASSERT_NEAR(patch.azimuth(theta * r, s), theta, 1e-9);
        }
    }
}
