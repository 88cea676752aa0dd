// DrumShape and its patches: the flutes, the claw band, the broken region, the bed faces.
#include "stylos/core/synth/DrumShape.h"
#include "stylos/core/synth/Random.h"
#include "stylos/core/synth/SyntheticScan.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace stylos::core::synth;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

DrumParameters parameters(int grooves = 48, double depth = 0.008, std::uint64_t seed = 11)
{
    SyntheticOptions o;
    o.grooves = grooves;
    o.grooveDepth = depth;
    Random random(seed);
    return DrumParameters::fromOptions(o, random);
}

} // namespace

TEST(SynthDrumShape, FlutesAreCircularArcsOfTheirDepth)
{
    const DrumShape drum(parameters());
    const DrumParameters& p = drum.parameters();
    const nlohmann::json t = drum.drumTruth();
    const double pitch = kTwoPi / 48;
    const double halfWidth = t["grooves"]["halfWidth"].get<double>();
    const double c = t["grooves"]["arcCentreDistance"].get<double>();
    const double rho = t["grooves"]["arcRadius"].get<double>();
    for (int k = 0; k < 48; ++k) {
        const double centre = p.groovePhase + k * pitch;
        EXPECT_NEAR(drum.fluteRadius(centre), p.radius - p.grooveDepth, 1e-12);
        EXPECT_DOUBLE_EQ(drum.fluteRadius(centre + 0.5 * pitch), p.radius); // fillet
        EXPECT_NEAR(drum.fluteRadius(centre + halfWidth * (1.0 - 1e-9)), p.radius, 1e-9); // continuous edge
        for (double f = -0.95; f <= 0.95; f += 0.1) {
            const double theta = centre + f * halfWidth;
            const Eigen::Vector2d point = drum.fluteRadius(theta) * Eigen::Vector2d(std::cos(theta), std::sin(theta));
            const Eigen::Vector2d arcCentre = c * Eigen::Vector2d(std::cos(centre), std::sin(centre));
            EXPECT_NEAR((point - arcCentre).norm(), rho, 1e-12);
        }
    }
}

TEST(SynthDrumShape, RadiusAroundTheDrumHasOneMinimumPerGroove)
{
    for (const int grooves : {48, 24, 20, 3}) {
        const DrumShape drum(parameters(grooves, grooves == 3 ? 0.08 : 0.01));
        const int samples = 4096;
        std::vector<double> r(samples);
        for (int i = 0; i < samples; ++i) r[static_cast<std::size_t>(i)] = drum.fluteRadius(kTwoPi * i / samples);
        int minima = 0;
        for (int i = 0; i < samples; ++i) {
            const double before = r[static_cast<std::size_t>((i + samples - 1) % samples)];
            const double after = r[static_cast<std::size_t>((i + 1) % samples)];
            const double here = r[static_cast<std::size_t>(i)];
            minima += here < before && here <= after;
        }
        EXPECT_EQ(minima, grooves);
    }
    const DrumShape plain(parameters(0));
    EXPECT_DOUBLE_EQ(plain.fluteRadius(1.234), plain.parameters().radius);
}

TEST(SynthDrumShape, LateralSurfaceStaysWithinItsDepth)
{
    const DrumShape drum(parameters());
    const DrumParameters& p = drum.parameters();
    bool clawSeen = false;
    for (double theta = 0.0; theta < kTwoPi; theta += 0.0011)
        for (double z = 0.0; z <= p.height; z += 0.0037) {
            const double r = drum.lateralRadius(theta, z);
            ASSERT_LE(r, p.radius);
            ASSERT_GE(r, p.radius - drum.maxLateralDepth());
            const double claw = drum.fluteRadius(theta) - r;
            const double dTheta = std::remainder(theta - p.brokenCentre, kTwoPi);
            const bool broken = std::fabs(dTheta) <= p.brokenHalfAngle && z >= p.brokenZMin && z <= p.brokenZMax;
            if (z < p.clawMin || z > p.clawMax) {
                if (!broken) {
                    ASSERT_EQ(claw, 0.0) << theta << " " << z;
                }
            } else if (!broken) {
                ASSERT_GE(claw, 0.0);
                ASSERT_LE(claw, p.clawDepth + 1e-15);
                clawSeen = clawSeen || claw > 0.9 * p.clawDepth;
            }
        }
    EXPECT_TRUE(clawSeen);
    // The middle of the broken region is a deep cavity.
    const double middle = drum.lateralRadius(p.brokenCentre, 0.5 * (p.brokenZMin + p.brokenZMax));
    EXPECT_LT(middle, p.radius - p.brokenDepth + 2.0 * p.fractureRoughness);
    EXPECT_GT(middle, p.radius - p.brokenDepth - 2.0 * p.fractureRoughness);
}

