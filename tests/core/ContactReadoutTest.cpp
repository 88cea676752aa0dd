// measureContact: exact signed distances and their summary on points placed on, inside and outside a known flute
// profile (guides built by hand: a cylinder, a cosine flute), the drum frame and the pose followed, the normal
// filter, refusals; and on a generated fragment docked against the guides of a generated drum of its design.
#include "DockTestSupport.h"

#include "stylos/core/dock/ContactReadout.h"
#include "stylos/core/dock/DockRegistration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace stylos::core::dock {
namespace {

constexpr double kPi = std::numbers::pi;

/** Guides about the z axis through the origin, 4 flutes, profile P(x) = radius − amplitude·cos(2πx) over one
 *  pitch (x in pitches from a flute's bottom, the bottom at azimuth @p phase). amplitude 0: a cylinder. */
DrumGuides handGuides(double radius, double amplitude, double phase = 0.0)
{
    DrumGuides g;
    g.axis.point = Eigen::Vector3d::Zero();
    g.axis.direction = Eigen::Vector3d::UnitZ();
    g.reference = Eigen::Vector3d::UnitX();
    g.flutes = 4;
    g.phase = phase;
    g.radius = radius + amplitude;
    g.fluteDepth = 2 * amplitude;
    for (int b = 0; b < DrumGuides::ProfileBins; ++b) {
        const double x = (b + 0.5 - 0.5 * DrumGuides::ProfileBins) / DrumGuides::ProfileBins;
        g.profile.push_back(radius - amplitude * std::cos(2 * kPi * x));
    }
    return g;
}

cloud::PointCloud cloudOf(const std::vector<Eigen::Vector3d>& points)
{
    cloud::PointCloud c;
    c.source = "hand.ply";
    for (const Eigen::Vector3d& p : points) c.addWorld(p);
    return c;
}

TEST(ContactReadoutTest, SummarisesExactDistancesToACylinder)
{
    const DrumGuides g = handGuides(0.5, 0.0);
    // Dyadic offsets, exact in float: on, 2^-11 m inside (within 0.5 mm), 2^-9 m inside, 2^-10 m outside, and one
    // 2^-6 m (15.6 mm) outside, beyond the band.
    const double a = std::ldexp(1.0, -11), b = std::ldexp(1.0, -9), c = std::ldexp(1.0, -10), far = std::ldexp(1.0, -6);
    const cloud::PointCloud points = cloudOf({{0.5, 0.0, 0.1}, {0.0, 0.5 - a, 0.2}, {-(0.5 - b), 0.0, 0.0},
                                              {0.0, -(0.5 + c), 0.3}, {0.5 + far, 0.0, 0.0}});
    auto r = measureContact(points, g, Eigen::Isometry3d::Identity());
    ASSERT_TRUE(r.ok()) << r.error().message;
    // Sorted signed distances: −b, −a, 0, c.
    EXPECT_EQ(r->points, 4u);
    EXPECT_NEAR(r->largestInterpenetration, b, 1e-12);
    EXPECT_NEAR(r->medianGap, (-a + 0.0) / 2, 1e-12);   // at 1.5
    EXPECT_NEAR(r->gap90, 0.7 * c, 1e-12);              // at 2.7
    EXPECT_NEAR(r->gap99, 0.97 * c, 1e-12);             // at 2.97
    EXPECT_DOUBLE_EQ(r->withinHalfMillimetre, 0.5);     // 0 and −a
}

TEST(ContactReadoutTest, NothingInsideMeansNoInterpenetration)
{
    const DrumGuides g = handGuides(0.5, 0.0);
    const double c = std::ldexp(1.0, -10);
    auto r = measureContact(cloudOf({{0.5 + c, 0.0, 0.0}, {0.0, 0.5 + 2 * c, 0.0}, {0.0, -0.5 - 3 * c, 0.0}}), g,
                            Eigen::Isometry3d::Identity());
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->points, 3u);
    EXPECT_EQ(r->largestInterpenetration, 0.0);
    EXPECT_NEAR(r->medianGap, 2 * c, 1e-12);
    EXPECT_EQ(r->withinHalfMillimetre, 0.0);
}

