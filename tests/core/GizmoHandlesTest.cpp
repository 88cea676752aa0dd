// core::view gizmo handles and drags: the handles in the World, Fragment and Drum frames, what each does
// to a pose, picking on screen, and whole drags (press, moves with Shift and Ctrl, snapping) on an
// orthographic camera at 1000 pixels per metre, so that a pixel is a millimetre.
#include "stylos/core/view/GizmoDrag.h"
#include "stylos/core/view/GizmoHandles.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace stylos::core::view;

namespace {

constexpr double Pi = std::numbers::pi;
constexpr double FlutePitch = 2 * Pi / 48;

Camera orthoCamera(StandardView view, const Eigen::Vector3d& target)
{
    Camera camera;
    camera.setStandardView(view);
    camera.setOrthographic(true);
    camera.setTarget(target);
    camera.setDistance(0.24 / std::tan(camera.fieldOfView() / 2));
    return camera;
}

Eigen::Matrix4d translation(const Eigen::Vector3d& t)
{
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topRightCorner<3, 1>() = t;
    return m;
}

Eigen::Matrix4d rotationAbout(const Eigen::Vector3d& point, const Eigen::Vector3d& axis, double angle)
{
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
    m.topLeftCorner<3, 3>() = r;
    m.topRightCorner<3, 1>() = point - r * point;
    return m;
}

/** A fragment 0.45 m from the drum axis (+Z through the origin), at azimuth 0, 0.3 m up, turned 10° about Z. */
GizmoTarget dockedTarget()
{
    GizmoTarget t;
    t.pose = translation({0.45, 0, 0.3}) * rotationAbout({0, 0, 0}, {0, 0, 1}, 10 * Degree);
    t.localCentre = Eigen::Vector3d::Zero();
    t.drum = DrumAxis{{0, 0, 0}, {0, 0, 1}, FlutePitch};
    return t;
}

Eigen::Vector2d pixelOf(const Camera& camera, const Eigen::Vector3d& p) { return camera.project(p)->head<2>(); }

std::size_t indexOf(const std::vector<GizmoHandle>& handles, HandleRole role)
{
    for (std::size_t i = 0; i < handles.size(); ++i)
        if (handles[i].role == role) return i;
    ADD_FAILURE() << "no such handle";
    return 0;
}

} // namespace

TEST(GizmoHandles, WorldAndFragmentFrames)
{
    GizmoTarget t = dockedTarget();
    t.localCentre = {0.1, 0, 0};
    const Eigen::Vector3d centre = t.centre();
    EXPECT_TRUE(centre.isApprox(Eigen::Vector3d(0.45 + 0.1 * std::cos(10 * Degree), 0.1 * std::sin(10 * Degree), 0.3)));

    const auto world = gizmoHandles(t, GizmoFrame::World, false, 2e-3);
    ASSERT_EQ(world.size(), 6u);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(world[std::size_t(i)].role, HandleRole(int(HandleRole::MoveX) + i));
        EXPECT_EQ(world[std::size_t(i)].direction, Eigen::Vector3d::Unit(i));
        EXPECT_EQ(world[std::size_t(i)].origin, centre);
        EXPECT_DOUBLE_EQ(world[std::size_t(i)].size, 90 * 2e-3);
        EXPECT_EQ(world[std::size_t(i + 3)].role, HandleRole(int(HandleRole::TurnX) + i));
        EXPECT_DOUBLE_EQ(world[std::size_t(i + 3)].size, 70 * 2e-3);
        EXPECT_EQ(world[std::size_t(i + 3)].pitch, 0.0);
    }
    const auto local = gizmoHandles(t, GizmoFrame::Fragment, false, 2e-3);
    EXPECT_TRUE(local[0].direction.isApprox(Eigen::Vector3d(std::cos(10 * Degree), std::sin(10 * Degree), 0), 1e-15));
    EXPECT_TRUE(local[1].direction.isApprox(Eigen::Vector3d(-std::sin(10 * Degree), std::cos(10 * Degree), 0), 1e-15));
    // No drum axis: the Drum frame is the World frame.
    t.drum.reset();
    EXPECT_EQ(gizmoHandles(t, GizmoFrame::Drum, true, 2e-3).size(), 6u);
}

