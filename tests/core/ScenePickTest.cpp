// sceneBounds and pickScene on the four-leaf tree: exact bounds (posed, selected only, hidden and empty
// fragments left out) and the leaf under a pixel — the nearest along the ray among posed fragments,
// perspective and orthographic, nothing in an empty corner.
#include "ViewTestSupport.h"

#include "stylos/core/view/ScenePick.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace stylos::core;
using stylos::core::view::Camera;
using stylos::core::view::StandardView;
using stylos::core::view::ViewFragment;
using stylos::test::viewFragment;

namespace {

const Eigen::Vector3d O(stylos::test::FourLeafOrigin[0], stylos::test::FourLeafOrigin[1],
                        stylos::test::FourLeafOrigin[2]);
constexpr double H = 0.8660254037844386; ///< half the diagonal of a 1 m leaf: its bound under any rotation

void expectBox(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& min, const Eigen::Vector3d& max)
{
    ASSERT_FALSE(box.isEmpty());
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(box.min()[a], min[a], 1e-12) << "min " << a;
        EXPECT_NEAR(box.max()[a], max[a], 1e-12) << "max " << a;
    }
}

/** Front view (looking along +y) of a 100 × 100 viewport, 10 m from leaf a1's centre. */
Camera frontCamera()
{
    Camera camera;
    camera.setViewport(100, 100);
    camera.setStandardView(StandardView::Front);
    camera.setTarget(O + Eigen::Vector3d(0.5, 0.5, 0.5));
    camera.setDistance(10);
    return camera;
}

Eigen::Matrix4d translation(double x, double y, double z)
{
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topRightCorner<3, 1>() << x, y, z;
    return m;
}

} // namespace

TEST(ScenePickTest, BoundsOfTheLeavesExactly)
{
    stylos::test::TempDir dir;
    const auto tree = stylos::test::fourLeafOctree(dir);
    ASSERT_NE(tree, nullptr);
    // Leaf centres from (0.5, 0.5, 0.5) to (3.5, 2.5, 2.5), each grown by H.
    const Eigen::Vector3d lo = O + Eigen::Vector3d(0.5 - H, 0.5 - H, 0.5 - H);
    const Eigen::Vector3d hi = O + Eigen::Vector3d(3.5 + H, 2.5 + H, 2.5 + H);
    expectBox(view::sceneBounds({viewFragment(1, tree)}), lo, hi);

    ViewFragment moved = viewFragment(2, tree, translation(10, 0, -1));
    moved.selected = true;
    const Eigen::Vector3d shift(10, 0, -1);
    expectBox(view::sceneBounds({viewFragment(1, tree), moved}), lo + Eigen::Vector3d(0, 0, -1),
              hi + Eigen::Vector3d(10, 0, 0));
    expectBox(view::sceneBounds({viewFragment(1, tree), moved}, true), lo + shift, hi + shift);

    ViewFragment hidden = moved;
    hidden.visible = false;
    ViewFragment empty = viewFragment(3, nullptr, translation(50, 50, 50));
    expectBox(view::sceneBounds({viewFragment(1, tree), hidden, empty}), lo, hi);
    EXPECT_TRUE(view::sceneBounds({hidden, empty}).isEmpty());
    EXPECT_TRUE(view::sceneBounds({viewFragment(1, tree)}, true).isEmpty()); // nothing selected
    EXPECT_TRUE(view::sceneBounds({}).isEmpty());
}

TEST(ScenePickTest, TheNearestLeafUnderThePixel)
{
    stylos::test::TempDir dir;
    const auto tree = stylos::test::fourLeafOctree(dir);
    ASSERT_NE(tree, nullptr);
    const Camera camera = frontCamera();
    const Eigen::Vector3d a1 = O + Eigen::Vector3d(0.5, 0.5, 0.5);

    const auto pick = view::pickScene({viewFragment(7, tree)}, camera, 50, 50);
    ASSERT_TRUE(pick);
    EXPECT_NEAR((pick->point - a1).norm(), 0, 1e-12);
    EXPECT_EQ(pick->fragmentId, 7u);
    EXPECT_EQ(pick->cellSize, 1.0);
    EXPECT_NEAR(pick->along, 10, 1e-9);

    // The pixel over leaf a2 picks a2; an empty corner picks nothing.
    const auto overA2 = camera.project(O + Eigen::Vector3d(1.5, 0.5, 0.5));
    ASSERT_TRUE(overA2);
    const auto a2 = view::pickScene({viewFragment(7, tree)}, camera, overA2->x(), overA2->y());
    ASSERT_TRUE(a2);
    EXPECT_NEAR((a2->point - (O + Eigen::Vector3d(1.5, 0.5, 0.5))).norm(), 0, 1e-12);
    EXPECT_FALSE(view::pickScene({viewFragment(7, tree)}, camera, 0, 0));

    // A copy 5 m nearer the eye is picked first, until it is hidden.
    ViewFragment nearer = viewFragment(8, tree, translation(0, -5, 0));
    const auto first = view::pickScene({viewFragment(7, tree), nearer}, camera, 50, 50);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->fragmentId, 8u);
    EXPECT_NEAR((first->point - (a1 + Eigen::Vector3d(0, -5, 0))).norm(), 0, 1e-12);
    EXPECT_NEAR(first->along, 5, 1e-9);
    nearer.visible = false;
    const auto behind = view::pickScene({viewFragment(7, tree), nearer}, camera, 50, 50);
    ASSERT_TRUE(behind);
    EXPECT_EQ(behind->fragmentId, 7u);
}

