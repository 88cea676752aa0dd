// core::view guide geometry: the docking drum's axis and flute pitch through its pose, each guide as a segment
// over the fragment's extent, and the occupied bounds of an octree.
#include "PoctTestSupport.h"
#include "ReferenceOctree.h"
#include "TestSupport.h"

#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/view/GuideGeometry.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <vector>

using namespace stylos::core;

namespace {

scene::Fragment drumWithGuides(int grooves)
{
    scene::Fragment drum;
    drum.id = 3;
    // A quarter turn about Z, then up 2 m.
    drum.pose = scene::Pose({0, -1, 0, 1, 1, 0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 1});
    drum.guides.push_back({"Axis", scene::GuideKind::Axis, {0.5, 0, 0}, {0, 0, 1}});
    for (int k = 0; k < grooves; ++k) drum.guides.push_back({"Flute", scene::GuideKind::Groove, {1.5, 0, 0}, {0, 0, 1}});
    return drum;
}

} // namespace

TEST(GuideGeometry, DrumAxisThroughThePose)
{
    const auto axis = view::drumAxisOf(drumWithGuides(48));
    ASSERT_TRUE(axis);
    EXPECT_EQ(axis->point, Eigen::Vector3d(1, 0.5, 2));
    EXPECT_EQ(axis->direction, Eigen::Vector3d(0, 0, 1));
    EXPECT_DOUBLE_EQ(axis->pitch, 2 * std::numbers::pi / 48);
    EXPECT_EQ(view::drumAxisOf(drumWithGuides(0))->pitch, 0.0);
    scene::Fragment none = drumWithGuides(3);
    none.guides.erase(none.guides.begin());
    EXPECT_FALSE(view::drumAxisOf(none));
}

TEST(GuideGeometry, SegmentsSpanTheFragment)
{
    const scene::Fragment drum = drumWithGuides(1);
    const Eigen::AlignedBox3d box(Eigen::Vector3d(-1, -1, 0.25), Eigen::Vector3d(2, 1, 0.75));
    const auto segments = view::guideSegments(drum, box);
    ASSERT_EQ(segments.size(), 2u);
    EXPECT_EQ(segments[0].kind, scene::GuideKind::Axis);
    EXPECT_EQ(segments[0].a, Eigen::Vector3d(1, 0.5, 2.25));
    EXPECT_EQ(segments[0].b, Eigen::Vector3d(1, 0.5, 2.75));
    EXPECT_EQ(segments[1].kind, scene::GuideKind::Groove);
    EXPECT_EQ(segments[1].a, Eigen::Vector3d(1, 1.5, 2.25));
    EXPECT_TRUE(view::guideSegments(drum, Eigen::AlignedBox3d()).empty());
}

// A drum lying tilted in its file: guides along its tilted axis span its cells' extent along that axis (the corners of
// the cells projected), not the box of the file's axes, whose corners projected gave lines 2–3 times its height.
TEST(GuideGeometry, SegmentsOfATiltedFragmentSpanItsCellsAlongTheGuide)
{
    // A drum 0.3 m high and 0.5 m in radius whose axis d = (1, 1, 1)/√3 leans in its file: cells of 0.02 m on its
    // bed circles and its axis, the lowest at 0 and the highest at 0.3 along d.
    const Eigen::Vector3d d = Eigen::Vector3d(1, 1, 1).normalized();
    const Eigen::Vector3d u = d.unitOrthogonal(), v = d.cross(u);
    view::OccupiedCells cells;
    cells.size = 0.02;
    for (int k = 0; k < 72; ++k) {
        const double a = k * std::numbers::pi / 36;
        for (const double t : {0.0, 0.3}) cells.centres.push_back(t * d + 0.5 * (std::cos(a) * u + std::sin(a) * v));
    }
    scene::Fragment drum;
    drum.guides.push_back({"Axis", scene::GuideKind::Axis, {0.1, 0.1, 0.1}, {2, 2, 2}});
    drum.guides.push_back({"Flute", scene::GuideKind::Groove, scene::toArray(Eigen::Vector3d(0.5 * u)), {1, 1, 1}});
    const auto segments = view::guideSegments(drum, cells);
    ASSERT_EQ(segments.size(), 2u);
    const double reach = 0.01 * std::sqrt(3.0); // a cube's corners along d: ½ · 0.02 · (|dx| + |dy| + |dz|)
    EXPECT_TRUE(segments[0].a.isApprox(-reach * d, 1e-12)) << segments[0].a.transpose();
    EXPECT_TRUE(segments[0].b.isApprox((0.3 + reach) * d, 1e-12)) << segments[0].b.transpose();
    EXPECT_TRUE(segments[1].a.isApprox(0.5 * u - reach * d, 1e-12)) << segments[1].a.transpose();
    EXPECT_NEAR((segments[1].b - segments[1].a).norm(), 0.3 + 2 * reach, 1e-12); // 0.335 m
    // The box of the file's axes: its corners projected on d span over twice the drum's height.
    Eigen::AlignedBox3d box;
    for (const auto& c : cells.centres) box.extend(c - Eigen::Vector3d::Constant(0.01)).extend(c + Eigen::Vector3d::Constant(0.01));
    const auto boxed = view::guideSegments(drum, box);
    EXPECT_GT((boxed[0].b - boxed[0].a).norm(), 2 * 0.3);
    EXPECT_TRUE(view::guideSegments(drum, view::OccupiedCells{}).empty());
}