TEST(ContactReadoutTest, FollowsTheProfileOfTheFlutes)
{
    const double radius = 0.5, amplitude = 0.004, phase = 0.1;
    const DrumGuides g = handGuides(radius, amplitude, phase);
    auto model = FluteModel::fromGuides(g);
    ASSERT_TRUE(model.ok());
    // At a flute's bottom and on a fillet the profile is flat: d = ρ − P exactly.
    const double pitch = kPi / 2;
    for (const auto& [phi, inside] : {std::pair{phase, 0.001}, std::pair{phase + pitch / 2, -0.002}}) {
        const double onProfile = radius - amplitude * std::cos(4 * (phi - phase));
        const Eigen::Vector3d p((onProfile - inside) * std::cos(phi), (onProfile - inside) * std::sin(phi), 0.3);
        EXPECT_NEAR(profileDistance(*model, p), -inside, 1e-9) << phi;
    }
    // On a flank: a point moved by δ along the profile's normal is δ away, to first order (δ²·curvature).
    const double phi = phase + pitch / 8;
    const double rho = radius - amplitude * std::cos(4 * (phi - phase));
    const Eigen::Vector3d onFlank(rho * std::cos(phi), rho * std::sin(phi), 0.0);
    Eigen::Vector3d normal;
    EXPECT_NEAR(profileDistance(*model, onFlank, &normal), 0.0, 1e-9);
    EXPECT_NEAR(normal.norm(), 1.0, 1e-12);
    EXPECT_GT(normal.dot(Eigen::Vector3d(std::cos(phi), std::sin(phi), 0.0)), 0.99); // outward, tilted by the flank
    EXPECT_LT(normal.dot(Eigen::Vector3d(std::cos(phi), std::sin(phi), 0.0)), 0.9999);
    for (double delta : {-0.001, 0.0005, 0.002})
        EXPECT_NEAR(profileDistance(*model, onFlank + delta * normal), delta, 2e-6) << delta;
}

TEST(ContactReadoutTest, FollowsTheDrumFrameAndThePose)
{
    // The same cylinder about a tilted axis away from the origin, the fragment placed by a pose.
    DrumGuides g = handGuides(0.5, 0.0);
    g.axis.point = Eigen::Vector3d(1.0, -2.0, 0.5);
    g.axis.direction = Eigen::Vector3d(0.2, 0.1, 1.0).normalized();
    g.reference = Eigen::Vector3d::UnitX();
    const DrumFrame frame(g);
    const Eigen::Isometry3d pose(Eigen::Translation3d(0.3, 0.2, -0.1) * Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
    std::vector<Eigen::Vector3d> local;
    const double offsets[] = {-0.003, -0.001, 0.0, 0.0002, 0.004};
    for (int i = 0; i < 5; ++i) {
        const double phi = 0.4 * i, rho = 0.5 + offsets[i];
        local.push_back(pose.inverse() * frame.toWorld(Eigen::Vector3d(rho * std::cos(phi), rho * std::sin(phi), 0.05 * i)));
    }
    auto r = measureContact(cloudOf(local), g, pose);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->points, 5u);
    EXPECT_NEAR(r->largestInterpenetration, 0.003, 3e-7); // float positions: 0.3 µm
    EXPECT_NEAR(r->medianGap, 0.0, 3e-7);
    EXPECT_NEAR(r->gap90, 0.0002 + 0.6 * 0.0038, 3e-7);
    EXPECT_NEAR(r->withinHalfMillimetre, 0.4, 1e-12);
}

TEST(ContactReadoutTest, LeavesOutPointsWhoseNormalIsNotTheProfiles)
{
    const DrumGuides g = handGuides(0.5, 0.0);
    // Three points 2^-9 m inside: radial normal (outer face), reversed (still the outer face), tangential (a
    // fracture face meeting the outer face).
    const double b = std::ldexp(1.0, -9);
    cloud::PointCloud c = cloudOf({{0.5 - b, 0.0, 0.0}, {0.0, 0.5 - b, 0.0}, {-(0.5 - b), 0.0, 0.0}});
    c.normals = {1, 0, 0, 0, -1, 0, 0, 1, 0};
    auto r = measureContact(c, g, Eigen::Isometry3d::Identity());
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->points, 2u);
    c.normals.clear();
    r = measureContact(c, g, Eigen::Isometry3d::Identity());
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->points, 3u);
}

