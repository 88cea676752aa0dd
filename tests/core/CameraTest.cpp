// core::view::Camera: exact view and projection matrices for the standard views, orbit/pan/dolly, fitting a
// box, the pixel ray round trip and the perspective/orthographic switch. Pure maths: no window, no GL.
#include "stylos/core/view/Camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

using stylos::core::view::Camera;
using stylos::core::view::StandardView;

namespace {

bool near(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double tolerance = 1e-12)
{
    return a.rows() == b.rows() && a.cols() == b.cols() && (a - b).cwiseAbs().maxCoeff() <= tolerance;
}

std::string show(const Eigen::MatrixXd& m)
{
    std::ostringstream s;
    s << m;
    return s.str();
}

/** The view matrix expected for a camera whose right/up/back axes are the given scene vectors. */
Eigen::Matrix4d expectedView(const Eigen::Vector3d& right, const Eigen::Vector3d& up, const Eigen::Vector3d& back,
                             const Eigen::Vector3d& target, double distance)
{
    const Eigen::Vector3d eye = target + back * distance;
    Eigen::Matrix4d v = Eigen::Matrix4d::Identity();
    v.row(0).head<3>() = right;
    v.row(1).head<3>() = up;
    v.row(2).head<3>() = back;
    v(0, 3) = -right.dot(eye);
    v(1, 3) = -up.dot(eye);
    v(2, 3) = -back.dot(eye);
    return v;
}

struct ViewAxes {
    const char* name;
    StandardView view;
    Eigen::Vector3d right, up, back;
};

std::vector<ViewAxes> standardAxes()
{
    const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d isoBack = Eigen::Vector3d(1, -1, 1) / std::sqrt(3.0);
    const Eigen::Vector3d isoRight = Eigen::Vector3d(1, 1, 0) / std::sqrt(2.0);
    return {{"front", StandardView::Front, x, z, -y},   {"back", StandardView::Back, -x, z, y},
            {"left", StandardView::Left, -y, z, -x},    {"right", StandardView::Right, y, z, x},
            {"top", StandardView::Top, x, y, z},        {"bottom", StandardView::Bottom, -x, y, -z},
            {"iso", StandardView::Iso, isoRight, isoBack.cross(isoRight), isoBack}};
}

} // namespace

TEST(CameraTest, StandardViewMatrices)
{
    for (const ViewAxes& axes : standardAxes()) {
        SCOPED_TRACE(axes.name);
        Camera camera;
        const Eigen::Vector3d target(1.5, -2, 100);
        camera.setTarget(target);
        camera.setDistance(4);
        camera.setStandardView(axes.view);
        const Eigen::Matrix4d expected = expectedView(axes.right, axes.up, axes.back, target, 4);
        EXPECT_TRUE(near(camera.viewMatrix(), expected)) << show(camera.viewMatrix());
        EXPECT_TRUE(near(camera.eye(), target + 4 * axes.back));
        EXPECT_TRUE(near(camera.forward(), -axes.back));
        // The target lies on the view axis, 4 m ahead.
        const Eigen::Vector4d t = camera.viewMatrix() * target.homogeneous();
        EXPECT_TRUE(near(t, Eigen::Vector4d(0, 0, -4, 1)));
    }
}

TEST(CameraTest, FrontViewExactly)
{
    Camera camera;
    camera.setTarget({1, 2, 3});
    camera.setDistance(4);
    camera.setStandardView(StandardView::Front);
    Eigen::Matrix4d expected;
    expected << 1, 0, 0, -1, //
        0, 0, 1, -3,         //
        0, -1, 0, -2,        //
        0, 0, 0, 1;
    EXPECT_TRUE(near(camera.viewMatrix(), expected)) << show(camera.viewMatrix());
}

TEST(CameraTest, ProjectionMatrices)
{
    Camera camera;
    camera.setViewport(200, 100);
    camera.setFieldOfView(M_PI / 2);
    camera.setDistance(2);
    // No scene bounds: near = 0.01 d, far = 100 d.
    const double n = 0.02, f = 200;
    Eigen::Matrix4d perspective;
    perspective << 0.5, 0, 0, 0, //
        0, 1, 0, 0,              //
        0, 0, (f + n) / (n - f), 2 * f * n / (n - f), //
        0, 0, -1, 0;
    EXPECT_TRUE(near(camera.projectionMatrix(), perspective)) << show(camera.projectionMatrix());
    EXPECT_EQ(camera.pixelsPerRadian(), 100 / (M_PI / 2));

    camera.setOrthographic(true);
    EXPECT_NEAR(camera.viewHeight(), 4.0, 1e-12); // 2 d tan(45°)
    Eigen::Matrix4d orthographic;
    orthographic << 0.25, 0, 0, 0, //
        0, 0.5, 0, 0,              //
        0, 0, -2 / (f - n), -(f + n) / (f - n), //
        0, 0, 0, 1;
    EXPECT_TRUE(near(camera.projectionMatrix(), orthographic)) << show(camera.projectionMatrix());
    EXPECT_NEAR(camera.pixelsPerMetre(), 25.0, 1e-12);
}