TEST(GizmoHandles, DrumFrame)
{
    const GizmoTarget t = dockedTarget();
    const auto handles = gizmoHandles(t, GizmoFrame::Drum, false, 1e-3);
    ASSERT_EQ(handles.size(), 3u);
    const GizmoHandle& z = handles[indexOf(handles, HandleRole::DrumZ)];
    const GizmoHandle& r = handles[indexOf(handles, HandleRole::DrumRadial)];
    const GizmoHandle& theta = handles[indexOf(handles, HandleRole::DrumTheta)];
    EXPECT_EQ(z.direction, Eigen::Vector3d::UnitZ());
    EXPECT_EQ(z.origin, Eigen::Vector3d(0.45, 0, 0.3));
    EXPECT_EQ(r.direction, Eigen::Vector3d::UnitX());
    EXPECT_EQ(theta.origin, Eigen::Vector3d(0, 0, 0.3));
    EXPECT_DOUBLE_EQ(theta.size, 0.45);
    EXPECT_DOUBLE_EQ(theta.pitch, FlutePitch);

    const auto tilted = gizmoHandles(t, GizmoFrame::Drum, true, 1e-3);
    ASSERT_EQ(tilted.size(), 5u);
    EXPECT_EQ(tilted[indexOf(tilted, HandleRole::TiltRadial)].direction, Eigen::Vector3d::UnitX());
    EXPECT_EQ(tilted[indexOf(tilted, HandleRole::TiltTangential)].direction, Eigen::Vector3d::UnitY());
    EXPECT_EQ(tilted[indexOf(tilted, HandleRole::TiltTangential)].origin, Eigen::Vector3d(0.45, 0, 0.3));

    // θ by a quarter turn carries the centre to azimuth 90° and turns the fragment about the drum axis.
    const Eigen::Matrix4d turned = applyHandle(theta, t.pose, Pi / 2);
    EXPECT_TRUE((turned.topRightCorner<3, 1>().isApprox(Eigen::Vector3d(0, 0.45, 0.3), 1e-15)));
    EXPECT_TRUE(turned.isApprox(rotationAbout({0, 0, 0}, {0, 0, 1}, Pi / 2) * t.pose, 1e-15));
    // z and r translate.
    EXPECT_TRUE(applyHandle(z, t.pose, 0.01).isApprox(translation({0, 0, 0.01}) * t.pose, 1e-15));
    EXPECT_TRUE(applyHandle(r, t.pose, -0.02).isApprox(translation({-0.02, 0, 0}) * t.pose, 1e-15));
    // A tilt turns about a line through the centre: the centre stays.
    const Eigen::Matrix4d tilt = applyHandle(tilted[indexOf(tilted, HandleRole::TiltTangential)], t.pose, 5 * Degree);
    EXPECT_TRUE((tilt.topRightCorner<3, 1>().isApprox(Eigen::Vector3d(0.45, 0, 0.3), 1e-15)));
}

TEST(GizmoHandles, PickOnScreen)
{
    const GizmoTarget t = dockedTarget();
    const Camera camera = orthoCamera(StandardView::Top, t.centre());
    const auto handles = gizmoHandles(t, GizmoFrame::World, false, 1e-3);
    // Top view centred on the fragment: X to the right, Y up; arrows 90 px, rings 70 px.
    const Eigen::Vector2d c(320, 240);
    EXPECT_EQ(pickHandle(handles, camera, c + Eigen::Vector2d(85, 3), 7), indexOf(handles, HandleRole::MoveX));
    EXPECT_EQ(pickHandle(handles, camera, c + Eigen::Vector2d(-2, -85), 7), indexOf(handles, HandleRole::MoveY));
    EXPECT_EQ(pickHandle(handles, camera, c + Eigen::Vector2d(49.5, 49.5), 7), indexOf(handles, HandleRole::TurnZ));
    EXPECT_FALSE(pickHandle(handles, camera, c + Eigen::Vector2d(150, 150), 7));
    EXPECT_FALSE(pickHandle(handles, camera, c + Eigen::Vector2d(85, 9), 7));
}

TEST(GizmoDrag, ArrowsSnapByTheMillimetre)
{
    const GizmoTarget t = dockedTarget();
    const Camera camera = orthoCamera(StandardView::Top, t.centre());
    const auto handles = gizmoHandles(t, GizmoFrame::World, false, 1e-3);
    const Eigen::Vector2d press(320 + 60, 240);
    auto drag = GizmoDrag::begin(handles[indexOf(handles, HandleRole::MoveX)], camera, press, t.pose);
    ASSERT_TRUE(drag);
    // 37.4 px = 37.4 mm → 37 mm.
    auto pose = drag->update(press + Eigen::Vector2d(37.4, 12), {});
    ASSERT_TRUE(pose);
    EXPECT_NEAR(drag->value(), 0.037, 1e-12);
    EXPECT_TRUE(pose->isApprox(translation({0.037, 0, 0}) * t.pose, 1e-12));
    // Shift from here on: a tenth of the next 20 px, by 0.1 mm → 37.4 + 2 = 39.4 mm.
    pose = drag->update(press + Eigen::Vector2d(57.4, 0), {.fine = true});
    EXPECT_NEAR(drag->value(), 0.0394, 1e-12);
    EXPECT_NEAR((*pose)(0, 3), 0.45 + 0.0394, 1e-12);
    EXPECT_EQ(drag->startPose(), t.pose);
}

