// fitDrumGuides: flute count, phase (every flute's bottom line), leading radius and depth against the
// generated drums' truth (48, 24 and 20 flutes, one all-round station so the points' frame is exact;
// three stations with registration offsets against the nominal pose); a given axis and count; refusals
// of a plane and a plain cylinder naming the source; a bad count; cancel; a tapering drum's cone (its
// radius slope and flute lines along its generators) and the guides file's radius_slope.
#include "FitTestSupport.h"

#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/dock/GuidesFile.h"

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

Eigen::Affine3d stationPose(const nlohmann::json& truth, int station)
{
    return station == kMeanStation ? meanStation(truth)
           : station < 0           ? test::affineOf(truth["pose"])
                                   : test::affineOf(truth["stations"][std::size_t(station)]["toOutput"]);
}

/** The drum's taper per metre of height (the generator's: radius lost from the lower bed to the upper one). */
double truthSlope(const nlohmann::json& truth)
{
    return -truth.value("taper", 0.0) / truth["height"].get<double>();
}

/** The true bottom line of flute @p k, in the output frame of @p station (−1: the nominal pose;
 *  kMeanStation: the mean of the stations): from the lower bed, along the cone's generator when it tapers. */
FluteLine trueBottom(const nlohmann::json& truth, int k, int station)
{
    const Eigen::Affine3d a = stationPose(truth, station);
    const auto& g = truth["grooves"];
    const double radius = truth["radius"].get<double>();
    const double r = radius - g["depth"].get<double>();
    const double angle = g["phase"].get<double>() + k * g["pitch"].get<double>();
    const Eigen::Vector3d radial(std::cos(angle), std::sin(angle), 0.0);
    const Eigen::Vector3d direction = (Eigen::Vector3d::UnitZ() + (r * truthSlope(truth) / radius) * radial).normalized();
    return {a * (r * radial), a.linear() * direction};
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
    // The leading radius at the axis point's height (the drum's own radius at the lower bed when it is a cylinder).
    const double z = (stationPose(truth, station).inverse() * g.axis.point).z();
    const double radius = truth["radius"].get<double>();
    EXPECT_NEAR(g.radius, radius * (1.0 + truthSlope(truth) / radius * z), radiusTolerance);
    EXPECT_NEAR(g.fluteDepth, truth["grooves"]["depth"].get<double>(), 0.0003);
    EXPECT_GE(g.phase, 0.0);
    EXPECT_LT(g.phase, 2.0 * std::numbers::pi / std::max(g.flutes, 1));
    const double height = truth["height"].get<double>();
    double worst = 0.0;
    for (int k = 0; k < count && !g.fluteLines.empty(); ++k) {
        const FluteLine t = trueBottom(truth, k, station);
        double nearest = std::numeric_limits<double>::infinity();
        for (const FluteLine& line : g.fluteLines) {
            nearest = std::min(nearest, lineDistance(line, t, height));
        }
        worst = std::max(worst, nearest);
    }
    EXPECT_LT(worst, lineTolerance) << "worst flute line, metres";
    // Each line against the nearest true line's direction (on a cone every flute has its own generator).
    double worstAngle = 0.0;
    for (const FluteLine& line : g.fluteLines) {
        double best = 180.0, bestDistance = std::numeric_limits<double>::infinity();
        for (int k = 0; k < count; ++k) {
            const FluteLine t = trueBottom(truth, k, station);
            if (const double d = lineDistance(line, t, height); d < bestDistance) bestDistance = d, best = test::angleDegrees(line.direction, t.direction);
        }
        EXPECT_LT(best, kDegreeTolerance);
        worstAngle = std::max(worstAngle, best);
    }
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
    EXPECT_EQ(g.slope, 0.0) << "a cylinder is not taken for a cone";
}

