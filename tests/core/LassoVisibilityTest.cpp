// lassoVisibleLeaves on a generated plain drum seen from the side: a lasso over its middle takes the front
// face only (no leaf whose normal faces away, none on the far half) and nearly all of the front leaves inside
// it; a fragment hidden behind another gets nothing (and its leaves once the front one is hidden); a polygon
// of two points or outside the view takes nothing; insidePolygon's even-odd rule.
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/view/LassoVisibility.h"

#include <gtest/gtest.h>

#include <fstream>
#include <memory>

using namespace stylos::core;
using view::Camera;
using view::ViewFragment;

namespace {

struct PlainDrum {
    std::unique_ptr<stylos::test::TempDir> dir;
    std::shared_ptr<const octree::PackedOctree> octree;
    Eigen::Affine3d pose = Eigen::Affine3d::Identity(); ///< drum frame (axis z, bed at z = 0) → file frame
    double radius = 0.2, height = 0.3;
};

const PlainDrum& plainDrum()
{
    static PlainDrum drum = [] {
        PlainDrum d;
        d.dir = std::make_unique<stylos::test::TempDir>();
        auto o = stylos::test::coarse(0.004, 11);
        o.radius = d.radius;
        o.height = d.height;
        o.grooves = 0;
        o.writeNormals = true;
        const auto ply = *d.dir / "drum.ply";
        const auto report = stylos::test::generate(synth::SyntheticKind::Drum, o, ply);
        std::ifstream truth(report.truthPath);
        d.pose = stylos::test::poseOf(nlohmann::json::parse(truth));
        octree::BuildOptions build;
        build.depth = 7;
        build.threads = 1;
        const auto built = octree::buildOctreeFile(ply, *d.dir / "drum.poct", build);
        EXPECT_TRUE(built.ok()) << (built.ok() ? "" : built.error().message);
        auto opened = octree::PackedOctree::open(*d.dir / "drum.poct");
        if (opened.ok()) d.octree = std::make_shared<const octree::PackedOctree>(std::move(opened).value());
        return d;
    }();
    return drum;
}

ViewFragment fragment(std::uint64_t id, const PlainDrum& drum, const Eigen::Vector3d& shift = Eigen::Vector3d::Zero())
{
    ViewFragment f;
    f.id = id;
    f.octree = drum.octree;
    f.pose.topRightCorner<3, 1>() = shift;
    return f;
}

/** From the side: looking at the middle of the axis along the drum's −x, the axis up on screen, 1.2 m away. */
Camera sideCamera(const PlainDrum& drum)
{
    Camera camera;
    camera.setViewport(400, 300);
    const Eigen::Vector3d up = drum.pose.linear() * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d back = drum.pose.linear() * Eigen::Vector3d::UnitX();
    Eigen::Matrix3d axes;
    axes.col(0) = up.cross(back);
    axes.col(1) = up;
    axes.col(2) = back;
    camera.setOrientation(Eigen::Quaterniond(axes));
    camera.setTarget(drum.pose * Eigen::Vector3d(0, 0, 0.5 * drum.height));
    camera.setDistance(1.2);
    return camera;
}

/** A rectangle about the view's centre: ± @p halfWidth, ± @p halfHeight metres at the target's depth. */
std::vector<Eigen::Vector2d> middle(const Camera& camera, double halfWidth, double halfHeight)
{
    const double s = camera.pixelsPerMetre(), cx = 0.5 * camera.width(), cy = 0.5 * camera.height();
    return {{cx - halfWidth * s, cy - halfHeight * s}, {cx + halfWidth * s, cy - halfHeight * s},
            {cx + halfWidth * s, cy + halfHeight * s}, {cx - halfWidth * s, cy + halfHeight * s}};
}

} // namespace

TEST(LassoVisibilityTest, InsidePolygonEvenOdd)
{
    const std::vector<Eigen::Vector2d> square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    EXPECT_TRUE(view::insidePolygon(square, 5, 5));
    EXPECT_FALSE(view::insidePolygon(square, 15, 5));
    EXPECT_FALSE(view::insidePolygon(square, 5, -1));
    // A bow tie (self-crossing): the two lobes are inside, the points above and below the crossing are not.
    const std::vector<Eigen::Vector2d> bowTie{{0, 0}, {10, 10}, {10, 0}, {0, 10}};
    EXPECT_TRUE(view::insidePolygon(bowTie, 1, 5));
    EXPECT_TRUE(view::insidePolygon(bowTie, 9, 5));
    EXPECT_FALSE(view::insidePolygon(bowTie, 5, 1));
    EXPECT_FALSE(view::insidePolygon({{0, 0}, {10, 10}}, 5, 5)); // two points: no area
}