TEST(GizmoDrag, ThetaSnapsByTheFlutePitchSeenAlongTheAxis)
{
    const GizmoTarget t = dockedTarget();
    const Camera camera = orthoCamera(StandardView::Top, {0, 0, 0.3});
    const auto handles = gizmoHandles(t, GizmoFrame::Drum, false, 1e-3);
    const GizmoHandle& theta = handles[indexOf(handles, HandleRole::DrumTheta)];
    const auto ringPoint = [](double a) { return Eigen::Vector3d(0.45 * std::cos(a), 0.45 * std::sin(a), 0.3); };
    auto drag = GizmoDrag::begin(theta, camera, pixelOf(camera, ringPoint(0)), t.pose);
    ASSERT_TRUE(drag);
    EXPECT_FALSE(drag->followsTangent());
    // 20° → 22.5° (three flutes); Ctrl: 20°; Ctrl+Shift from there: a tenth of the next 10°, 21°.
    auto pose = drag->update(pixelOf(camera, ringPoint(20 * Degree)), {});
    EXPECT_NEAR(drag->value(), 22.5 * Degree, 1e-12);
    EXPECT_TRUE(pose->isApprox(rotationAbout({0, 0, 0}, {0, 0, 1}, 22.5 * Degree) * t.pose, 1e-12));
    drag->update(pixelOf(camera, ringPoint(20 * Degree)), {.precise = true});
    EXPECT_NEAR(drag->value(), 20 * Degree, 1e-12);
    drag->update(pixelOf(camera, ringPoint(30 * Degree)), {.fine = true, .precise = true});
    EXPECT_NEAR(drag->value(), 21 * Degree, 1e-12);
    // Past half a turn, the angle keeps growing (unwrapped): 20 + 1 + 170 + 20 = 211° → 210° by flutes.
    drag->update(pixelOf(camera, ringPoint(200 * Degree)), {});
    drag->update(pixelOf(camera, ringPoint(220 * Degree)), {});
    EXPECT_NEAR(drag->value(), 210 * Degree, 1e-12);
}

TEST(GizmoDrag, ThetaSeenEdgeOnFollowsTheTangent)
{
    // The fragment faces the viewer (azimuth −90°), the camera looks from the front: the θ ring is a line.
    GizmoTarget t = dockedTarget();
    t.pose = translation({0, -0.45, 0.3});
    const Camera camera = orthoCamera(StandardView::Front, {0, -0.45, 0.3});
    const auto handles = gizmoHandles(t, GizmoFrame::Drum, false, 1e-3);
    const GizmoHandle& theta = handles[indexOf(handles, HandleRole::DrumTheta)];
    const Eigen::Vector2d press(320, 240);
    auto drag = GizmoDrag::begin(theta, camera, press, t.pose);
    ASSERT_TRUE(drag);
    EXPECT_TRUE(drag->followsTangent());
    // The tangent there is +X at 0.45 m a radian = 450 px: 29 px is 3.69° (under half a flute), 30 px 3.82°.
    drag->update(press + Eigen::Vector2d(29, 0), {});
    EXPECT_EQ(drag->value(), 0.0);
    drag->update(press + Eigen::Vector2d(30, 5), {});
    EXPECT_NEAR(drag->value(), 7.5 * Degree, 1e-12);
    drag->update(press + Eigen::Vector2d(-10 * Degree * 450, 0), {.precise = true}); // −10°, by degrees
    EXPECT_NEAR(drag->value(), -10 * Degree, 1e-12);
    // The arrow along the axis, seen from the front, moves by the millimetre.
    auto lift = GizmoDrag::begin(handles[indexOf(handles, HandleRole::DrumZ)], camera, press + Eigen::Vector2d(0, -50), t.pose);
    ASSERT_TRUE(lift);
    auto pose = lift->update(press + Eigen::Vector2d(3, -62.6), {});
    EXPECT_NEAR((*pose)(2, 3), 0.3 + 0.013, 1e-12);
}