TEST(ContactReadoutTest, NoContactAndRefusals)
{
    const DrumGuides g = handGuides(0.5, 0.0);
    const cloud::PointCloud c = cloudOf({{0.6, 0.0, 0.0}, {0.0, 0.3, 0.0}});
    auto r = measureContact(c, g, Eigen::Isometry3d::Identity());
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->points, 0u);
    EXPECT_EQ(r->largestInterpenetration, 0.0);

    // A stray point in the band among 200 away from it (a fragment moved 15 cm off): no contact, not a readout of
    // one point; 2 of 200 (1 %) are a contact.
    std::vector<Eigen::Vector3d> far(199, Eigen::Vector3d(0.65, 0.0, 0.0));
    far.push_back({0.0, 0.5 - 0.004, 0.0});
    r = measureContact(cloudOf(far), g, Eigen::Isometry3d::Identity());
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->points, 0u);
    EXPECT_EQ(r->largestInterpenetration, 0.0);
    far[0] = {0.0, -0.5, 0.0};
    r = measureContact(cloudOf(far), g, Eigen::Isometry3d::Identity());
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->points, 2u);
    EXPECT_NEAR(r->largestInterpenetration, 0.004, 1e-7); // the cloud keeps float offsets

    Eigen::Isometry3d broken = Eigen::Isometry3d::Identity();
    broken.translation().x() = std::nan("");
    r = measureContact(c, g, broken);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(r.error().message.find("hand.ply"), std::string::npos) << r.error().message;

    DrumGuides none = g;
    none.profile.clear();
    r = measureContact(c, none, Eigen::Isometry3d::Identity());
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("no flute profile"), std::string::npos) << r.error().message;
}

TEST(ContactReadoutTest, ADockedFragmentTouchesTheDrum)
{
    auto fitted = fitDrumGuides(test::dockDrum().cloud);
    ASSERT_TRUE(fitted.ok()) << fitted.error().message;
    const DrumFrame frame(*fitted);
    // Fragment 5 of the drum's design, with its true normals (what a .poct's leaves carry).
    auto o = test::allRound(0.003, 5, 48);
    o.designSeed = test::kDockDesign;
    o.writeNormals = true;
    const auto& fragment = test::generatedScan("contact-fragment-5", synth::SyntheticKind::Fragment, o);
    ASSERT_TRUE(fragment.cloud.hasNormals());
    const Eigen::Isometry3d truth = test::truePose(fragment, test::dockDrum());
    auto docked = dockFragment(fragment.cloud, *fitted, truth);
    ASSERT_TRUE(docked.ok()) << docked.error().message;
    auto contact = measureContact(fragment.cloud, *fitted, docked->pose);
    ASSERT_TRUE(contact.ok()) << contact.error().message;
    std::printf("contact: %zu points, largest %.3f mm, median %.3f, 90 %.3f, 99 %.3f mm, within %.3f\n", contact->points,
                contact->largestInterpenetration * 1e3, contact->medianGap * 1e3, contact->gap90 * 1e3,
                contact->gap99 * 1e3, contact->withinHalfMillimetre);
    EXPECT_GT(contact->points, 1000u);
    EXPECT_LT(std::abs(contact->medianGap), 0.0002) << contact->medianGap;
    EXPECT_GT(contact->withinHalfMillimetre, 0.7);
    EXPECT_LT(contact->largestInterpenetration, 0.0015);
    EXPECT_GT(contact->gap99, 0.0);

    // Pushed 2 mm into the drum (radially, at its centre): the median gap becomes −2 mm, the interpenetration > 2 mm.
    const Eigen::Vector3d centre = docked->pose * test::cloudCentre(fragment.cloud);
    const Eigen::Isometry3d in = test::perturbed(docked->pose, frame, centre, 0.0, 0.0, -0.002);
    auto pushed = measureContact(fragment.cloud, *fitted, in);
    ASSERT_TRUE(pushed.ok());
    EXPECT_NEAR(pushed->medianGap, -0.002, 0.0003) << pushed->medianGap;
    EXPECT_GT(pushed->largestInterpenetration, 0.002);
    EXPECT_LT(pushed->withinHalfMillimetre, 0.3);
}

} // namespace
} // namespace stylos::core::dock