TEST(SynthDrumShape, BedFacesHaveAnAnathyrosis)
{
    const DrumShape drum(parameters());
    const DrumParameters& p = drum.parameters();
    const double maxDepth = drum.drumTruth()["anathyrosis"]["maxDepth"].get<double>();
    for (double rho = 0.0; rho < p.radius; rho += 0.003)
        for (double theta = 0.0; theta < kTwoPi; theta += 0.1)
            for (const bool top : {false, true}) {
                const double d = drum.bedDepth(rho * std::cos(theta), rho * std::sin(theta), top);
                if (rho >= p.radius - p.ringWidth) {
                    ASSERT_EQ(d, 0.0); // the smooth contact ring
                } else if (rho < p.radius - p.ringWidth - 0.005) {
                    ASSERT_GE(d, p.recess);
                    ASSERT_LE(d, maxDepth);
                }
            }
}

TEST(SynthDrumShape, PatchesCloseTheDrumWithOutwardNormals)
{
    const DrumShape drum(parameters());
    const DrumParameters& p = drum.parameters();
    const auto patches = drum.patches();
    ASSERT_EQ(patches.size(), 3u);
    const SurfacePatch& lateral = *patches[0];
    EXPECT_TRUE(lateral.columns(0.1).wraps);
    EXPECT_NEAR(lateral.columns(0.1).length(), kTwoPi * p.radius, 1e-12);
    EXPECT_DOUBLE_EQ(lateral.rows().max, p.height);
    // A fillet: the normal is radial. A flute's bottom: radial too.
    for (const double theta : {p.groovePhase + std::numbers::pi / 48, p.groovePhase}) {
        const double a = theta * p.radius;
        const Eigen::Vector3d n = lateral.normal(a, 0.05);
        EXPECT_NEAR(n.dot(Eigen::Vector3d(std::cos(theta), std::sin(theta), 0.0)), 1.0, 1e-6);
        EXPECT_NEAR(lateral.azimuth(a, 0.05), theta, 1e-12);
    }
    const SurfacePatch& bottom = *patches[1];
    const SurfacePatch& top = *patches[2];
    EXPECT_NEAR(bottom.normal(0.3, p.radius - 0.02).z(), -1.0, 1e-9);
    EXPECT_NEAR(top.normal(0.3, p.radius - 0.02).z(), 1.0, 1e-9);
    EXPECT_NEAR(top.normal(0.0, 0.0).z(), 1.0, 1e-12);
    EXPECT_NEAR(top.position(0.3, p.radius - 0.02).z(), p.height, 1e-12);
    EXPECT_NEAR(bottom.position(0.3, p.radius - 0.02).z(), 0.0, 1e-12);
    // The bed is clipped by the flutes: a point at the fillet radius inside a flute is dropped.
    const double inFlute = p.groovePhase * (p.radius - 0.001);
    EXPECT_FALSE(top.contains(inFlute, p.radius - 0.001, top.position(inFlute, p.radius - 0.001)));
    // Carrying a column to another row keeps its azimuth.
    EXPECT_NEAR(top.azimuth(top.carry(0.1, 0.2, 0.25), 0.25), top.azimuth(0.1, 0.2), 1e-12);
}

TEST(SynthDrumShape, ParametersAreCheckedAndDrawnFromTheSeed)
{
    EXPECT_TRUE(parameters().problem().empty());
    EXPECT_TRUE(parameters(0).problem().empty());
    EXPECT_FALSE(parameters(2).problem().empty());
    EXPECT_FALSE(parameters(48, 0.0005).problem().empty());
    EXPECT_FALSE(parameters(48, 0.2).problem().empty());
    DrumParameters bad = parameters();
    bad.height = 0.0;
    EXPECT_FALSE(bad.problem().empty());
    EXPECT_EQ(parameters(48, 0.008, 5).groovePhase, parameters(48, 0.008, 5).groovePhase);
    EXPECT_NE(parameters(48, 0.008, 5).groovePhase, parameters(48, 0.008, 6).groovePhase);
    EXPECT_LT(parameters().groovePhase, kTwoPi / 48);
}
