// generateScan: determinism, point counts, the sidecar, cancel and errors (points against the truth:
// SyntheticTruthTest.cpp).
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/synth/SyntheticScan.h"

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

namespace fs = std::filesystem;
using namespace stylos::core;
using namespace stylos::core::synth;
using stylos::test::TempDir;
using stylos::test::coarse;
using stylos::test::generate;
using stylos::test::poseOf;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

nlohmann::json readTruth(const fs::path& path)
{
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

} // namespace

TEST(SynthScan, KindFromName)
{
    EXPECT_EQ(syntheticKindFromName("drum"), SyntheticKind::Drum);
    EXPECT_EQ(syntheticKindFromName("omphalos"), SyntheticKind::Omphalos);
    EXPECT_EQ(syntheticKindFromName("fragment"), SyntheticKind::Fragment);
    EXPECT_FALSE(syntheticKindFromName("Drum").has_value());
    EXPECT_FALSE(syntheticKindFromName("").has_value());
}

TEST(SynthScan, TruthPathBesideTheOutput)
{
    EXPECT_EQ(truthPathFor("x.ply"), fs::path("x.truth.json"));
    EXPECT_EQ(truthPathFor("/a/b/drum.ply"), fs::path("/a/b/drum.truth.json"));
    EXPECT_EQ(truthPathFor("noext"), fs::path("noext.truth.json"));
}

TEST(SynthScan, SameSeedSameBytesOtherSeedOtherBytes)
{
    TempDir a, b, c;
    for (const auto kind : {SyntheticKind::Drum, SyntheticKind::Omphalos, SyntheticKind::Fragment}) {
        generate(kind, coarse(0.008, 3), a / "s.ply");
        generate(kind, coarse(0.008, 3), b / "s.ply");
        generate(kind, coarse(0.008, 4), c / "s.ply");
        EXPECT_EQ(stylos::test::readBytes(a / "s.ply"), stylos::test::readBytes(b / "s.ply"));
        EXPECT_EQ(stylos::test::readBytes(a / "s.truth.json"), stylos::test::readBytes(b / "s.truth.json"));
        EXPECT_NE(stylos::test::readBytes(a / "s.ply"), stylos::test::readBytes(c / "s.ply"));
    }
}

TEST(SynthScan, DrumPointCountMatchesTheSpacing)
{
    TempDir dir;
    for (const double spacing : {0.004, 0.008}) {
        const SyntheticOptions o = coarse(spacing);
        const SyntheticReport report = generate(SyntheticKind::Drum, o, dir / "d.ply");
        // Lateral surface and both beds, each point seen by scans·(2·halfAngle / 2π) scans on average.
        const double area = kTwoPi * o.radius * o.height + 2.0 * std::numbers::pi * o.radius * o.radius;
        const double expected = area * o.scans * (o.scanHalfAngle / std::numbers::pi) / (spacing * spacing);
        EXPECT_GT(report.points, 0.85 * expected) << spacing;
        EXPECT_LT(report.points, 1.10 * expected) << spacing;
        const nlohmann::json truth = readTruth(report.truthPath);
        EXPECT_EQ(truth["points"].get<std::uint64_t>(), report.points);
        auto reader = io::openPointReader(dir / "d.ply");
        ASSERT_TRUE(reader.ok());
        EXPECT_EQ((*reader)->header().declaredPoints, report.points);
    }
}

TEST(SynthScan, DrumSidecarIsCompleteAndConsistent)
{
    TempDir dir;
    const SyntheticOptions o = coarse();
    const SyntheticReport report = generate(SyntheticKind::Drum, o, dir / "drum.ply");
    EXPECT_EQ(report.truthPath, dir / "drum.truth.json");
    const nlohmann::json t = readTruth(report.truthPath);
    for (const char* key : {"kind", "seed", "spacing", "noise", "scans", "points", "axis", "radius", "height",
                            "grooves", "clawBand", "broken", "anathyrosis", "pose", "stations"})
        EXPECT_TRUE(t.contains(key)) << key;
    EXPECT_EQ(t["kind"], "drum");
    EXPECT_EQ(t["seed"].get<std::uint64_t>(), o.seed);
    EXPECT_DOUBLE_EQ(t["spacing"].get<double>(), o.spacing);
    EXPECT_DOUBLE_EQ(t["noise"].get<double>(), o.noise);
    EXPECT_EQ(t["scans"].get<int>(), o.scans);
    EXPECT_EQ(t["stations"].size(), static_cast<std::size_t>(o.scans));
    EXPECT_EQ(t["grooves"]["count"].get<int>(), 48);
    EXPECT_DOUBLE_EQ(t["grooves"]["depth"].get<double>(), o.grooveDepth);
    EXPECT_DOUBLE_EQ(t["radius"].get<double>(), o.radius);
    EXPECT_LT(t["clawBand"]["vMin"].get<double>(), t["clawBand"]["vMax"].get<double>());
    EXPECT_LT(t["broken"]["thetaMin"].get<double>(), t["broken"]["thetaMax"].get<double>());

    const Eigen::Affine3d pose = poseOf(t);
    const Eigen::Matrix3d r = pose.linear();
    EXPECT_TRUE((r.transpose() * r).isIdentity(1e-12));
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
    EXPECT_GT(pose.translation().norm(), 1000.0); // a museum frame: large coordinates
    const Eigen::Vector3d direction(t["axis"]["direction"][0], t["axis"]["direction"][1], t["axis"]["direction"][2]);
    const Eigen::Vector3d point(t["axis"]["point"][0], t["axis"]["point"][1], t["axis"]["point"][2]);
    EXPECT_NEAR(direction.norm(), 1.0, 1e-12);
    EXPECT_TRUE(direction.isApprox(r.col(2), 1e-12));
    EXPECT_TRUE(point.isApprox(pose.translation(), 1e-12));
}

