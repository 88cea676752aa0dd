// drumFramePose / placeInDrumFrame: exact values for poses built by hand about a tilted, offset axis; round trips;
// one value changed keeps the others; θ turns rigidly about the axis; the tilts turn about the centre.
#include "stylos/core/dock/DrumFramePose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace stylos::core::dock {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

DrumFrame zFrame()
{
    return DrumFrame(unroll::Axis{Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d::UnitZ()});
}

DrumFrame tiltedFrame()
{
    return DrumFrame(unroll::Axis{Eigen::Vector3d(1.5, -2.0, 0.25), Eigen::Vector3d(0.2, 0.1, 1.0).normalized()});
}

TEST(DrumFramePoseTest, ReadsAFragmentPlacedByHandAboutTheZAxis)
{
    const DrumFrame frame = zFrame();
    ASSERT_NEAR(frame.rows.row(2).dot(Eigen::Vector3d::UnitZ()), 1.0, 1e-15);
    // The fragment's centre (its frame) at the origin; placed at azimuth 30° of e1, 0.5 m from the axis, 0.2 m up,
    // its orientation that of the frame turning with it (no tilt, no spin).
    const double theta = 30 * kDeg;
    const Eigen::Vector3d e1 = frame.rows.row(0).transpose(), e2 = frame.rows.row(1).transpose();
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = frame.rows.transpose() * Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    pose.translation() = 0.5 * (std::cos(theta) * e1 + std::sin(theta) * e2) + Eigen::Vector3d(0, 0, 0.2);
    const DrumFramePose v = drumFramePose(frame, pose, Eigen::Vector3d::Zero());
    EXPECT_NEAR(v.theta, theta, 1e-12);
    EXPECT_NEAR(v.r, 0.5, 1e-12);
    EXPECT_NEAR(v.z, 0.2, 1e-12);
    EXPECT_NEAR(v.tiltLean, 0.0, 1e-12);
    EXPECT_NEAR(v.tiltRoll, 0.0, 1e-12);
    EXPECT_NEAR(v.spin, 0.0, 1e-12);
    // A fragment in the drum's own frame (identity pose) whose centre lies at azimuth θ: spin −θ, no tilt.
    const Eigen::Vector3d centre = 0.5 * (std::cos(theta) * e1 + std::sin(theta) * e2);
    const DrumFramePose own = drumFramePose(frame, Eigen::Isometry3d::Identity(), centre);
    EXPECT_NEAR(own.theta, theta, 1e-12);
    EXPECT_NEAR(own.spin, -theta, 1e-12);
    EXPECT_NEAR(own.tiltLean, 0.0, 1e-12);
    EXPECT_NEAR(own.tiltRoll, 0.0, 1e-12);
}

TEST(DrumFramePoseTest, RoundTripsAboutATiltedOffsetAxis)
{
    const DrumFrame frame = tiltedFrame();
    const Eigen::Vector3d centre(0.1, -0.3, 0.7);
    DrumFramePose v;
    v.theta = -2.5;
    v.z = 0.731;
    v.r = 0.545;
    v.tiltLean = 3 * kDeg;
    v.tiltRoll = -7 * kDeg;
    v.spin = 1.1;
    const Eigen::Isometry3d pose = placeInDrumFrame(frame, v, centre);
    EXPECT_NEAR((pose.linear().transpose() * pose.linear() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-14);
    const DrumFramePose back = drumFramePose(frame, pose, centre);
    EXPECT_NEAR(back.theta, v.theta, 1e-12);
    EXPECT_NEAR(back.z, v.z, 1e-12);
    EXPECT_NEAR(back.r, v.r, 1e-12);
    EXPECT_NEAR(back.tiltLean, v.tiltLean, 1e-12);
    EXPECT_NEAR(back.tiltRoll, v.tiltRoll, 1e-12);
    EXPECT_NEAR(back.spin, v.spin, 1e-12);
    // And the other way: a pose read and placed again is the same pose.
    const Eigen::Isometry3d again = placeInDrumFrame(frame, back, centre);
    EXPECT_NEAR((again.matrix() - pose.matrix()).norm(), 0.0, 1e-12);
}

TEST(DrumFramePoseTest, ThetaTurnsRigidlyAboutTheAxisAndKeepsTheRest)
{
    const DrumFrame frame = tiltedFrame();
    const Eigen::Vector3d centre(0.1, -0.3, 0.7);
    DrumFramePose v{.theta = 0.4, .z = 0.3, .r = 0.6, .tiltLean = 2 * kDeg, .tiltRoll = 1 * kDeg, .spin = -0.2};
    const Eigen::Isometry3d before = placeInDrumFrame(frame, v, centre);
    v.set(DockUnknown::Theta, 0.4 + 10 * kDeg);
    const Eigen::Isometry3d after = placeInDrumFrame(frame, v, centre);
    // after = (rotation of 10° about the drum axis line) · before.
    const Eigen::Vector3d d = frame.rows.row(2).transpose();
    const Eigen::Isometry3d turn = Eigen::Translation3d(frame.origin) * Eigen::AngleAxisd(10 * kDeg, d) *
                                   Eigen::Translation3d(-frame.origin);
    EXPECT_NEAR(((turn * before).matrix() - after.matrix()).norm(), 0.0, 1e-12);
    const DrumFramePose read = drumFramePose(frame, after, centre);
    EXPECT_NEAR(read.z, 0.3, 1e-12);
    EXPECT_NEAR(read.r, 0.6, 1e-12);
    EXPECT_NEAR(read.tiltLean, 2 * kDeg, 1e-12);
    EXPECT_NEAR(read.tiltRoll, 1 * kDeg, 1e-12);
    EXPECT_NEAR(read.spin, -0.2, 1e-12);
}

TEST(DrumFramePoseTest, LeanTurnsAboutTheTangentThroughTheCentre)
{
    const DrumFrame frame = zFrame();
    const Eigen::Vector3d centre(0.0, 0.0, 0.0);
    DrumFramePose v{.theta = 0.0, .z = 0.1, .r = 0.5};
    const Eigen::Isometry3d before = placeInDrumFrame(frame, v, centre);
    v.set(DockUnknown::TiltLean, 5 * kDeg);
    const Eigen::Isometry3d after = placeInDrumFrame(frame, v, centre);
    EXPECT_NEAR((after * centre - before * centre).norm(), 0.0, 1e-15); // the centre stays
    const Eigen::Vector3d ut = frame.rows.row(1).transpose(); // at θ = 0 the tangent is e2
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(5 * kDeg, ut).toRotationMatrix();
    EXPECT_NEAR((turn * before.linear() - after.linear()).norm(), 0.0, 1e-14);
    EXPECT_DOUBLE_EQ(v.value(DockUnknown::Tangent), 0.0);
}

TEST(DrumFramePoseTest, ReadsARollOfNinetyDegreesWithoutNaN)
{
    const DrumFrame frame = zFrame();
    DrumFramePose v{.theta = 0.3, .z = 0.0, .r = 0.5, .tiltLean = 0.2, .tiltRoll = std::numbers::pi / 2};
    const DrumFramePose back = drumFramePose(frame, placeInDrumFrame(frame, v, Eigen::Vector3d::Zero()), Eigen::Vector3d::Zero());
    EXPECT_NEAR(back.tiltRoll, std::numbers::pi / 2, 1e-7);
    EXPECT_NEAR(back.tiltLean, 0.2, 1e-7);
    EXPECT_DOUBLE_EQ(back.spin, 0.0);
}

} // namespace
} // namespace stylos::core::dock
