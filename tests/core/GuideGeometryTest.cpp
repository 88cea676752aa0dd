// core::view guide geometry: the docking drum's axis and flute pitch through its pose, each guide as a segment
// over the fragment's extent, and the occupied bounds of an octree.
#include "stylos/core/view/GuideGeometry.h"

#include <gtest/gtest.h>

#include <numbers>

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