TEST(ScenePickTest, APosedFragmentIsPickedInItsOwnFrame)
{
    stylos::test::TempDir dir;
    const auto tree = stylos::test::fourLeafOctree(dir);
    ASSERT_NE(tree, nullptr);
    // A quarter turn about z, then a translation that puts leaf b1 on the central ray, 4.5 m from the eye
    // (b2 lands on it too, 1 m further; a1 and a2 2.8 m off it).
    Eigen::Matrix4d pose = translation(303, 92.5, -2);
    pose.topLeftCorner<3, 3>() << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    const Eigen::Vector3d b1 = pose.topLeftCorner<3, 3>() * (O + Eigen::Vector3d(2.5, 2.5, 2.5)) +
                               pose.topRightCorner<3, 1>();
    EXPECT_NEAR((b1 - Eigen::Vector3d(100.5, 195, 300.5)).norm(), 0, 1e-12);
    const auto pick = view::pickScene({viewFragment(1, tree), viewFragment(2, tree, pose)}, frontCamera(), 50, 50);
    ASSERT_TRUE(pick);
    EXPECT_EQ(pick->fragmentId, 2u);
    EXPECT_NEAR((pick->point - b1).norm(), 0, 1e-12);
    EXPECT_NEAR(pick->along, 4.5, 1e-9);
}

TEST(ScenePickTest, OrthographicRaysStartOnTheNearPlane)
{
    stylos::test::TempDir dir;
    const auto tree = stylos::test::fourLeafOctree(dir);
    ASSERT_NE(tree, nullptr);
    Camera camera = frontCamera();
    camera.setOrthographic(true); // no scene bounds: the near plane is 0.01 · distance ahead of the eye
    const auto pick = view::pickScene({viewFragment(1, tree)}, camera, 50, 50);
    ASSERT_TRUE(pick);
    EXPECT_NEAR((pick->point - (O + Eigen::Vector3d(0.5, 0.5, 0.5))).norm(), 0, 1e-12);
    EXPECT_NEAR(pick->along, 9.9, 1e-9);
}

TEST(ScenePickTest, SceneCornersAreTheOccupiedCellsPosed)
{
    stylos::test::TempDir dir;
    const auto tree = stylos::test::fourLeafOctree(dir);
    ASSERT_NE(tree, nullptr);
    // Four 1 m leaves, centres from (0.5, 0.5, 0.5) to (3.5, 2.5, 2.5): eight corners each, whole cells.
    const auto corners = view::sceneCorners({viewFragment(1, tree)});
    ASSERT_EQ(corners.size(), std::size_t{32});
    Eigen::AlignedBox3d box;
    for (const auto& c : corners) box.extend(c);
    expectBox(box, O, O + Eigen::Vector3d(4, 3, 3));

    ViewFragment moved = viewFragment(2, tree, translation(10, 0, -1));
    moved.selected = true;
    const auto selected = view::sceneCorners({viewFragment(1, tree), moved}, true);
    ASSERT_EQ(selected.size(), std::size_t{32});
    box.setEmpty();
    for (const auto& c : selected) box.extend(c);
    expectBox(box, O + Eigen::Vector3d(10, 0, -1), O + Eigen::Vector3d(14, 3, 2));
    ViewFragment hidden = moved;
    hidden.visible = false;
    EXPECT_TRUE(view::sceneCorners({hidden}).empty());
    EXPECT_TRUE(view::sceneCorners({viewFragment(1, tree)}, true).empty());
}

TEST(ScenePickTest, FitFramesTheOccupiedCells)
{
    // The four leaves seen from the front (x right, z up), 800 × 600, 45° vertical field: every corner of the
    // occupied cells in view, the picture exactly centred along the axis that sets the distance, where it spans
    // 1 / 1.05 of the view (the 5 % margin), and within it along the other.
    stylos::test::TempDir dir;
    const auto tree = stylos::test::fourLeafOctree(dir);
    ASSERT_NE(tree, nullptr);
    Camera camera;
    camera.setViewport(800, 600);
    camera.setStandardView(StandardView::Front);
    const auto corners = view::sceneCorners({viewFragment(1, tree)});
    camera.fit(corners);
    double loX = INFINITY, hiX = -INFINITY, loY = INFINITY, hiY = -INFINITY;
    for (const auto& c : corners) {
        const auto p = camera.project(c);
        ASSERT_TRUE(p);
        loX = std::min(loX, p->x());
        hiX = std::max(hiX, p->x());
        loY = std::min(loY, p->y());
        hiY = std::max(hiY, p->y());
    }
    const double fillX = (hiX - loX) / 800.0, fillY = (hiY - loY) / 600.0;
    EXPECT_NEAR(std::max(fillX, fillY), 1.0 / 1.05, 1e-9);
    EXPECT_GT(std::min(fillX, fillY), 0.5); // the other axis is well filled too (its extent is 3 m against 4 m)
    if (fillX >= fillY) EXPECT_NEAR(400.0 - loX, hiX - 400.0, 1e-6);
    else EXPECT_NEAR(300.0 - loY, hiY - 300.0, 1e-6);
    EXPECT_GE(loX, 0.0);
    EXPECT_LE(hiX, 800.0);
    EXPECT_GE(loY, 0.0);
    EXPECT_LE(hiY, 600.0);
}