TEST(CameraTest, OrbitReachesStandardViews)
{
    Camera camera;
    camera.setTarget({0.5, 0.25, -1});
    camera.setStandardView(StandardView::Front);
    camera.orbit(M_PI / 2, 0); // the eye goes counter-clockwise from −Y to +X
    Camera right = camera;
    right.setStandardView(StandardView::Right);
    EXPECT_TRUE(near(camera.viewMatrix(), right.viewMatrix(), 1e-12)) << show(camera.viewMatrix());

    camera.setStandardView(StandardView::Front);
    camera.orbit(0, M_PI / 2); // the eye rises over the target
    Camera top = camera;
    top.setStandardView(StandardView::Top);
    EXPECT_TRUE(near(camera.viewMatrix(), top.viewMatrix(), 1e-12)) << show(camera.viewMatrix());
    EXPECT_TRUE(near(camera.target(), Eigen::Vector3d(0.5, 0.25, -1)));
}

TEST(CameraTest, PanFollowsTheDrag)
{
    for (bool ortho : {false, true}) {
        SCOPED_TRACE(ortho ? "orthographic" : "perspective");
        Camera camera;
        camera.setViewport(640, 400);
        camera.setOrthographic(ortho);
        camera.setStandardView(StandardView::Iso);
        camera.setTarget({3, 4, 5});
        const Eigen::Vector3d before = camera.target();
        camera.pan(10, -5);
        const auto p = camera.project(before);
        ASSERT_TRUE(p);
        EXPECT_NEAR(p->x(), 330, 1e-9);
        EXPECT_NEAR(p->y(), 195, 1e-9);
    }
}

TEST(CameraTest, Dolly)
{
    Camera camera;
    camera.setDistance(3);
    camera.dolly(0.5);
    EXPECT_EQ(camera.distance(), 1.5);
    camera.dolly(-1); // ignored
    EXPECT_EQ(camera.distance(), 1.5);
    camera.dolly(1e-12);
    EXPECT_EQ(camera.distance(), 1e-6); // clamped
}

TEST(CameraTest, FitPutsTheBoxInView)
{
    const Eigen::AlignedBox3d box(Eigen::Vector3d(-1, 0, 5), Eigen::Vector3d(2, 1, 9));
    for (bool orthographic : {false, true})
        for (int view = 0; view <= int(StandardView::Iso); ++view)
            for (auto [width, height] : {std::pair{800, 600}, std::pair{300, 900}}) {
                SCOPED_TRACE(::testing::Message() << (orthographic ? "ortho" : "persp") << " view " << view << " "
                                                  << width << "x" << height);
                Camera camera;
                camera.setViewport(width, height);
                camera.setOrthographic(orthographic);
                camera.setStandardView(StandardView(view));
                camera.setSceneBounds(box);
                camera.setTarget({50, 50, 50});
                camera.fit(box);
                // Orthographic: centred on the box. Perspective: the target at the depth of the box centre,
                // moved across so that the picture is centred.
                if (orthographic) EXPECT_TRUE(near(camera.target(), box.center()));
                EXPECT_NEAR((camera.target() - box.center()).dot(camera.forward()), 0.0, 1e-9);
                double maxX = 0, maxY = 0;
                for (int corner = 0; corner < 8; ++corner) {
                    const auto p = camera.project(box.corner(Eigen::AlignedBox3d::CornerType(corner)));
                    ASSERT_TRUE(p);
                    EXPECT_TRUE(p->x() >= 0 && p->x() <= width && p->y() >= 0 && p->y() <= height)
                        << "corner " << corner << " at " << p->x() << ", " << p->y();
                    EXPECT_TRUE(p->z() > -1 && p->z() < 1);
                    maxX = std::max(maxX, std::abs(p->x() - width / 2.0) / (width / 2.0));
                    maxY = std::max(maxY, std::abs(p->y() - height / 2.0) / (height / 2.0));
                }
                EXPECT_GT(std::max(maxX, maxY), 0.85) << "the box fills most of the view";
            }
}

