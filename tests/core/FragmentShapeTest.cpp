// FragmentShape: a closed piece of a drum, its fracture faces consistent with each other.
#include "stylos/core/synth/FragmentShape.h"
#include "stylos/core/synth/Random.h"
#include "stylos/core/synth/SyntheticScan.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace stylos::core::synth;
using Face = FragmentShape::Face;

namespace {

std::unique_ptr<FragmentShape> makeFragment(std::uint64_t seed = 9)
{
    Random random(seed);
    const DrumParameters drum = DrumParameters::fromOptions(SyntheticOptions{}, random);
    return std::make_unique<FragmentShape>(drum, FragmentParameters::random(drum, random));
}

} // namespace

TEST(SynthFragmentShape, IsAnUnbrokenDrumsSector)
{
    const auto fragment = makeFragment();
    EXPECT_FALSE(fragment->drum().parameters().broken);
    const FragmentParameters& f = fragment->parameters();
    EXPECT_GE(2.0 * f.halfAngle, 40.0 * std::numbers::pi / 180.0);
    EXPECT_LE(2.0 * f.halfAngle, 60.0 * std::numbers::pi / 180.0);
    EXPECT_TRUE(fragment->inside(fragment->scanCentre(), Face::Outer));
    nlohmann::json truth;
    fragment->describe(truth);
    EXPECT_EQ(truth["grooves"]["count"].get<int>(), 48);
    EXPECT_DOUBLE_EQ(truth["fragment"]["thetaCentre"].get<double>(), f.thetaCentre);
    EXPECT_DOUBLE_EQ(truth["fragment"]["innerRadius"].get<double>(),
                     fragment->drum().parameters().radius - f.thickness);
}

TEST(SynthFragmentShape, FracturePointsBoundTheSolid)
{
    const auto fragment = makeFragment();
    const FragmentParameters& f = fragment->parameters();
    const double radius = fragment->drum().parameters().radius;
    const double zMid = 0.5 * (f.zMin + fragment->height());
    const double rMid = radius - 0.5 * f.thickness;
    const Eigen::Vector3d radial(std::cos(f.thetaCentre), std::sin(f.thetaCentre), 0.0);
    const Eigen::Vector3d tangent = Eigen::Vector3d::UnitZ().cross(radial);
    const Eigen::AngleAxisd toLow(-f.halfAngle, Eigen::Vector3d::UnitZ());
    const Eigen::AngleAxisd toHigh(f.halfAngle, Eigen::Vector3d::UnitZ());
    // Mid-face points of each fracture face, with the direction into the piece there.
    struct Probe {
        Face face;
        double a, b;
        Eigen::Vector3d inward;
    };
    const Probe probes[] = {{Face::SideLow, rMid, zMid, toLow * tangent},
                            {Face::SideHigh, rMid, zMid, -(toHigh * tangent)},
                            {Face::Inner, 0.0, zMid, radial},
                            {Face::Bottom, 0.0, rMid, Eigen::Vector3d::UnitZ()}};
    for (const Probe& probe : probes) {
        const Eigen::Vector3d p = fragment->fracturePoint(probe.face, probe.a, probe.b);
        EXPECT_TRUE(fragment->inside(p, probe.face));
        // Just inside the face the solid continues; just outside it does not.
        EXPECT_TRUE(fragment->inside(p + 0.002 * probe.inward, Face::Outer));
        EXPECT_FALSE(fragment->inside(p - 0.002 * probe.inward, Face::Outer));
    }
}

TEST(SynthFragmentShape, SampledFacesStayInTheSector)
{
    const auto fragment = makeFragment(21);
    const FragmentParameters& f = fragment->parameters();
    const double radius = fragment->drum().parameters().radius;
    const double bound = fragment->fractureBound();
    const double rIn = radius - f.thickness;
    const auto patches = fragment->patches();
    ASSERT_EQ(patches.size(), 6u);
    for (const SurfacePatch* patch : patches) {
        int kept = 0;
        int outward = 0;
        const ParameterRange rows = patch->rows();
        for (double b = rows.min; b <= rows.max; b += 0.004) {
            const ParameterRange columns = patch->columns(b);
            for (double a = columns.min; a <= columns.max; a += 0.004) {
                const Eigen::Vector3d p = patch->position(a, b);
                if (!patch->contains(a, b, p)) continue;
                ++kept;
                const double r = p.head<2>().norm();
                const double dTheta = std::remainder(std::atan2(p.y(), p.x()) - f.thetaCentre, 2.0 * std::numbers::pi);
                ASSERT_LE(r, radius + 1e-12);
                ASSERT_GE(r, rIn - bound);
                ASSERT_LE(std::fabs(dTheta), f.halfAngle + bound / rIn);
                ASSERT_GE(p.z(), f.zMin - bound);
                ASSERT_LE(p.z(), fragment->height() + 1e-12);
                const Eigen::Vector3d n = patch->normal(a, b);
                ASSERT_NEAR(n.norm(), 1.0, 1e-9);
                outward += n.dot(p - fragment->scanCentre()) > 0.0; // a wedge: normals leave its middle
            }
        }
        EXPECT_GT(kept, 100);
        EXPECT_GT(outward, 0.95 * kept);
    }
}