TEST(SynthScan, EveryKindsSidecarHasItsFields)
{
    TempDir dir;
    const std::pair<SyntheticKind, std::vector<const char*>> kinds[] = {
        {SyntheticKind::Omphalos, {"profile", "plinth", "ovoid", "net", "height"}},
        {SyntheticKind::Fragment, {"fragment", "radius", "height", "grooves", "clawBand", "anathyrosis"}}};
    for (const auto& [kind, keys] : kinds) {
        const SyntheticReport report = generate(kind, coarse(0.01), dir / "k.ply");
        const nlohmann::json t = readTruth(report.truthPath);
        for (const char* key : {"kind", "seed", "spacing", "noise", "scans", "points", "axis", "pose", "stations"})
            EXPECT_TRUE(t.contains(key)) << key;
        for (const char* key : keys) EXPECT_TRUE(t.contains(key)) << key;
        EXPECT_EQ(t["points"].get<std::uint64_t>(), report.points);
        EXPECT_GT(report.points, 1000u);
        const Eigen::Vector3d direction(t["axis"]["direction"][0], t["axis"]["direction"][1],
                                        t["axis"]["direction"][2]);
        EXPECT_NEAR(direction.norm(), 1.0, 1e-12);
    }
}

TEST(SynthScan, CancelLeavesNoFile)
{
    TempDir dir;
    SilentProgress cancelled;
    cancelled.cancel();
    auto r = generateScan(SyntheticKind::Drum, coarse(), dir / "c.ply", &cancelled);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::Cancelled);

    // Cancelled half-way, after whole batches were written.
    struct LateCancel final : ProgressSink {
        void update(double fraction) override { m_fraction = fraction; }
        bool isCancelRequested() const override { return m_fraction > 0.5; }
        double m_fraction = 0.0;
    } late;
    r = generateScan(SyntheticKind::Fragment, coarse(0.003), dir / "c.ply", &late);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::Cancelled);
    EXPECT_GT(late.m_fraction, 0.5);
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(SynthScan, ProgressReachesOne)
{
    TempDir dir;
    SilentProgress progress;
    ASSERT_TRUE(generateScan(SyntheticKind::Omphalos, coarse(0.01), dir / "p.ply", &progress).ok());
    EXPECT_DOUBLE_EQ(progress.last(), 1.0);
}

TEST(SynthScan, InvalidOptionsAreRefusedBeforeWriting)
{
    TempDir dir;
    auto refused = [&](SyntheticKind kind, const SyntheticOptions& o, const char* what) {
        auto r = generateScan(kind, o, dir / "bad.ply");
        ASSERT_FALSE(r.ok()) << what;
        EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument) << what;
        EXPECT_NE(r.error().message.find("bad.ply"), std::string::npos) << r.error().message;
    };
    SyntheticOptions o = coarse();
    for (const double s : {0.0, -0.001, std::nan(""), std::numeric_limits<double>::infinity(), 1e-5}) {
        o.spacing = s;
        refused(SyntheticKind::Drum, o, "spacing");
        refused(SyntheticKind::Omphalos, o, "spacing");
        refused(SyntheticKind::Fragment, o, "spacing");
    }
    o = coarse();
    o.scans = 0;
    refused(SyntheticKind::Drum, o, "no scans");
    o.scans = 256;
    refused(SyntheticKind::Drum, o, "scan ids are bytes");
    o = coarse();
    o.noise = -1e-4;
    refused(SyntheticKind::Omphalos, o, "negative noise");
    o = coarse();
    o.scanHalfAngle = 0.0;
    refused(SyntheticKind::Drum, o, "no window");
    o = coarse();
    o.grooveDepth = 0.0005; // shallower than the fillet circle's own sagitta: no concave flute
    refused(SyntheticKind::Drum, o, "flat flutes");
    o.grooveDepth = 0.2;
    refused(SyntheticKind::Fragment, o, "flutes deeper than a quarter of the radius");
    o = coarse();
    o.grooves = 2;
    refused(SyntheticKind::Drum, o, "two grooves");
    o = coarse();
    o.radius = -1.0;
    refused(SyntheticKind::Drum, o, "negative radius");
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(SynthScan, UnwritableOutputIsWriteFailed)
{
    TempDir dir;
    auto r = generateScan(SyntheticKind::Drum, coarse(0.01), dir / "missing" / "d.ply");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::WriteFailed);
}
