// Pose: row-major rigid transforms, angles Rz·Ry·Rx both ways, inverse, rigidity checks.
#include "stylos/core/scene/Pose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace stylos::core::scene {
namespace {

constexpr double pi = std::numbers::pi;

void expectNear(const std::array<double, 3>& a, const std::array<double, 3>& b, double tolerance)
{
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tolerance) << "component " << i;
}

TEST(PoseTest, IdentityAndTranslation)
{
    const Pose identity;
    EXPECT_EQ(identity.apply({1, 2, 3}), (std::array<double, 3>{1, 2, 3}));
    const Pose t = Pose::translation({10, -20, 1e6});
    EXPECT_EQ(t.apply({1, 2, 3}), (std::array<double, 3>{11, -18, 1e6 + 3}));
    EXPECT_EQ(t.translationPart(), (std::array<double, 3>{10, -20, 1e6}));
    EXPECT_EQ(t(0, 3), 10.0);
    EXPECT_EQ(t.rowMajor()[11], 1e6);
    EXPECT_TRUE(t.isRigid());
}

TEST(PoseTest, AnglesRotateAboutFixedAxesXThenYThenZ)
{
    // 90° about z maps x to y.
    expectNear(Pose().withAngles({0, 0, pi / 2}).apply({1, 0, 0}), {0, 1, 0}, 1e-15);
    // 90° about x maps y to z.
    expectNear(Pose().withAngles({pi / 2, 0, 0}).apply({0, 1, 0}), {0, 0, 1}, 1e-15);
    // x first, then z: y → z (by x) → z (z leaves it).
    expectNear(Pose().withAngles({pi / 2, 0, pi / 2}).apply({0, 1, 0}), {0, 0, 1}, 1e-15);
    // 90° about y maps z to x.
    expectNear(Pose().withAngles({0, pi / 2, 0}).apply({0, 0, 1}), {1, 0, 0}, 1e-15);
}

TEST(PoseTest, TranslationAnglesRoundTrip)
{
    const TranslationAngles value{{1.25, -3.5, 402.125}, {0.3, -1.2, 2.9}};
    const Pose pose = Pose::fromTranslationAngles(value);
    EXPECT_TRUE(pose.isRigid(1e-12));
    const TranslationAngles back = pose.toTranslationAngles();
    EXPECT_EQ(back.translation, value.translation);
    expectNear(back.angles, value.angles, 1e-12);
}

TEST(PoseTest, GimbalLockKeepsTheRotation)
{
    const Pose pose = Pose().withAngles({0.4, pi / 2, 0.1});
    const TranslationAngles back = pose.toTranslationAngles();
    EXPECT_EQ(back.angles[0], 0.0);
    EXPECT_NEAR(back.angles[1], pi / 2, 1e-12);
    const Pose again = Pose().withAngles(back.angles);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(again(r, c), pose(r, c), 1e-7) << r << "," << c;
}

TEST(PoseTest, WithTranslationAndWithAnglesLeaveTheOtherPartBitExact)
{
    const Pose pose = Pose::fromTranslationAngles({{0.1, 0.2, 0.3}, {0.7, 0.1, -0.4}});
    const Pose moved = pose.withTranslation({5, 6, 7});
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(moved(r, c), pose(r, c));
    const Pose turned = pose.withAngles({0, 0, 1});
    EXPECT_EQ(turned.translationPart(), pose.translationPart());
}

TEST(PoseTest, InverseAndComposition)
{
    const Pose pose = Pose::fromTranslationAngles({{3, -1, 2}, {0.2, 0.5, -0.9}});
    const Pose product = pose * pose.rigidInverse();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(product(r, c), r == c ? 1.0 : 0.0, 1e-15);
    const std::array<double, 3> p{0.5, -4, 9};
    expectNear(pose.rigidInverse().apply(pose.apply(p)), p, 1e-14);
    const Pose other = Pose::translation({1, 0, 0});
    expectNear((pose * other).apply(p), pose.apply(other.apply(p)), 1e-14);
}

TEST(PoseTest, RigidityRefusesScaleShearMirrorsAndNonFinite)
{
    EXPECT_TRUE(Pose().isRigid());
    EXPECT_FALSE(Pose({2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}).isRigid());   // scale
    EXPECT_FALSE(Pose({1, 0.1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}).isRigid()); // shear
    EXPECT_FALSE(Pose({-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}).isRigid());  // mirror
    EXPECT_FALSE(Pose({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1}).isRigid());   // projective row
    EXPECT_FALSE(Pose({1, 0, 0, NAN, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}).isRigid());
    EXPECT_TRUE(Pose({1, 1e-9, 0, 0, -1e-9, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}).isRigid());
}

} // namespace
} // namespace stylos::core::scene
