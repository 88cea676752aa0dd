// fitDrumGuides: flute count, phase (every flute's bottom line), leading radius and depth against the
// generated drums' truth (48, 24 and 20 flutes, one all-round station so the points' frame is exact;
// three stations with registration offsets against the nominal pose); a given axis and count; refusals
// of a plane and a plain cylinder naming the source; a bad count; cancel.
#include "FitTestSupport.h"

#include "stylos/core/dock/DrumGuides.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace stylos::core::dock {
namespace {

using synth::SyntheticKind;

constexpr double kDegreeTolerance = 0.02; // the targets
constexpr double kLineTolerance = 0.0002;
constexpr double kRadiusTolerance = 0.0002;

const test::FitScan& drum(int grooves, int scans = 1)
{
    auto o = scans == 1 ? test::allRound(0.003, 11 + std::uint64_t(grooves), grooves) : test::coarse(0.003, 5);
    o.grooves = grooves;
    return test::generatedScan("guides" + std::to_string(grooves) + "x" + std::to_string(scans), SyntheticKind::Drum, o);
}

DrumGuides guidesOk(const cloud::PointCloud& cloud, const GuideOptions& options = {})
{
    auto g = fitDrumGuides(cloud, options);
    EXPECT_TRUE(g.ok()) << (g.ok() ? "" : g.error().message);
    return g.ok() ? *g : DrumGuides{};
}

constexpr int kMeanStation = -2;

/** The mean of the stations' object → output transforms (quaternions and translations averaged): where
 *  the scans, each moved by its registration error, put the drum on average. */
Eigen::Affine3d meanStation(const nlohmann::json& truth)
{
    Eigen::Vector4d q = Eigen::Vector4d::Zero();
    Eigen::Vector3d t = Eigen::Vector3d::Zero();
    const auto& stations = truth["stations"];
    for (const auto& s : stations) {
        const Eigen::Affine3d a = test::affineOf(s["toOutput"]);
        Eigen::Quaterniond r(a.linear());
        if (q.dot(r.coeffs()) < 0.0) r.coeffs() *= -1.0;
        q += r.coeffs();
        t += a.translation();
    }
    Eigen::Affine3d mean = Eigen::Affine3d::Identity();
    mean.linear() = Eigen::Quaterniond(q.normalized()).toRotationMatrix();
    mean.translation() = t / double(stations.size());
    return mean;
}

/** The true bottom line of flute @p k, in the output frame of @p station (−1: the nominal pose;
 *  kMeanStation: the mean of the stations). */
FluteLine trueBottom(const nlohmann::json& truth, int k, int station)
{
    const Eigen::Affine3d a = station == kMeanStation ? meanStation(truth)
                              : station < 0 ? test::affineOf(truth["pose"])
                                            : test::affineOf(truth["stations"][std::size_t(station)]["toOutput"]);
    const auto& g = truth["grooves"];
    const double r = truth["radius"].get<double>() - g["depth"].get<double>();
    const double angle = g["phase"].get<double>() + k * g["pitch"].get<double>();
    return {a * Eigen::Vector3d(r * std::cos(angle), r * std::sin(angle), 0.0), a.linear() * Eigen::Vector3d::UnitZ()};
}

/** Largest distance of @p line from the true line over the drum's height. */
double lineDistance(const FluteLine& line, const FluteLine& truth, double height)
{
    const unroll::Axis t{truth.point, truth.direction.normalized()};
    const double s = (truth.point - line.point).dot(line.direction); // level with the true line's foot
    return std::max(test::distanceToLine(line.point + s * line.direction, t),
                    test::distanceToLine(line.point + (s + height) * line.direction, t));
}

/** Checks count, radius, depth and every flute line against the truth; returns the worst line distance. */
double expectMatchesTruth(const DrumGuides& g, const nlohmann::json& truth, int station, double lineTolerance,
                          double radiusTolerance)
{
    const int count = truth["grooves"]["count"].get<int>();
    EXPECT_EQ(g.flutes, count);
    EXPECT_EQ(int(g.fluteLines.size()), g.flutes);
    EXPECT_NEAR(g.radius, truth["radius"].get<double>(), radiusTolerance);
    EXPECT_NEAR(g.fluteDepth, truth["grooves"]["depth"].get<double>(), 0.0003);
    EXPECT_GE(g.phase, 0.0);
    EXPECT_LT(g.phase, 2.0 * std::numbers::pi / std::max(g.flutes, 1));
    const double height = truth["height"].get<double>();
    double worst = 0.0;
    for (int k = 0; k < count && !g.fluteLines.empty(); ++k) {
        const FluteLine t = trueBottom(truth, k, station);
        double nearest = std::numeric_limits<double>::infinity();
        for (const FluteLine& line : g.fluteLines) {
            EXPECT_LT(test::angleDegrees(line.direction, t.direction), kDegreeTolerance);
            nearest = std::min(nearest, lineDistance(line, t, height));
        }
        worst = std::max(worst, nearest);
    }
    EXPECT_LT(worst, lineTolerance) << "worst flute line, metres";
    double worstAngle = 0.0;
    for (const FluteLine& line : g.fluteLines)
        worstAngle = std::max(worstAngle, test::angleDegrees(line.direction, trueBottom(truth, 0, station).direction));
    std::printf("[ measured ] %d flutes, %zu points: worst line %.4f mm, %.4f deg; radius %+.4f mm; depth %+.4f mm; "
                "rms %.4f mm; %.3f s\n", g.flutes, std::size_t(g.lateralPoints), worst * 1e3, worstAngle,
                (g.radius - truth["radius"].get<double>()) * 1e3,
                (g.fluteDepth - truth["grooves"]["depth"].get<double>()) * 1e3, g.rms * 1e3, g.seconds);
    EXPECT_LT(g.rms, 0.0006);
    EXPECT_GT(g.seconds, 0.0);
    return worst;
}

TEST(DrumGuidesTest, FortyEightFlutesMatchTheTruth)
{
    const auto& scan = drum(48);
    const DrumGuides g = guidesOk(scan.cloud);
    const double worst = expectMatchesTruth(g, scan.truth, 0, kLineTolerance, kRadiusTolerance);
    RecordProperty("worst_line_mm", std::to_string(worst * 1e3));
    EXPECT_NEAR(g.reference.norm(), 1.0, 1e-12);
    EXPECT_NEAR(g.reference.dot(g.axis.direction), 0.0, 1e-12);
}

TEST(DrumGuidesTest, TwentyFourFlutesMatchTheTruth)
{
    const auto& scan = drum(24);
    expectMatchesTruth(guidesOk(scan.cloud), scan.truth, 0, kLineTolerance, kRadiusTolerance);
}

TEST(DrumGuidesTest, TwentyFlutesMatchTheTruth)
{
    const auto& scan = drum(20);
    expectMatchesTruth(guidesOk(scan.cloud), scan.truth, 0, kLineTolerance, kRadiusTolerance);
}

TEST(DrumGuidesTest, ThreeScansWithOffsetsMatchTheNominalDrum)
{
    const auto& scan = drum(48, 3);
    const DrumGuides g = guidesOk(scan.cloud);
    expectMatchesTruth(g, scan.truth, kMeanStation, kLineTolerance, kRadiusTolerance);
    expectMatchesTruth(g, scan.truth, -1, 0.0004, kRadiusTolerance);
}

TEST(DrumGuidesTest, GivenAxisAndCountAreUsed)
{
    const auto& scan = drum(24);
    GuideOptions options;
    options.axis = test::trueAxis(scan.truth, 0);
    options.flutes = 24;
    const DrumGuides g = guidesOk(scan.cloud, options);
    EXPECT_LT(test::angleDegrees(g.axis.direction, options.axis->direction), 1e-9);
    expectMatchesTruth(g, scan.truth, 0, kLineTolerance, kRadiusTolerance);
}

TEST(DrumGuidesTest, PlaneIsRefusedNamingTheSource)
{
    const auto cloud = test::badCloud(test::BadShape::Plane, 20000, 3);
    const auto g = fitDrumGuides(cloud);
    ASSERT_FALSE(g.ok());
    EXPECT_EQ(g.error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(g.error().message.rfind("plane", 0), 0u) << g.error().message;
}

TEST(DrumGuidesTest, PlainCylinderHasNoFlutes)
{
    const auto& scan = drum(0);
    const auto g = fitDrumGuides(scan.cloud);
    ASSERT_FALSE(g.ok());
    EXPECT_EQ(g.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(g.error().message.find("no flutes found: the strongest of 12..64"), std::string::npos)
        << g.error().message;
    std::printf("[ measured ] plain cylinder: %s\n", g.error().message.c_str());
    EXPECT_EQ(g.error().message.rfind(scan.cloud.source, 0), 0u) << g.error().message;
}

TEST(DrumGuidesTest, BadFluteCountIsRefused)
{
    const auto& scan = drum(24);
    GuideOptions options;
    options.flutes = 2;
    const auto g = fitDrumGuides(scan.cloud, options);
    ASSERT_FALSE(g.ok());
    EXPECT_EQ(g.error().code, ErrorCode::InvalidArgument);
}

TEST(DrumGuidesTest, WrongGivenCountIsRefused)
{
    const auto& scan = drum(48);
    GuideOptions options;
    options.flutes = 37;
    const auto g = fitDrumGuides(scan.cloud, options);
    ASSERT_FALSE(g.ok());
    EXPECT_EQ(g.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(g.error().message.find("no flutes found: 37 flutes"), std::string::npos) << g.error().message;
}

TEST(DrumGuidesTest, CancelStops)
{
    const auto& scan = drum(24);
    SilentProgress progress;
    progress.cancel();
    const auto g = fitDrumGuides(scan.cloud, {}, &progress);
    ASSERT_FALSE(g.ok());
    EXPECT_EQ(g.error().code, ErrorCode::Cancelled);
}

} // namespace
} // namespace stylos::core::dock
