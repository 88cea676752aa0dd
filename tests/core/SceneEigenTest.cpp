// SceneEigen: the one conversion between the scene's arrays and Eigen — exact round trips, the same
// transform either way, the first guide of a kind.
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/scene/Scene.h"

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

// The axis a fragment unrolls about (its développée in the workbench and on a plate): its own axis guide, else its
// drum's carried into its frame through both scene poses — checked against the transform worked by hand.
TEST(SceneEigen, UnrollAxisIsTheOwnGuideElseTheDrumsInTheFragmentsFrame)
{
    Scene scene;
    Fragment drum;
    drum.name = "drum";
    drum.pose = Pose({1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1}); // a translation (1, 2, 3)
    drum.guides.push_back({"axis", GuideKind::Axis, {0.1, 0, 0}, {0, 0, 1}});
    const FragmentId drumId = scene.add(drum);
    Fragment piece;
    piece.name = "piece";
    // 90° about x (y → z, z → −y), then (0, 0.5, 0).
    piece.pose = Pose({1, 0, 0, 0, 0, 0, -1, 0.5, 0, 1, 0, 0, 0, 0, 0, 1});
    const FragmentId pieceId = scene.add(piece);
    Fragment alone;
    alone.name = "alone";
    const FragmentId aloneId = scene.add(alone);
    Fragment plain;
    plain.name = "plain";
    plain.guides.push_back({"a flute", GuideKind::Groove, {0, 0, 0}, {0, 0, 1}});
    const FragmentId plainId = scene.add(plain);

    // The drum's origin (0.1, 0, 0) is (1.1, 2, 3) in the scene, (1.1, 1.5, 3) less the piece's translation, and
    // (1.1, 3, −1.5) once turned back by −90° about x; its direction z becomes y.
    const auto carried = unrollAxis(scene, pieceId, drumId);
    ASSERT_TRUE(carried);
    EXPECT_NEAR((carried->origin - Eigen::Vector3d(1.1, 3, -1.5)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((carried->direction - Eigen::Vector3d(0, 1, 0)).norm(), 0.0, 1e-12);
    // The drum's own, and a piece's own guide first.
    const auto own = unrollAxis(scene, drumId, pieceId);
    ASSERT_TRUE(own);
    EXPECT_EQ(own->origin, Eigen::Vector3d(0.1, 0, 0));
    Fragment guided = *scene.find(pieceId);
    guided.guides.push_back({"its own", GuideKind::Axis, {0, 0, 0}, {1, 0, 0}});
    scene.take(pieceId);
    const FragmentId guidedId = scene.add(guided);
    const auto first = unrollAxis(scene, guidedId, drumId);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->direction, Eigen::Vector3d(1, 0, 0));
    // None: no guide and no drum, the drum itself, an unknown fragment or drum, a drum without an axis guide.
    EXPECT_FALSE(unrollAxis(scene, aloneId, NoFragment));
    EXPECT_FALSE(unrollAxis(scene, aloneId, aloneId));
    EXPECT_FALSE(unrollAxis(scene, 999, drumId));
    EXPECT_FALSE(unrollAxis(scene, aloneId, 999));
    EXPECT_FALSE(unrollAxis(scene, aloneId, plainId));
}
