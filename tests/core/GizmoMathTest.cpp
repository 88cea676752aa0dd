// core::view gizmo maths: the closest parameter along an arrow to a ray, ray ∩ plane and the ring angle,
// distances on screen to a projected segment and ring, the snapping steps and Shift's fine motion.
// Exact values from known geometry; an orthographic top camera at 1000 pixels per metre.
#include "stylos/core/view/GizmoMath.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace stylos::core::view;

namespace {

constexpr double Pi = std::numbers::pi;

/** 640 × 480, orthographic, looking down −Z at the origin: 1000 pixels per metre. */
Camera topCamera()
{
    Camera camera;
    camera.setStandardView(StandardView::Top);
    camera.setOrthographic(true);
    camera.setDistance(0.24 / std::tan(camera.fieldOfView() / 2));
    return camera;
}

Ray rayFrom(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) { return {origin, direction.normalized()}; }

} // namespace

TEST(GizmoMath, ClosestAxisParameter)
{
    // A ray along +Y at x = 0, z = 2 passes nearest the X line through (1, 0, 0) at x = 0: s = −1.
    EXPECT_DOUBLE_EQ(*closestAxisParameter(rayFrom({0, -5, 2}, {0, 1, 0}), {1, 0, 0}, {1, 0, 0}), -1.0);
    // Looking down at (3, 4): on the diagonal through the origin, s = (3 + 4) / √2.
    const Eigen::Vector3d diagonal = Eigen::Vector3d(1, 1, 0).normalized();
    EXPECT_NEAR(*closestAxisParameter(rayFrom({3, 4, 10}, {0, 0, -1}), Eigen::Vector3d::Zero(), diagonal),
                7 / std::sqrt(2.0), 1e-15);
    // A ray along the arrow: nothing to drag.
    EXPECT_FALSE(closestAxisParameter(rayFrom({0, 0, 0}, {1, 0, 0}), {0, 1, 0}, {1, 0, 0}));
}

TEST(GizmoMath, RayPlaneAndRingAngle)
{
    EXPECT_EQ(*rayPlane(rayFrom({0.5, 0.25, 5}, {0, 0, -1}), {0, 0, 1}, {0, 0, 1}), Eigen::Vector3d(0.5, 0.25, 1));
    EXPECT_FALSE(rayPlane(rayFrom({0, 0, 5}, {0, 0, 1}), {0, 0, 1}, {0, 0, 1}));  // behind
    EXPECT_FALSE(rayPlane(rayFrom({0, 0, 5}, {1, 0, 0}), {0, 0, 1}, {0, 0, 1}));  // parallel

    EXPECT_DOUBLE_EQ(signedAngle({1, 0, 0}, {0, 1, 0}, {0, 0, 1}), Pi / 2);
    EXPECT_DOUBLE_EQ(signedAngle({1, 0, 0}, {0, 1, 0}, {0, 0, -1}), -Pi / 2);
    EXPECT_DOUBLE_EQ(signedAngle({1, 0, 0}, {-1, 0, 0}, {0, 0, 1}), Pi);
    EXPECT_DOUBLE_EQ(signedAngle({1, 0, 7}, {0, 2, -3}, {0, 0, 1}), Pi / 2); // projected on the plane first
    EXPECT_EQ(signedAngle({0, 0, 1}, {0, 1, 0}, {0, 0, 1}), 0.0);

    // The ring about +Z through (1, 2, 0.5); the ray hits it 30° from +X.
    const Eigen::Vector3d centre(1, 2, 0.5);
    const Eigen::Vector3d at30 = centre + 0.3 * Eigen::Vector3d(std::cos(Pi / 6), std::sin(Pi / 6), 0);
    EXPECT_NEAR(*ringAngle(rayFrom(at30 + Eigen::Vector3d(0, 0, 4), {0, 0, -1}), centre, {0, 0, 1}, {1, 0, 0}), Pi / 6,
                1e-15);
    EXPECT_NEAR(*ringAngle(rayFrom(at30 + Eigen::Vector3d(0, 0, 4), {0, 0, -1}), centre, {0, 0, 1}, {0, 1, 0}), -Pi / 3,
                1e-15);
    EXPECT_FALSE(ringAngle(rayFrom(centre + Eigen::Vector3d(0, 0, 4), {0, 0, -1}), centre, {0, 0, 1}, {1, 0, 0}));

    EXPECT_DOUBLE_EQ(unwrapAngle(3.0, -3.0), 2 * Pi - 3.0);
    EXPECT_DOUBLE_EQ(unwrapAngle(-3.0, 3.0), 3.0 - 2 * Pi);
    EXPECT_DOUBLE_EQ(unwrapAngle(0.5, 0.75), 0.75);
}