TEST(CameraTest, FitDistanceExactly)
{
    // A unit cube seen from the front, 45° vertical field, 800 × 600: the nearest face is 0.5 m in front of
    // the centre and its top edge sets the distance, 0.5 + 0.5 / tan(22.5°) with the 5 % margin in the angle
    // (the face spans 1 / 1.05 of the view height).
    Camera camera;
    camera.setViewport(800, 600);
    camera.setStandardView(StandardView::Front);
    camera.fit(Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1)));
    EXPECT_NEAR(camera.distance(), 0.5 + 1.05 * 0.5 / std::tan(M_PI / 8), 1e-12);
    EXPECT_TRUE(near(camera.target(), Eigen::Vector3d(0.5, 0.5, 0.5)));
    // Orthographic: half the view height is the larger of the half height and half width / aspect.
    camera.setOrthographic(true);
    camera.fit(Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, 1, 1)));
    EXPECT_NEAR(camera.viewHeight(), 2 * 1.05 * 2 / (800.0 / 600.0), 1e-12);
}

TEST(CameraTest, FitPointsCentresTheirPicture)
{
    // Points spanning x ∈ [−1, 3], z ∈ [0, 1], all at y = 5, seen from the front (x right, z up) in 800 × 600
    // with a 45° vertical field: one depth, so the width sets the distance, 2 / tanX, times the 5 % margin,
    // and the target is their centre.
    Camera camera;
    camera.setViewport(800, 600);
    camera.setStandardView(StandardView::Front);
    camera.fit(std::vector<Eigen::Vector3d>{{-1, 5, 0}, {3, 5, 1}, {0, 5, 0.5}});
    const double tanY = std::tan(M_PI / 8), tanX = tanY * 800.0 / 600.0;
    EXPECT_NEAR(camera.distance(), 1.05 * 2 / tanX, 1e-12);
    EXPECT_TRUE(near(camera.target(), Eigen::Vector3d(1, 5, 0.5)));
    // A point in front of the others pulls the eye back and across: the picture stays centred, the near
    // point and the far edge at the same distance from the middle.
    camera.fit(std::vector<Eigen::Vector3d>{{-1, 5, 0}, {3, 5, 0}, {3, 3, 0}});
    const auto left = camera.project({-1, 5, 0}), right = camera.project({3, 3, 0});
    ASSERT_TRUE(left && right);
    EXPECT_NEAR(400.0 - left->x(), right->x() - 400.0, 1e-6);
    EXPECT_NEAR((right->x() - 400.0) / 400.0, 1 / 1.05 + 0.0, 0.05);
    camera.fit(std::vector<Eigen::Vector3d>{}); // ignored
    EXPECT_NEAR((right->x() - 400.0) / 400.0, (camera.project({3, 3, 0})->x() - 400.0) / 400.0, 1e-12);
}

TEST(CameraTest, PixelRayRoundTrip)
{
    for (bool orthographic : {false, true}) {
        SCOPED_TRACE(orthographic ? "orthographic" : "perspective");
        Camera camera;
        camera.setViewport(1280, 800);
        camera.setOrthographic(orthographic);
        camera.setTarget({1000.25, -2000.5, 12}); // a museum frame: large coordinates
        camera.setDistance(3);
        camera.setStandardView(StandardView::Iso);
        camera.orbit(0.3, -0.2);
        camera.setSceneBounds(Eigen::AlignedBox3d(camera.target() - Eigen::Vector3d::Constant(1),
                                                  camera.target() + Eigen::Vector3d::Constant(1)));
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-0.9, 0.9);
        for (int i = 0; i < 100; ++i) {
            const Eigen::Vector3d point = camera.target() + Eigen::Vector3d(u(rng), u(rng), u(rng));
            const auto pixel = camera.project(point);
            ASSERT_TRUE(pixel);
            const auto ray = camera.rayAt(pixel->x(), pixel->y());
            EXPECT_NEAR(ray.direction.norm(), 1, 1e-12);
            const Eigen::Vector3d toPoint = point - ray.origin;
            const double along = toPoint.dot(ray.direction);
            EXPECT_GT(along, 0);
            EXPECT_LT((toPoint - along * ray.direction).norm(), 1e-9);
        }
        // The centre pixel looks straight at the target.
        const auto centre = camera.rayAt(640, 400);
        EXPECT_TRUE(near(centre.direction, camera.forward(), 1e-12));
        const Eigen::Vector3d toTarget = camera.target() - centre.origin;
        EXPECT_LT((toTarget - toTarget.dot(centre.direction) * centre.direction).norm(), 1e-9);
        if (!orthographic) {
            EXPECT_TRUE(near(centre.origin, camera.eye(), 1e-12));
        }
    }
}

