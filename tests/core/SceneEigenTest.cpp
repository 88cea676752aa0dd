// SceneEigen: the one conversion between the scene's arrays and Eigen — exact round trips, the same
// transform either way, the first guide of a kind.
#include "stylos/core/scene/SceneEigen.h"

#include <gtest/gtest.h>

using namespace stylos::core::scene;

TEST(SceneEigen, PosesAndPointsRoundTripExactly)
{
    TranslationAngles value;
    value.translation = {412345.125, -3.5, 0.0625};
    value.angles = {0.1, -0.7, 2.9};
    const Pose pose = Pose::fromTranslationAngles(value);
    const Eigen::Matrix4d m = toEigen(pose);
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) EXPECT_EQ(m(row, col), pose(row, col));
    EXPECT_EQ(poseFromEigen(m).rowMajor(), pose.rowMajor());
    const std::array<double, 3> p{1.25, -2.5, 1e-9};
    EXPECT_EQ(toArray(toEigen(p)), p);
    // apply() is the pose's own arithmetic, bit for bit.
    const Eigen::Vector3d q = apply(pose, toEigen(p));
    EXPECT_EQ(toArray(q), pose.apply(p));
    const Eigen::Vector4d h = m * Eigen::Vector4d(p[0], p[1], p[2], 1.0);
    EXPECT_NEAR((h.head<3>() - q).norm(), 0.0, 1e-9);
}

TEST(SceneEigen, FirstGuideOfAKind)
{
    Fragment fragment;
    EXPECT_FALSE(firstGuide(fragment, GuideKind::Axis));
    fragment.guides.push_back({"first", GuideKind::Axis, {1, 2, 3}, {0, 0, 1}});
    fragment.guides.push_back({"second", GuideKind::Axis, {4, 5, 6}, {0, 1, 0}});
    const auto line = firstGuide(fragment, GuideKind::Axis);
    ASSERT_TRUE(line);
    EXPECT_EQ(line->origin, Eigen::Vector3d(1, 2, 3));
    EXPECT_EQ(line->direction, Eigen::Vector3d(0, 0, 1));
}
