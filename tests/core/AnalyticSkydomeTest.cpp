// The analytic skydome of the generated shapes against closed forms: an open flat face sees its whole
// hemisphere, the bottom of a long flute sees the directions whose azimuth clears the flute's edges, a
// convex face sees everything; the solids' inside tests and clearance bounds.
#include "stylos/core/ao/Directions.h"
#include "stylos/core/synth/AnalyticSkydome.h"
#include "stylos/core/synth/DrumShape.h"
#include "stylos/core/synth/FragmentShape.h"
#include "stylos/core/synth/Random.h"
#include "stylos/core/synth/SyntheticScan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace stylos::core::synth;

namespace {

DrumParameters plainDrum()
{
    DrumParameters p;
    p.clawBand = false;
    p.broken = false;
    p.anathyrosis = false;
    return p;
}

const std::vector<std::array<double, 3>>& directions256()
{
    static const auto d = stylos::core::ao::fibonacciDirections(256, false);
    return d;
}

} // namespace

TEST(AnalyticSkydome, OpenBedFaceSeesItsWholeHemisphere)
{
    DrumParameters p = plainDrum();
    p.anathyrosis = true; // a recessed centre: the ring's rays pass over it
    const DrumShape drum(p);
    const auto solid = drumSolid(drum);
    for (const double rho : {p.radius - 0.5 * p.ringWidth, 0.0}) {
        const double depth = drum.bedDepth(rho, 0.0, true);
        const AnalyticSkyCount count = analyticSkydome(*solid, {rho, 0.0, p.height - depth}, {0.0, 0.0, 1.0},
                                                       directions256());
        EXPECT_EQ(count.front, 128) << rho; // z_i = 1 − (2i + 1)/256 > 0 for i < 128
        if (rho > 0.0) EXPECT_EQ(count.free, 128); // the flat ring; the recess's dressing may hide a few
        else EXPECT_GE(count.free, 120);
    }
}

TEST(AnalyticSkydome, ConvexLateralFaceSeesEverything)
{
    DrumParameters p = plainDrum();
    p.grooves = 0;
    const DrumShape drum(p);
    const auto solid = drumSolid(drum);
    const double theta = 0.7;
    const Eigen::Vector3d n(std::cos(theta), std::sin(theta), 0.0);
    const AnalyticSkyCount count = analyticSkydome(*solid, p.radius * n + Eigen::Vector3d(0, 0, 0.2), n, directions256());
    EXPECT_EQ(count.free, count.front);
    EXPECT_GT(count.front, 100);
}

TEST(AnalyticSkydome, FluteBottomSeesTheArcBetweenItsEdges)
{
    // A tall drum: the flute is a long straight groove whose cross-section is a circular arc from the
    // fillet circle at azimuths ±w down to R − depth. A ray from the bottom B = (R − depth, 0) escapes
    // exactly when its horizontal direction's angle ψ from the radius is within the angle of the edges
    // E± = R (cos w, ±sin w) seen from B (past them the fillet circle, convex, never comes back).
    DrumParameters p = plainDrum();
    p.height = 10.0;
    p.groovePhase = 0.0;
    const DrumShape drum(p);
    const auto solid = drumSolid(drum);
    const double w = 0.5 * (2.0 * std::numbers::pi / p.grooves) * (1.0 - p.filletFraction);
    const double edge = std::atan2(p.radius * std::sin(w), p.radius * std::cos(w) - (p.radius - p.grooveDepth));
    int front = 0, free = 0;
    double closest = 1.0;
    for (const auto& d : directions256()) {
        if (!(d[0] > 0.0)) continue;
        ++front;
        const double psi = std::fabs(std::atan2(d[1], d[0]));
        free += psi < edge;
        closest = std::min(closest, std::fabs(psi - edge));
    }
    ASSERT_GT(closest, 1e-3); // no direction grazes an edge: the count is exact
    const Eigen::Vector3d bottom(p.radius - p.grooveDepth, 0.0, 0.5 * p.height);
    EXPECT_NEAR(drum.lateralRadius(0.0, bottom.z()), bottom.x(), 1e-12);
    const AnalyticSkyCount count = analyticSkydome(*solid, bottom, Eigen::Vector3d::UnitX(), directions256());
    EXPECT_EQ(count.front, front);
    EXPECT_EQ(count.free, free);
    EXPECT_LT(free, front); // the flute hides something
    EXPECT_GT(free, front / 2);
}