namespace {

/** Every cell of @p level, one by one: what occupiedBounds() finds by its descent. */
Eigen::AlignedBox3d boundsOfEveryCell(const octree::PackedOctree& octree, int level)
{
    Eigen::AlignedBox3d box;
    octree.forEachCell(level, [&box](const octree::CellView& cell) {
        const Eigen::Vector3d c(cell.centre[0], cell.centre[1], cell.centre[2]);
        box.extend(c - Eigen::Vector3d::Constant(cell.size / 2));
        box.extend(c + Eigen::Vector3d::Constant(cell.size / 2));
        return true;
    });
    return box;
}

} // namespace

TEST(GuideGeometry, OccupiedBoundsOfKnownLeaves)
{
    // Root (100, 200, 300), edge 4, depth 2: leaves (0,0,0), (1,0,0), (2,2,2), (3,2,2) of edge 1.
    const std::vector<double> p{100.5, 200.5, 300.5, 101.5, 200.5, 300.5, 102.5, 202.5, 302.5, 103.5, 202.5, 302.5};
    const std::vector<float> n{0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, -1};
    const stylos::test::ReferenceOctree reference(p, n, {}, 2, octree::NormalCodeKind::Octahedral16,
                                                  octree::RootBox{{100, 200, 300}, 4.0});
    stylos::test::TempDir dir;
    const auto tree = stylos::test::pack(reference, dir);
    ASSERT_NE(tree, nullptr);
    const Eigen::AlignedBox3d leaves = view::occupiedBounds(*tree, 2);
    EXPECT_EQ(leaves.min(), Eigen::Vector3d(100, 200, 300));
    EXPECT_EQ(leaves.max(), Eigen::Vector3d(104, 203, 303));
    const Eigen::AlignedBox3d halves = view::occupiedBounds(*tree, 1); // cells (0,0,0) and (1,1,1) of edge 2
    EXPECT_EQ(halves.min(), Eigen::Vector3d(100, 200, 300));
    EXPECT_EQ(halves.max(), Eigen::Vector3d(104, 204, 304));
    EXPECT_EQ(view::occupiedBounds(*tree, 9).max(), leaves.max()); // clamped to the depth
    EXPECT_EQ(view::occupiedBounds(*tree, 0).max(), Eigen::Vector3d(104, 204, 304));
}

TEST(GuideGeometry, OccupiedBoundsAgreeWithEveryCellAtEveryLevel)
{
    // A scattered cloud (a lumpy shell and stray points), depth 9: the descent against a walk over every cell.
    std::mt19937 random(5);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(-0.3, 0.7);
    std::vector<double> p;
    for (int i = 0; i < 3000; ++i) {
        Eigen::Vector3d v(gauss(random), gauss(random), 0.4 * gauss(random));
        v = v.normalized() * (0.2 + 0.01 * gauss(random));
        if (i % 100 == 0) v = Eigen::Vector3d(uniform(random), uniform(random), uniform(random));
        p.insert(p.end(), {v.x() + 3.0, v.y() - 1.0, v.z() + 0.5});
    }
    const std::vector<float> n(p.size(), 0.57735f);
    // The root box off the cloud's centre: the cloud's low and high cells are not mirror images.
    const stylos::test::ReferenceOctree reference(p, n, {}, 9, octree::NormalCodeKind::Octahedral16,
                                                  octree::RootBox{{2.6, -1.35, 0.05}, 1.5});
    stylos::test::TempDir dir;
    const auto tree = stylos::test::pack(reference, dir);
    ASSERT_NE(tree, nullptr);
    for (int level = 0; level <= 9; ++level) {
        const Eigen::AlignedBox3d expected = boundsOfEveryCell(*tree, level);
        const Eigen::AlignedBox3d found = view::occupiedBounds(*tree, level);
        EXPECT_EQ(found.min(), expected.min()) << "level " << level;
        EXPECT_EQ(found.max(), expected.max()) << "level " << level;
    }
}
