// A développée at a given radius about a given axis (how a fragment unrolls at its drum's leading radius) reports
// the misfit of the lateral surface, as a fit does: on a plain generated drum (radius 0.2 m, bed faces, noise
// 0.33 mm) unrolled at its true radius about its true axis, the RMS is at the noise's scale and the bed faces
// fall outside the band; at a radius 5 mm too large the RMS reads 5 to 8 mm (the offset and the relief).
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include "stylos/core/developpee/Developpee.h"

#include <gtest/gtest.h>

#include <fstream>

using namespace stylos::core;

namespace {

/** A plain generated drum (radius 0.2 m at its lower bed, height 0.3 m, 4 mm spacing) losing @p taper of radius
 *  to its top, written in @p dir; the options of a développée at radius 0.2 m about its true axis. */
developpee::DeveloppeeOptions plainDrum(const stylos::test::TempDir& dir, double taper, std::filesystem::path& ply)
{
    auto o = stylos::test::coarse(0.004, 9);
    o.radius = 0.2;
    o.height = 0.3;
    o.grooves = 0;
    o.taper = taper;
    ply = dir / "drum.ply";
    const auto report = stylos::test::generate(synth::SyntheticKind::Drum, o, ply);
    std::ifstream truthFile(report.truthPath);
    const Eigen::Affine3d pose = stylos::test::poseOf(nlohmann::json::parse(truthFile));
    developpee::DeveloppeeOptions options;
    options.axis = unroll::Axis{pose.translation(), pose.linear() * Eigen::Vector3d::UnitZ()};
    options.radius = 0.2;
    options.shading = developpee::Shading::Height;
    return options;
}

} // namespace

TEST(DeveloppeeGivenRadius, ReportsTheLateralSurfacesMisfit)
{
    stylos::test::TempDir dir;
    std::filesystem::path ply;
    auto options = plainDrum(dir, 0.0, ply);
    const auto made = developpee::computeDeveloppee(ply, options);
    ASSERT_TRUE(made.ok()) << made.error().message;
    EXPECT_LT(made->fit.rmsResidual, 0.0015);       // the noise and the generator's relief, not the bed faces
    EXPECT_GT(made->fit.inlierFraction, 0.4);
    EXPECT_LT(made->fit.inlierFraction, 0.97);      // the bed faces are outside the band
    EXPECT_DOUBLE_EQ(made->fit.surface.referenceRadius(), 0.2);

    options.radius = 0.205;
    const auto off = developpee::computeDeveloppee(ply, options);
    ASSERT_TRUE(off.ok()) << off.error().message;
    EXPECT_GT(off->fit.rmsResidual, 0.005); // the 5 mm offset, with the relief and noise on top of it
    EXPECT_LT(off->fit.rmsResidual, 0.008);
}

// A tapering drum (6 mm narrower at its top) unrolled on its guides' cone: the surface is that cone, nothing
// fitted, and the misfit is the noise's; on the cylinder of its lower radius the misfit grows with the taper.
TEST(DeveloppeeGivenRadius, ATaperingDrumUnrollsOnItsCone)
{
    stylos::test::TempDir dir;
    std::filesystem::path ply;
    auto options = plainDrum(dir, 0.006, ply);
    options.radiusSlope = -0.006 / 0.3;
    const auto made = developpee::computeDeveloppee(ply, options);
    ASSERT_TRUE(made.ok()) << made.error().message;
    EXPECT_EQ(made->fit.surface.kind(), unroll::SurfaceKind::Cone);
    EXPECT_DOUBLE_EQ(made->fit.surface.slope(), -0.02);
    EXPECT_DOUBLE_EQ(made->fit.surface.referenceRadius(), 0.2);
    EXPECT_LT(made->fit.rmsResidual, 0.0015);

    options.radiusSlope = 0.0; // the cylinder of the lower bed's radius: up to 6 mm off at the top
    const auto cylinder = developpee::computeDeveloppee(ply, options);
    ASSERT_TRUE(cylinder.ok()) << cylinder.error().message;
    EXPECT_EQ(cylinder->fit.surface.kind(), unroll::SurfaceKind::Cylinder);
    EXPECT_GT(cylinder->fit.rmsResidual, 0.002);
}