TEST(AnalyticSkydome, DrumInsideFollowsTheSurface)
{
    const DrumShape drum(plainDrum());
    const auto& p = drum.parameters();
    const double zMid = 0.5 * p.height;
    EXPECT_TRUE(drum.inside({0.0, 0.0, zMid}));
    EXPECT_FALSE(drum.inside({0.0, 0.0, p.height + 1e-6}));
    EXPECT_FALSE(drum.inside({0.0, 0.0, -1e-6}));
    const double theta = p.groovePhase; // a flute's bottom
    const Eigen::Vector3d radial(std::cos(theta), std::sin(theta), 0.0);
    const double bottom = p.radius - p.grooveDepth;
    EXPECT_TRUE(drum.inside(radial * (bottom - 1e-5) + Eigen::Vector3d(0, 0, zMid)));
    EXPECT_FALSE(drum.inside(radial * (bottom + 1e-5) + Eigen::Vector3d(0, 0, zMid)));
}

TEST(AnalyticSkydome, ClearanceNeverReachesTheSolid)
{
    Random random(5);
    const DrumParameters design = DrumParameters::fromOptions(SyntheticOptions{}, random);
    const DrumShape drum(design);
    const FragmentShape fragment(design, FragmentParameters::random(design, random));
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const auto& solid : {drumSolid(drum), fragmentSolid(fragment)}) {
        int positive = 0;
        for (int i = 0; i < 4000; ++i) {
            const Eigen::Vector3d q =
                solid->boundCentre() + 1.3 * solid->boundRadius() * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
            const double c = solid->clearance(q);
            if (!(c > 0.0)) continue;
            ++positive;
            for (int k = 0; k < 8; ++k) {
                const Eigen::Vector3d u = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
                ASSERT_FALSE(solid->inside(q + 0.999 * c * std::fabs(unit(rng)) * u)) << i;
            }
        }
        EXPECT_GT(positive, 1000);
    }
}

TEST(AnalyticSkydome, FragmentRingSeesItsHemisphereAndCoreIsInside)
{
    Random random(9);
    const DrumParameters design = DrumParameters::fromOptions(SyntheticOptions{}, random);
    const FragmentShape fragment(design, FragmentParameters::random(design, random));
    const auto solid = analyticSolid(fragment);
    ASSERT_TRUE(solid);
    const auto& f = fragment.parameters();
    const auto& d = fragment.drum().parameters();
    const double rho = d.radius - 0.5 * d.ringWidth;
    const Eigen::Vector3d top(rho * std::cos(f.thetaCentre), rho * std::sin(f.thetaCentre), d.height);
    const AnalyticSkyCount count = analyticSkydome(*solid, top, Eigen::Vector3d::UnitZ(), directions256());
    EXPECT_EQ(count.front, 128);
    EXPECT_EQ(count.free, 128);
    EXPECT_TRUE(solid->inside(fragment.scanCentre()));
    EXPECT_FALSE(solid->inside(Eigen::Vector3d(0.0, 0.0, 0.5 * d.height))); // the drum's axis: not in the piece
    // Straight down from the top face, through the piece: blocked.
    EXPECT_TRUE(analyticRayBlocked(*solid, top + Eigen::Vector3d(0, 0, 1e-3), -Eigen::Vector3d::UnitZ()));
    EXPECT_FALSE(analyticRayBlocked(*solid, top, Eigen::Vector3d::UnitZ()));
}

TEST(AnalyticSkydome, OnlyDrumsAndFragmentsHaveASolid)
{
    SyntheticOptions options;
    EXPECT_TRUE(analyticSolid(*makeSyntheticObject(SyntheticKind::Drum, options)));
    EXPECT_TRUE(analyticSolid(*makeSyntheticObject(SyntheticKind::Fragment, options)));
    EXPECT_FALSE(analyticSolid(*makeSyntheticObject(SyntheticKind::Omphalos, options)));
}