TEST(DrumGuidesTest, ATaperingDrumGivesItsConeAndFluteLinesAlongIt)
{
    for (const double taper : {0.006, -0.004}) { // 6 mm narrower at the top; 4 mm wider
        auto o = test::allRound(0.003, 59, 48);
        o.taper = taper;
        const auto& scan = test::generatedScan("guides-taper" + std::to_string(taper), SyntheticKind::Drum, o);
        const DrumGuides g = guidesOk(scan.cloud);
        // The cylinder's guides missed the fillets by millimetres here (radius −2.6 mm, rms 1.5 mm for 5 mm of taper).
        expectMatchesTruth(g, scan.truth, 0, kLineTolerance, kRadiusTolerance);
        // The slope is along the fitted axis direction, which may point down the drum.
        const Eigen::Vector3d up = stationPose(scan.truth, 0).linear() * Eigen::Vector3d::UnitZ();
        const double slope = truthSlope(scan.truth) * (g.axis.direction.dot(up) < 0.0 ? -1.0 : 1.0);
        std::printf("[ measured ] taper %.1f mm: slope %.6f (truth %.6f)\n", taper * 1e3, g.slope, slope);
        EXPECT_NEAR(g.slope, slope, 0.0004) << "0.2 mm of radius over the drum's half metre";
        EXPECT_NE(g.slope, 0.0);
    }
}

TEST(DrumGuidesTest, TheGuidesFileKeepsTheTaper)
{
    auto o = test::allRound(0.003, 59, 48);
    o.taper = 0.006;
    const auto& scan = test::generatedScan("guides-taper" + std::to_string(o.taper), SyntheticKind::Drum, o);
    const DrumGuides g = guidesOk(scan.cloud);
    nlohmann::json json = guidesToJson(g, 1.0);
    auto back = guidesFromJson(json, "g.json");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_DOUBLE_EQ(back->slope, g.slope);
    ASSERT_EQ(back->fluteLines.size(), g.fluteLines.size());
    for (std::size_t k = 0; k < g.fluteLines.size(); ++k) {
        EXPECT_LT((back->fluteLines[k].point - g.fluteLines[k].point).norm(), 1e-9) << k;
        EXPECT_LT((back->fluteLines[k].direction - g.fluteLines[k].direction).norm(), 1e-12) << k;
    }
    json.erase("radius_slope"); // a file written before cones: a cylinder
    auto old = guidesFromJson(json, "old.json");
    ASSERT_TRUE(old.ok());
    EXPECT_EQ(old->slope, 0.0);
    EXPECT_EQ(old->fluteLines[0].direction, old->axis.direction);
    json["radius_slope"] = "steep";
    auto bad = guidesFromJson(json, "bad.json");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("bad.json"), std::string::npos) << bad.error().message;
    EXPECT_NE(bad.error().message.find("radius_slope"), std::string::npos) << bad.error().message;
    json["radius_slope"] = g.slope;
    json["flutes"] = 40; // edited by hand: the 48 lines say otherwise
    auto edited = guidesFromJson(json, "edited.json");
    ASSERT_FALSE(edited.ok());
    EXPECT_EQ(edited.error().message,
              "edited.json: flutes (40) disagrees with its 48 flute_lines: give the count the guides were fitted with");
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

// A multiple of the drum's count (96 on 48 flutes: the fillets' harmonic stands well over the noise) is refused
// naming the count it is a multiple of; before, it gave 96 guides that docked nothing. The true count still fits.
TEST(DrumGuidesTest, AMultipleOfTheFluteCountIsRefused)
{
    const auto& scan = drum(48);
    GuideOptions options;
    for (const int multiple : {96, 144}) {
        options.flutes = multiple;
        const auto g = fitDrumGuides(scan.cloud, options);
        ASSERT_FALSE(g.ok()) << multiple;
        EXPECT_EQ(g.error().code, ErrorCode::InvalidArgument);
        EXPECT_NE(g.error().message.find(std::to_string(multiple) + " is a multiple of the drum's 48 flutes (give --flutes 48)"),
                  std::string::npos) << g.error().message;
    }
    // A divisor has nothing to stand on: refused, with the count the drum has.
    options.flutes = 24;
    const auto half = fitDrumGuides(scan.cloud, options);
    ASSERT_FALSE(half.ok());
    EXPECT_NE(half.error().message.find("no flutes found: 24 flutes stand "), std::string::npos) << half.error().message;
    EXPECT_NE(half.error().message.find("; 48 flutes stand "), std::string::npos) << half.error().message;
    EXPECT_NE(half.error().message.find("(give --flutes 48)"), std::string::npos) << half.error().message;
    options.flutes = 48;
    const auto g = fitDrumGuides(scan.cloud, options);
    ASSERT_TRUE(g.ok()) << g.error().message;
    EXPECT_EQ(g->flutes, 48);
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