TEST(CameraTest, OrthographicSwitchKeepsTheTargetScale)
{
    Camera camera;
    camera.setViewport(800, 600);
    camera.setStandardView(StandardView::Iso);
    camera.setTarget({0.1, 0.2, 0.3});
    camera.setDistance(2.5);
    const Eigen::Vector3d offset = camera.target() + 0.1 * camera.right() - 0.05 * camera.up();
    const Eigen::Matrix4d view = camera.viewMatrix();
    const auto inPerspective = camera.project(offset);
    camera.setOrthographic(true);
    EXPECT_TRUE(camera.isOrthographic());
    EXPECT_TRUE(near(camera.viewMatrix(), view)); // only the projection changes
    const auto inOrthographic = camera.project(offset);
    ASSERT_TRUE(inPerspective && inOrthographic);
    EXPECT_LT((inPerspective->head<2>() - inOrthographic->head<2>()).norm(), 1e-9);
    camera.setOrthographic(false);
    EXPECT_FALSE(camera.isOrthographic());
    EXPECT_LT((camera.project(offset)->head<2>() - inPerspective->head<2>()).norm(), 1e-12);
}

TEST(CameraTest, ClipPlanesHoldTheScene)
{
    Camera camera;
    const Eigen::AlignedBox3d box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 3));
    camera.setSceneBounds(box);
    camera.fit(box);
    const double radius = 0.5 * box.diagonal().norm();
    EXPECT_GT(camera.nearPlane(), 0);
    EXPECT_LE(camera.nearPlane(), camera.distance() - radius);
    EXPECT_GE(camera.farPlane(), camera.distance() + radius);
    // Exactly: the bounding sphere's radius with a 5 % margin on either side of the target's depth.
    EXPECT_NEAR(camera.nearPlane(), camera.distance() - 1.05 * radius, 1e-12);
    EXPECT_NEAR(camera.farPlane(), camera.distance() + 1.05 * radius, 1e-12);
    // Inside the scene the perspective near plane stays positive; orthographic may go behind the eye.
    camera.setDistance(0.1);
    EXPECT_TRUE(camera.nearPlane() > 0 && camera.nearPlane() < 0.1);
    camera.setOrthographic(true);
    EXPECT_LT(camera.nearPlane(), 0);
}

TEST(CameraTest, AFragmentFarAwayDoesNotClipWhatTheCameraLooksAt)
{
    Camera camera;
    const Eigen::AlignedBox3d drum(Eigen::Vector3d(-0.5, -0.5, 0), Eigen::Vector3d(0.5, 0.5, 1));
    camera.setSceneBounds(drum);
    camera.fit(drum);
    const double nearAlone = camera.nearPlane(), farAlone = camera.farPlane();
    // A fragment typed 10,000 km away: the scene's box now spans it.
    Eigen::AlignedBox3d scene = drum;
    scene.extend(Eigen::Vector3d(1e7, 0, 0));
    camera.setSceneBounds(scene);
    const double radius = 0.5 * drum.diagonal().norm();
    EXPECT_NEAR(camera.nearPlane(), 0.05 * camera.distance(), 1e-12); // was 1e-4 of 10,000 km: 1 km
    EXPECT_LT(camera.nearPlane(), camera.distance() - radius);
    EXPECT_NEAR(camera.farPlane(), 1e4 * camera.nearPlane(), 1e-6); // the far fragment is clipped
    EXPECT_GT(camera.farPlane(), camera.distance() + radius);
    // Back to the drum alone: the planes as before.
    camera.setSceneBounds(drum);
    EXPECT_DOUBLE_EQ(camera.nearPlane(), nearAlone);
    EXPECT_DOUBLE_EQ(camera.farPlane(), farAlone);

    // A close-up 1 cm from a drum of a 10 m column: the planes the scene gives (the rule must not clip the column
    // beyond 5 m): near at 1e-4 of far, far past the column's end.
    const Eigen::AlignedBox3d column(Eigen::Vector3d(-0.5, -0.5, 0), Eigen::Vector3d(0.5, 0.5, 10));
    camera.setSceneBounds(column);
    camera.setDistance(0.01);
    const double radiusColumn = 0.5 * column.diagonal().norm() * 1.05;
    const double depth = (column.center() - camera.eye()).dot(camera.forward());
    EXPECT_NEAR(camera.farPlane(), depth + radiusColumn, 1e-9);
    EXPECT_NEAR(camera.nearPlane(), 1e-4 * camera.farPlane(), 1e-12);
}