TEST(GizmoMath, DistancesOnScreen)
{
    const Camera camera = topCamera();
    EXPECT_NEAR(*metresPerPixel(camera, {5, 5, -3}), 1e-3, 1e-15);
    Camera perspective = camera;
    perspective.setOrthographic(false);
    EXPECT_NEAR(*metresPerPixel(perspective, {0, 0, 0}), 1e-3, 1e-15); // at the target's depth
    EXPECT_NEAR(*metresPerPixel(perspective, {0, 0, -perspective.distance()}), 2e-3, 1e-15); // twice as deep
    EXPECT_FALSE(metresPerPixel(perspective, perspective.eye() + perspective.up()));

    // The centre of the view is the pixel (320, 240); +X is to the right, +Y up on screen.
    const Eigen::Vector2d c(320, 240);
    EXPECT_NEAR(pixelDistanceToSegment(camera, {0, 0, 0}, {0.1, 0, 0}, c + Eigen::Vector2d(50, 10)), 10, 1e-9);
    EXPECT_NEAR(pixelDistanceToSegment(camera, {0, 0, 0}, {0.1, 0, 0}, c + Eigen::Vector2d(103, -4)), 5, 1e-9);
    EXPECT_NEAR(pixelDistanceToSegment(camera, {0, 0, 0}, {0, 0.1, 0}, c + Eigen::Vector2d(7, -60)), 7, 1e-9);
    EXPECT_TRUE(std::isinf(pixelDistanceToSegment(perspective, perspective.eye() + perspective.forward() * -1,
                                                  {0, 0, 0}, c)));

    // From the centre of a ring of 0.1 m seen face on: the apothem of its polygon, 100 · cos(π/n) pixels.
    EXPECT_NEAR(pixelDistanceToRing(camera, {0, 0, 0}, {0, 0, 1}, 0.1, c, 96), 100 * std::cos(Pi / 96), 1e-9);
    EXPECT_NEAR(pixelDistanceToRing(camera, {0, 0, 0}, {0, 0, 1}, 0.1, c + Eigen::Vector2d(130, 0), 96), 30, 1e-9);
    // Edge-on (about +X seen from above): a segment of 200 pixels along y.
    EXPECT_NEAR(pixelDistanceToRing(camera, {0, 0, 0}, {1, 0, 0}, 0.1, c + Eigen::Vector2d(12, 50), 96), 12, 1e-9);
}

TEST(GizmoMath, SnappingSteps)
{
    const double pitch = 2 * Pi / 48;
    EXPECT_DOUBLE_EQ(angleStep(pitch, {}), 7.5 * Degree);
    EXPECT_DOUBLE_EQ(angleStep(pitch, {.fine = true}), 7.5 * Degree); // Shift alone: slower, still by flutes
    EXPECT_DOUBLE_EQ(angleStep(pitch, {.precise = true}), Degree);
    EXPECT_DOUBLE_EQ(angleStep(pitch, {.fine = true, .precise = true}), 0.1 * Degree);
    EXPECT_DOUBLE_EQ(angleStep(0, {}), Degree);
    EXPECT_DOUBLE_EQ(angleStep(0, {.fine = true}), 0.1 * Degree);
    EXPECT_EQ(lengthStep({}), 1e-3);
    EXPECT_EQ(lengthStep({.fine = true}), 1e-4);

    EXPECT_NEAR(snapToStep(0.0374, 1e-3), 0.037, 1e-15);
    EXPECT_NEAR(snapToStep(-0.0376, 1e-3), -0.038, 1e-15);
    EXPECT_NEAR(snapToStep(20 * Degree, pitch), 22.5 * Degree, 1e-15);
    EXPECT_NEAR(snapToStep(3.7 * Degree, pitch), 0.0, 1e-15);
    EXPECT_EQ(snapToStep(0.123, 0), 0.123);
}

TEST(GizmoMath, FineDragAccumulatesATenthWithShift)
{
    FineDrag drag(5.0);
    EXPECT_EQ(drag.value(), 0.0);
    EXPECT_DOUBLE_EQ(drag.feed(15.0, false), 10.0);
    EXPECT_DOUBLE_EQ(drag.feed(25.0, true), 11.0);  // Shift pressed: no jump, a tenth from here
    EXPECT_DOUBLE_EQ(drag.feed(20.0, true), 10.5);
    EXPECT_DOUBLE_EQ(drag.feed(30.0, false), 20.5); // released: full speed again
}