TEST(LassoVisibilityTest, TheLassoTakesTheFrontFaceOfADrumOnly)
{
    const PlainDrum& drum = plainDrum();
    ASSERT_NE(drum.octree, nullptr);
    const Camera camera = sideCamera(drum);
    const auto polygon = middle(camera, 0.5 * drum.radius, 0.25 * drum.height);
    const auto result = view::lassoVisibleLeaves({fragment(1, drum)}, camera, {1}, polygon);
    ASSERT_EQ(result.size(), 1u);
    EXPECT_EQ(result[0].fragment, 1u);
    const std::vector<std::uint32_t>& got = result[0].leaves;
    ASSERT_TRUE(std::is_sorted(got.begin(), got.end()));

    // Every leaf: inside the lasso (its centre's pixel), on the front half or not, facing the eye or not.
    const Eigen::Vector3d axisPoint = drum.pose * Eigen::Vector3d::Zero();
    const Eigen::Vector3d axis = drum.pose.linear() * Eigen::Vector3d::UnitZ();
    std::size_t frontInside = 0, frontInsideTaken = 0, taken = 0;
    std::size_t next = 0;
    drum.octree->forEachCell(drum.octree->depth(), [&](const octree::CellView& leaf) {
        const Eigen::Vector3d p(leaf.centre[0], leaf.centre[1], leaf.centre[2]);
        const Eigen::Vector3d n(leaf.normal[0], leaf.normal[1], leaf.normal[2]);
        const Eigen::Vector3d toEye = (camera.eye() - p).normalized();
        const bool isTaken = next < got.size() && got[next] == leaf.index;
        if (isTaken) ++next, ++taken;
        const auto pixel = camera.project(p);
        const bool inside = pixel && view::insidePolygon(polygon, std::floor(pixel->x()) + 0.5, std::floor(pixel->y()) + 0.5);
        Eigen::Vector3d radial = p - axisPoint;
        radial -= radial.dot(axis) * axis;
        const bool frontHalf = radial.dot(camera.eye() - axisPoint) > 0;
        if (isTaken) {
            EXPECT_TRUE(inside) << "leaf " << leaf.index << " outside the lasso";
            EXPECT_TRUE(frontHalf) << "leaf " << leaf.index << " on the back of the drum";
            EXPECT_GT(n.dot(toEye), 0.0) << "leaf " << leaf.index << " faces away";
        }
        if (inside && frontHalf && n.dot(toEye) > 0.5) {
            ++frontInside;
            if (isTaken) ++frontInsideTaken;
        }
        return true;
    });
    EXPECT_EQ(next, got.size()); // every returned index is a leaf, once
    ASSERT_GT(frontInside, 500u);
    EXPECT_GE(double(frontInsideTaken), 0.99 * double(frontInside)) << frontInsideTaken << " of " << frontInside;
    EXPECT_EQ(taken, got.size());

    // Without the depth test (an unbounded tolerance) the same lasso goes through to the back: the test above
    // would see it.
    view::LassoOptions through;
    through.toleranceSpacings = 1e9;
    const auto all = view::lassoVisibleLeaves({fragment(1, drum)}, camera, {1}, polygon, through);
    EXPECT_GT(all[0].leaves.size(), got.size() + 200);
}

TEST(LassoVisibilityTest, AFragmentHiddenBehindAnotherGetsNothing)
{
    const PlainDrum& drum = plainDrum();
    ASSERT_NE(drum.octree, nullptr);
    const Camera camera = sideCamera(drum);
    const auto polygon = middle(camera, 0.5 * drum.radius, 0.25 * drum.height);
    // Fragment 2: the same drum 1 m further along the line of sight, behind fragment 1 (smaller on screen).
    const Eigen::Vector3d behind = camera.forward() * 1.0;
    const std::vector<ViewFragment> scene{fragment(1, drum), fragment(2, drum, behind)};
    const auto hidden = view::lassoVisibleLeaves(scene, camera, {2, 1}, polygon);
    ASSERT_EQ(hidden.size(), 2u);
    EXPECT_EQ(hidden[0].fragment, 2u); // in the targets' order
    EXPECT_TRUE(hidden[0].leaves.empty()) << hidden[0].leaves.size() << " hidden leaves taken";
    EXPECT_EQ(hidden[1].fragment, 1u);
    EXPECT_EQ(hidden[1].leaves, view::lassoVisibleLeaves({fragment(1, drum)}, camera, {1}, polygon)[0].leaves);
    view::LassoOptions through;
    through.toleranceSpacings = 1e9;
    EXPECT_FALSE(view::lassoVisibleLeaves(scene, camera, {2}, polygon, through)[0].leaves.empty()); // it is in the lasso

    // Without the front one (hidden), the back one's front face is taken.
    std::vector<ViewFragment> alone = scene;
    alone[0].visible = false;
    const auto shown = view::lassoVisibleLeaves(alone, camera, {1, 2}, polygon);
    ASSERT_EQ(shown.size(), 1u); // a hidden target is not selected at all
    EXPECT_EQ(shown[0].fragment, 2u);
    EXPECT_GT(shown[0].leaves.size(), 200u);
}

TEST(LassoVisibilityTest, NoPolygonOrOutsideTheViewTakesNothing)
{
    const PlainDrum& drum = plainDrum();
    ASSERT_NE(drum.octree, nullptr);
    const Camera camera = sideCamera(drum);
    const auto two = view::lassoVisibleLeaves({fragment(1, drum)}, camera, {1}, {{100, 100}, {300, 200}});
    ASSERT_EQ(two.size(), 1u);
    EXPECT_TRUE(two[0].leaves.empty());
    const std::vector<Eigen::Vector2d> outside{{-50, -50}, {-10, -50}, {-10, -10}};
    EXPECT_TRUE(view::lassoVisibleLeaves({fragment(1, drum)}, camera, {1}, outside)[0].leaves.empty());
    EXPECT_TRUE(view::lassoVisibleLeaves({fragment(1, drum)}, camera, {7}, middle(camera, 0.1, 0.1)).empty()); // no such target
}
