// measureFragmentContact: two pieces cut from one design (a 100 × 60 × 40 mm block sampled every millimetre on its
// faces, cut by the plane x = 0, each half with its own break face): touching along the break, no interpenetration
// and every point at 0; one pushed 2 mm into the other, 2 mm; pulled 1 mm apart, a 1 mm gap; far apart, no contact;
// the sample caps; refusals.
#include "stylos/core/dock/FragmentContact.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stylos::core::dock {
namespace {

constexpr double kStep = 0.001;

void addPoint(cloud::PointCloud& c, const Eigen::Vector3d& p, const Eigen::Vector3d& n)
{
    c.addWorld(c.origin + p); // the design's coordinates about the site's origin
    c.normals.push_back(float(n.x()));
    c.normals.push_back(float(n.y()));
    c.normals.push_back(float(n.z()));
}

/** The half of the block between x = @p x0 and x = @p x1 (the break at x = 0), its faces sampled on the design's
 *  millimetre grid, outward normals. */
cloud::PointCloud half(double x0, double x1, const char* source)
{
    cloud::PointCloud c;
    c.source = source;
    c.origin = Eigen::Vector3d(1000.0, -2000.0, 50.0); // a site frame: the distances must not suffer
    const int nx = int(std::lround((x1 - x0) / kStep)), ny = 60, nz = 40;
    for (int i = 0; i <= nx; ++i)
        for (int j = 0; j <= ny; ++j) { // bottom and top
            const double x = x0 + i * kStep, y = -0.03 + j * kStep;
            addPoint(c, {x, y, -0.02}, -Eigen::Vector3d::UnitZ());
            addPoint(c, {x, y, 0.02}, Eigen::Vector3d::UnitZ());
        }
    for (int i = 0; i <= nx; ++i)
        for (int k = 1; k < nz; ++k) { // front and back
            const double x = x0 + i * kStep, z = -0.02 + k * kStep;
            addPoint(c, {x, -0.03, z}, -Eigen::Vector3d::UnitY());
            addPoint(c, {x, 0.03, z}, Eigen::Vector3d::UnitY());
        }
    for (int j = 1; j < ny; ++j)
        for (int k = 1; k < nz; ++k) { // the two ends: one is the break
            const double y = -0.03 + j * kStep, z = -0.02 + k * kStep;
            addPoint(c, {x0, y, z}, -Eigen::Vector3d::UnitX());
            addPoint(c, {x1, y, z}, Eigen::Vector3d::UnitX());
        }
    return c;
}

class FragmentContactTest : public ::testing::Test {
protected:
    cloud::PointCloud a = half(-0.05, 0.0, "a.ply"); // break face at x = 0, normal +x
    cloud::PointCloud b = half(0.0, 0.05, "b.ply");  // break face at x = 0, normal −x
};

TEST_F(FragmentContactTest, PiecesTouchingAlongTheBreakDoNotInterpenetrate)
{
    auto r = measureFragmentContact(a, b, Eigen::Isometry3d::Identity());
    ASSERT_TRUE(r.ok()) << r.error().message;
    // The break face (59 × 39 points) and the outer faces' points along the joint.
    EXPECT_GE(r->points, 59u * 39u);
    EXPECT_LT(r->largestInterpenetration, 1e-6);
    EXPECT_NEAR(r->medianGap, 0.0, 1e-6);
    EXPECT_NEAR(r->gap99, 0.0, 1e-6);
    EXPECT_DOUBLE_EQ(r->withinHalfMillimetre, 1.0);
}

TEST_F(FragmentContactTest, APiecePushedTwoMillimetresInReadsTwoMillimetres)
{
    const Eigen::Isometry3d pushed(Eigen::Translation3d(-0.002, 0.0, 0.0));
    auto r = measureFragmentContact(a, b, pushed);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_NEAR(r->largestInterpenetration, 0.002, 1e-6);
    EXPECT_NEAR(r->medianGap, -0.002, 1e-6); // most of the contact is the break face, 2 mm deep
    EXPECT_LT(r->withinHalfMillimetre, 0.5);
    // The same seen from the other piece.
    auto back = measureFragmentContact(b, a, pushed.inverse());
    ASSERT_TRUE(back.ok());
    EXPECT_NEAR(back->largestInterpenetration, 0.002, 1e-6);
}

TEST_F(FragmentContactTest, PiecesPulledApartReadTheGap)
{
    auto r = measureFragmentContact(a, b, Eigen::Isometry3d(Eigen::Translation3d(0.001, 0.0, 0.0)));
    ASSERT_TRUE(r.ok());
    EXPECT_LT(r->largestInterpenetration, 1e-6);
    EXPECT_NEAR(r->medianGap, 0.001, 1e-6);
    // Far apart: nothing within the band.
    auto far = measureFragmentContact(a, b, Eigen::Isometry3d(Eigen::Translation3d(0.1, 0.0, 0.0)));
    ASSERT_TRUE(far.ok());
    EXPECT_EQ(far->points, 0u);
    EXPECT_DOUBLE_EQ(far->largestInterpenetration, 0.0);
}

TEST_F(FragmentContactTest, TheCapsBoundTheSample)
{
    FragmentContactOptions options;
    options.maxPoints = 1000;
    auto r = measureFragmentContact(a, b, Eigen::Isometry3d(Eigen::Translation3d(-0.002, 0.0, 0.0)), options);
    ASSERT_TRUE(r.ok());
    EXPECT_LE(r->points, 1000u);
    EXPECT_GT(r->points, 0u);
    EXPECT_NEAR(r->largestInterpenetration, 0.002, 1e-6);
}

TEST_F(FragmentContactTest, RefusesAnOtherPieceWithoutNormalsAndABadPose)
{
    cloud::PointCloud bare = b;
    bare.normals.clear();
    auto r = measureFragmentContact(a, bare, Eigen::Isometry3d::Identity());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(r.error().message.find("b.ply"), std::string::npos);
    EXPECT_NE(r.error().message.find("normals"), std::string::npos);
    Eigen::Isometry3d nan = Eigen::Isometry3d::Identity();
    nan.translation().x() = std::nan("");
    EXPECT_FALSE(measureFragmentContact(a, b, nan).ok());
}

} // namespace
} // namespace stylos::core::dock
