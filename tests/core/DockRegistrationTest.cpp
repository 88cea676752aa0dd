// dockFragment: generated fragments docked against the guides of a generated drum of the same design
// (different noise, registration and pose) from perturbed starts; z reported unobservable and kept;
// locks hold exactly; refusals (no flutes, too far) leave nothing half done.
#include "DockTestSupport.h"

#include "stylos/core/dock/DockRegistration.h"

#include <gtest/gtest.h>

#include <cstdio>


namespace stylos::core::dock {
namespace {

const DrumGuides& guides()
{
    static const DrumGuides g = [] {
        auto r = fitDrumGuides(test::dockDrum().cloud);
        EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
        return r.ok() ? *r : DrumGuides{};
    }();
    return g;
}

TEST(DockRegistrationTest, DocksFromPerturbedStarts)
{
    const DrumFrame frame(guides());
    for (std::uint64_t seed : {3u, 5u, 8u}) {
        const auto& fragment = test::dockFragment(seed);
        const Eigen::Isometry3d truth = test::truePose(fragment, test::dockDrum());
        const Eigen::Vector3d centre = test::cloudCentre(fragment.cloud);
        const Eigen::Vector3d centreInDrum = truth * centre;
        for (const auto& [theta, tilt, radial] : {std::tuple{0.0, 0.0, 0.0}, std::tuple{3.0, 5.0, 0.015},
                                                  std::tuple{-3.0, -5.0, -0.015}, std::tuple{2.0, -3.0, 0.01}}) {
            const Eigen::Isometry3d start = test::perturbed(truth, frame, centreInDrum, theta * std::numbers::pi / 180.0,
                                                            tilt * std::numbers::pi / 180.0, radial);
            auto result = dockFragment(fragment.cloud, guides(), start);
            ASSERT_TRUE(result.ok()) << result.error().message;
            const auto e = test::dockErrors(result->pose, truth, frame, centre);
            EXPECT_LT(e.thetaDeg, 0.01);
            EXPECT_LT(e.tiltDeg, 0.02);
            EXPECT_LT(e.radialMm, 0.05);
            ASSERT_EQ(result->unobservable.size(), 1u);
            EXPECT_EQ(result->unobservable[0], DockUnknown::Z);
            EXPECT_EQ(result->uncertainty.size(), 5u);
        }
        // The RMS is what the noise alone leaves: the same measure at the true pose, nothing free.
        DockOptions fixed;
        fixed.locked.fill(true);
        auto atTruth = dockFragment(fragment.cloud, guides(), truth, fixed);
        ASSERT_TRUE(atTruth.ok()) << atTruth.error().message;
        EXPECT_TRUE(atTruth->pose.isApprox(truth, 1e-12));
        auto docked = dockFragment(fragment.cloud, guides(), truth);
        ASSERT_TRUE(docked.ok());
        EXPECT_NEAR(docked->rms / atTruth->rms, 1.0, 0.05) << docked->rms << " vs " << atTruth->rms;
    }
}

TEST(DockRegistrationTest, DocksAgainstATaperingDrum)
{
    // A drum 6 mm narrower at its top and a fragment of the same design: the guides' cone, the fragment
    // registered against the scaled profile at its own height.
    auto drumOptions = test::allRound(0.003, 101, 48);
    drumOptions.designSeed = test::kDockDesign;
    drumOptions.taper = 0.006;
    const auto& drum = test::generatedScan("dock-drum-taper", synth::SyntheticKind::Drum, drumOptions);
    auto fitted = fitDrumGuides(drum.cloud);
    ASSERT_TRUE(fitted.ok()) << fitted.error().message;
    ASSERT_NE(fitted->slope, 0.0);
    const DrumFrame frame(*fitted);
    auto fragmentOptions = test::allRound(0.003, 5, 48);
    fragmentOptions.designSeed = test::kDockDesign;
    fragmentOptions.taper = 0.006;
    const auto& fragment = test::generatedScan("dock-fragment-taper", synth::SyntheticKind::Fragment, fragmentOptions);
    const Eigen::Isometry3d truth = test::truePose(fragment, drum);
    const Eigen::Vector3d centre = test::cloudCentre(fragment.cloud);
    for (const auto& [theta, tilt, radial] : {std::tuple{3.0, 5.0, 0.015}, std::tuple{-3.0, -5.0, -0.015}}) {
        const Eigen::Isometry3d start = test::perturbed(truth, frame, truth * centre, theta * std::numbers::pi / 180.0,
                                                        tilt * std::numbers::pi / 180.0, radial);
        auto result = dockFragment(fragment.cloud, *fitted, start);
        ASSERT_TRUE(result.ok()) << result.error().message;
        const auto e = test::dockErrors(result->pose, truth, frame, centre);
        std::printf("[ measured ] tapering drum: theta %.4f deg, tilt %.4f deg, radial %.4f mm, rms %.3f mm\n",
                    e.thetaDeg, e.tiltDeg, e.radialMm, result->rms * 1e3);
        EXPECT_LT(e.thetaDeg, 0.01);
        EXPECT_LT(e.tiltDeg, 0.02);
        // With z held, the radius is the guides' cone at the fragment's height: their slope's error (about 1e-4,
        // DrumGuidesTest) over the ~0.3 m from the axis point adds a few hundredths of a millimetre (measured 0.08).
        EXPECT_LT(e.radialMm, 0.1);
        // The cone fixes only r + slope·z: z stays unobservable, kept where the start put it.
        ASSERT_EQ(result->unobservable.size(), 1u);
        EXPECT_EQ(result->unobservable[0], DockUnknown::Z);
        EXPECT_EQ(result->uncertainty.size(), 5u);
    }
}

TEST(DockRegistrationTest, LockedUnknownsDoNotMove)
{
    const DrumFrame frame(guides());
    const auto& fragment = test::dockFragment(5);
    const Eigen::Isometry3d truth = test::truePose(fragment, test::dockDrum());
    const Eigen::Vector3d centre = test::cloudCentre(fragment.cloud);
    const Eigen::Isometry3d start = test::perturbed(truth, frame, truth * centre, 0.02, 0.0, 0.004);
    DockOptions options;
    for (DockUnknown u : dockUnknownsFromName("theta")) options.locked[std::size_t(u)] = true;
    for (DockUnknown u : dockUnknownsFromName("tilt")) options.locked[std::size_t(u)] = true;
    auto result = dockFragment(fragment.cloud, guides(), start, options);
    ASSERT_TRUE(result.ok()) << result.error().message;
    // Rotation locked about the axis and in tilt: the rotation part is exactly the start's.
    EXPECT_TRUE(result->pose.linear().isApprox(start.linear(), 1e-12));
    EXPECT_EQ(result->snapRotation, 0.0);
    // r is free: the 4 mm radial offset is taken back.
    const auto e = test::dockErrors(result->pose, truth, frame, centre);
    EXPECT_LT(e.radialMm, 1.0); // 0.51: the flutes 1.15° off (θ locked) leave the profile a little wider or narrower
    EXPECT_EQ(result->uncertainty.size(), 1u); // r
    // θ locks the place round the drum: the centre moves along the surface by less than 0.05 mm (the radial move about
    // the inliers' centroid, not this centre); the sideways slide is locked with the turn.
    const Eigen::Vector3d before = frame.toFrame(start * centre), after = frame.toFrame(result->pose * centre);
    const double along = std::abs(std::atan2(after.y(), after.x()) - std::atan2(before.y(), before.x())) *
                         std::hypot(before.x(), before.y());
    std::printf("[ measured ] theta locked: %.4f mm along the surface, radial error %.3f mm\n", along * 1e3, e.radialMm);
    EXPECT_LT(along, 5e-5);
}

TEST(DockRegistrationTest, FluteShiftIsTheTurnAboutTheAxis)
{
    const DrumFrame frame(guides());
    const double pitchDeg = 360.0 / 48.0;
    const double degree = std::numbers::pi / 180.0;
    // A fragment started 2° round the axis from its place: docked, it turns 2° back.
    const auto& fragment = test::dockFragment(5);
    const Eigen::Isometry3d truth = test::truePose(fragment, test::dockDrum());
    const Eigen::Vector3d centre = truth * test::cloudCentre(fragment.cloud);
    auto turned = dockFragment(fragment.cloud, guides(), test::perturbed(truth, frame, centre, 2.0 * degree, 0.0, 0.0));
    ASSERT_TRUE(turned.ok()) << turned.error().message;
    EXPECT_NEAR(turned->fluteShift, -2.0 / pitchDeg, 0.003);

    // The whole drum against its own guides (its place is where it is): turned 1°, it turns 1° back; slid 1 mm
    // sideways, it turns by nothing (its centre's azimuth, on the axis, read 0.108 pitches).
    const auto& drum = test::dockDrum().cloud;
    const Eigen::Vector3d axisPoint = frame.origin, e1 = frame.rows.row(0).transpose();
    auto drumTurned = dockFragment(drum, guides(), test::perturbed(Eigen::Isometry3d::Identity(), frame,
                                                                   axisPoint + 0.3 * e1, 1.0 * degree, 0.0, 0.0));
    ASSERT_TRUE(drumTurned.ok()) << drumTurned.error().message;
    EXPECT_NEAR(drumTurned->fluteShift, -1.0 / pitchDeg, 0.003);
    const Eigen::Isometry3d slid(Eigen::Translation3d(0.001 * e1));
    auto drumSlid = dockFragment(drum, guides(), slid);
    ASSERT_TRUE(drumSlid.ok()) << drumSlid.error().message;
    EXPECT_LT(std::abs(drumSlid->fluteShift), 0.003) << drumSlid->fluteShift;
    const Eigen::Vector3d onSurface = axisPoint + guides().radius * e1;
    EXPECT_LT((drumSlid->pose * onSurface - onSurface).norm(), 2e-4) << frame.origin.transpose(); // slid back
}

TEST(DockRegistrationTest, NamesUnknownsAndLocks)
{
    EXPECT_STREQ(dockUnknownName(DockUnknown::TiltRoll), "tilt_roll");
    EXPECT_EQ(dockUnknownsFromName("tilt").size(), 2u);
    EXPECT_EQ(dockUnknownsFromName("theta"), (std::vector<DockUnknown>{DockUnknown::Theta, DockUnknown::Tangent}));
    EXPECT_EQ(dockUnknownsFromName("tangent"), std::vector<DockUnknown>{DockUnknown::Tangent});
    EXPECT_EQ(dockUnknownsFromName("z"), std::vector<DockUnknown>{DockUnknown::Z});
    EXPECT_TRUE(dockUnknownsFromName("yaw").empty());
}

TEST(DockRegistrationTest, RefusesAStartFarFromTheDrum)
{
    const auto& fragment = test::dockFragment(5);
    Eigen::Isometry3d far = test::truePose(fragment, test::dockDrum());
    far.translation() += Eigen::Vector3d(0.0, 0.0, 5.0); // 5 m off, along z of the file frame
    far = Eigen::Translation3d(2.0, 2.0, 0.0) * far;
    DockFailure failure;
    failure.kind = DockFailure::Kind::NotConverged; // overwritten
    auto result = dockFragment(fragment.cloud, guides(), far, {}, nullptr, &failure);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(result.error().message.find("too far from the drum"), std::string::npos) << result.error().message;
    // The same as values, for the workbench's words: no point within the searched reach, which the message names.
    EXPECT_EQ(failure.kind, DockFailure::Kind::TooFar);
    EXPECT_EQ(failure.points, 0u);
    EXPECT_GT(failure.reachM, 0.0);
    char reach[32];
    std::snprintf(reach, sizeof reach, "within %.1f mm", failure.reachM * 1e3);
    EXPECT_NE(result.error().message.find(reach), std::string::npos) << result.error().message << " / " << reach;
    // A dock that succeeds says no failure.
    const auto docked = dockFragment(fragment.cloud, guides(), Eigen::Isometry3d(test::truePose(fragment, test::dockDrum())),
                                     {}, nullptr, &failure);
    ASSERT_TRUE(docked.ok()) << docked.error().message;
    EXPECT_EQ(failure.kind, DockFailure::Kind::None);
}

TEST(DockRegistrationTest, RefusesAFragmentWithoutFlutes)
{
    auto o = test::allRound(0.004, 9, 0); // a plain drum's fragment
    const auto& plain = test::generatedScan("dock-plain-fragment", synth::SyntheticKind::Fragment, o);
    DockFailure failure;
    auto result = dockFragment(plain.cloud, guides(), Eigen::Isometry3d(test::truePose(plain, test::dockDrum())), {},
                               nullptr, &failure);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().message.find("no readable flutes"), std::string::npos) << result.error().message;
    EXPECT_EQ(failure.kind, DockFailure::Kind::NoFlutes);
    EXPECT_LT(failure.strength, failure.needed);
    char signal[64];
    std::snprintf(signal, sizeof signal, "signal is %.2f (at least %.2f", failure.strength, failure.needed);
    EXPECT_NE(result.error().message.find(signal), std::string::npos) << result.error().message;
}

TEST(DockRegistrationTest, RefusesGuidesWithoutAProfile)
{
    DrumGuides g = guides();
    g.profile.clear();
    auto result = dockFragment(test::dockFragment(5).cloud, g, Eigen::Isometry3d::Identity());
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().message.find("no flute profile"), std::string::npos) << result.error().message;
}

} // namespace
} // namespace stylos::core::dock
