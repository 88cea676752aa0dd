// Synthetic scans against their truth sidecars: every point where the truth says the surface is.
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

/** Every point of a file, moved into the object frame with the truth's pose. */
struct Cloud {
    std::vector<Eigen::Vector3d> points;   ///< object frame
    std::vector<Eigen::Vector3d> normals;  ///< object frame (empty without normals)
    std::vector<int> scans;
    std::uint64_t count = 0;
};

nlohmann::json readTruth(const fs::path& path)
{
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

Cloud readCloud(const fs::path& path, const nlohmann::json& truth)
{
    auto reader = io::openPointReader(path);
    EXPECT_TRUE(reader.ok()) << (reader.ok() ? "" : reader.error().message);
    Cloud cloud;
    if (!reader.ok()) return cloud;
    const Eigen::Affine3d toObject = poseOf(truth).inverse();
    const auto& schema = (*reader)->header().schema;
    EXPECT_EQ(schema.scalarNames, std::vector<std::string>{"scan_id"});
    io::PointBatch batch;
    for (;;) {
        auto n = (*reader)->read(batch, 50000);
        EXPECT_TRUE(n.ok());
        if (!n.ok() || *n == 0) break;
        for (std::size_t i = 0; i < *n; ++i) {
            const Eigen::Vector3d p(batch.positions[3 * i], batch.positions[3 * i + 1], batch.positions[3 * i + 2]);
            cloud.points.push_back(toObject * p);
            cloud.scans.push_back(static_cast<int>(batch.scalars[0][i]));
            if (schema.hasNormals)
                cloud.normals.push_back(toObject.linear() * Eigen::Vector3d(batch.normals[3 * i],
                                                                             batch.normals[3 * i + 1],
                                                                             batch.normals[3 * i + 2]));
        }
    }
    cloud.count = cloud.points.size();
    return cloud;
}

/** Tolerance for noise and registration, metres. */
double slack(const nlohmann::json& truth)
{
    return truth["noiseClamp"].get<double>() + truth["registrationBound"].get<double>() + 1e-6;
}

} // namespace

TEST(SynthTruth, DrumPointsLieWithinTheTruthBounds)
{
    TempDir dir;
    const SyntheticReport report = generate(SyntheticKind::Drum, coarse(), dir / "d.ply");
    const nlohmann::json t = readTruth(report.truthPath);
    const Cloud cloud = readCloud(dir / "d.ply", t);
    const double radius = t["radius"].get<double>();
    const double height = t["height"].get<double>();
    const double tol = slack(t);
    const double deepest = std::max(t["grooves"]["depth"].get<double>() + t["clawBand"]["depth"].get<double>(),
                                    t["broken"]["maxDepth"].get<double>());
    const double bedDepth = t["anathyrosis"]["maxDepth"].get<double>();
    std::vector<std::size_t> perScan(3, 0);
    for (std::size_t i = 0; i < cloud.count; ++i) {
        const Eigen::Vector3d& p = cloud.points[i];
        const double r = p.head<2>().norm();
        ASSERT_GE(p.z(), -tol);
        ASSERT_LE(p.z(), height + tol);
        ASSERT_LE(r, radius + tol);
        if (p.z() > bedDepth + tol && p.z() < height - bedDepth - tol) { // not a bed-face point
            ASSERT_GE(r, radius - deepest - tol) << p.transpose();
        }
        ASSERT_GE(cloud.scans[i], 0);
        ASSERT_LT(cloud.scans[i], 3);
        ++perScan[static_cast<std::size_t>(cloud.scans[i])];
        // Each scan sees only its own window of azimuths.
        const double view = t["stations"][cloud.scans[i]]["viewAzimuth"].get<double>();
        // Jitter of a quarter step, noise and registration may carry a point slightly out of it.
        const double reach = t["scanHalfAngle"].get<double>() + (0.26 * t["spacing"].get<double>() + tol) / r;
        if (r > 0.05) {
            ASSERT_LE(std::fabs(std::remainder(std::atan2(p.y(), p.x()) - view, kTwoPi)), reach);
        }
    }
    for (const std::size_t n : perScan) EXPECT_GT(n, cloud.count / 5);
}

/** Counts the flutes seen in the points: runs of azimuth bins whose mean radius is below R - depth/2. */
int countGrooves(const Cloud& cloud, const nlohmann::json& t, int bins, double* firstCentre)
{
    const double radius = t["radius"].get<double>();
    const double depth = t["grooves"]["depth"].get<double>();
    std::vector<double> sum(static_cast<std::size_t>(bins), 0.0);
    std::vector<int> count(static_cast<std::size_t>(bins), 0);
    for (const Eigen::Vector3d& p : cloud.points) {
        // Lateral points away from the beds and below the broken region and the claw band.
        if (p.z() < 0.02 || p.z() > t["broken"]["zMin"].get<double>() - 0.01) continue;
        const double r = p.head<2>().norm();
        if (r < radius - 2.0 * depth) continue;
        double theta = std::atan2(p.y(), p.x());
        if (theta < 0.0) theta += kTwoPi;
        const auto bin = std::min(bins - 1, static_cast<int>(theta / kTwoPi * bins));
        sum[static_cast<std::size_t>(bin)] += r;
        ++count[static_cast<std::size_t>(bin)];
    }
    std::vector<bool> deep(static_cast<std::size_t>(bins));
    for (int i = 0; i < bins; ++i) {
        EXPECT_GT(count[static_cast<std::size_t>(i)], 0) << "empty bin " << i;
        deep[static_cast<std::size_t>(i)] = sum[static_cast<std::size_t>(i)] / count[static_cast<std::size_t>(i)]
                                            < radius - 0.5 * depth;
    }
    int runs = 0;
    int start = -1;
    for (int i = 0; i < bins; ++i) {
        const bool now = deep[static_cast<std::size_t>(i)];
        const bool before = deep[static_cast<std::size_t>((i + bins - 1) % bins)];
        if (now && !before) {
            ++runs;
            if (start < 0) start = i;
        }
        if (!now && before && start >= 0 && firstCentre && *firstCentre < 0.0)
            *firstCentre = 0.5 * (start + i) / bins * kTwoPi;
    }
    return runs;
}

TEST(SynthTruth, DrumHasTheTruthsFlutesAtTheTruthsPhase)
{
    TempDir dir;
    for (const auto& [grooves, depth] : {std::pair{48, 0.008}, std::pair{20, 0.012}}) {
        SyntheticOptions o = coarse(0.003);
        o.grooves = grooves;
        o.grooveDepth = depth;
        const SyntheticReport report = generate(SyntheticKind::Drum, o, dir / "d.ply");
        const nlohmann::json t = readTruth(report.truthPath);
        const Cloud cloud = readCloud(dir / "d.ply", t);
        double centre = -1.0;
        EXPECT_EQ(countGrooves(cloud, t, grooves * 12, &centre), grooves);
        // That flute's centre sits on a groove of the truth: phase + k·pitch.
        const double pitch = t["grooves"]["pitch"].get<double>();
        const double phase = t["grooves"]["phase"].get<double>();
        EXPECT_NEAR(std::remainder(centre - phase, pitch), 0.0, 1.5 * kTwoPi / (grooves * 12)) << grooves;
    }
}

TEST(SynthTruth, NormalsAreTheSurfaces)
{
    TempDir dir;
    SyntheticOptions o = coarse(0.008);
    o.writeNormals = true;
    const SyntheticReport report = generate(SyntheticKind::Drum, o, dir / "n.ply");
    const nlohmann::json t = readTruth(report.truthPath);
    const Cloud cloud = readCloud(dir / "n.ply", t);
    ASSERT_EQ(cloud.normals.size(), cloud.count);
    const double height = t["height"].get<double>();
    const double radius = t["radius"].get<double>();
    const double ring = t["anathyrosis"]["ringWidth"].get<double>();
    for (std::size_t i = 0; i < cloud.count; ++i) {
        const Eigen::Vector3d& p = cloud.points[i];
        const Eigen::Vector3d& n = cloud.normals[i];
        ASSERT_NEAR(n.norm(), 1.0, 1e-5);
        const Eigen::Vector3d radial = Eigen::Vector3d(p.x(), p.y(), 0.0).normalized();
        const double rho = p.head<2>().norm();
        if (p.z() > 0.02 && p.z() < t["broken"]["zMin"].get<double>() - 0.01) {
            ASSERT_GT(n.dot(radial), 0.85); // lateral: outwards, tilted at most by the flutes' sides
        }
        if (rho < 0.3) { // bed faces: point-dressed recess, outwards
            ASSERT_GT(std::fabs(n.z()), 0.8);
            ASSERT_EQ(n.z() > 0.0, p.z() > 0.5 * height);
        }
        if (rho > radius - ring + 0.01 && rho < radius - 0.02 && (p.z() < 0.01 || p.z() > height - 0.01)) {
            ASSERT_GT(std::fabs(n.z()), 0.9999); // the smooth contact ring
        }
    }
}

TEST(SynthTruth, OmphalosFollowsItsProfileWithARaisedNet)
{
    TempDir dir;
    const SyntheticReport report = generate(SyntheticKind::Omphalos, coarse(), dir / "o.ply");
    const nlohmann::json t = readTruth(report.truthPath);
    EXPECT_EQ(t["kind"], "omphalos");
    const auto& zs = t["profile"]["z"];
    const auto& rs = t["profile"]["r"];
    ASSERT_EQ(zs.size(), rs.size());
    ASSERT_GT(zs.size(), 100u);
    EXPECT_NEAR(t["height"].get<double>(), 1.2, 0.1);
    EXPECT_DOUBLE_EQ(rs.back().get<double>(), 0.0);
    const Cloud cloud = readCloud(dir / "o.ply", t);
    const double tol = slack(t) + 2e-5;
    const double band = t["net"]["bandHeight"].get<double>();
    const double z0 = zs.front().get<double>();
    const double dz = zs[1].get<double>() - z0;
    std::size_t body = 0;
    std::size_t raised = 0;
    for (const Eigen::Vector3d& p : cloud.points) {
        ASSERT_LE(p.head<2>().norm(), t["plinth"]["radius"].get<double>() + tol);
        ASSERT_LE(p.z(), t["height"].get<double>() + tol);
        if (p.z() < z0 + 0.05 || p.z() > t["net"]["zMax"].get<double>()) continue;
        const double x = (p.z() - z0) / dz;
        const auto i = static_cast<std::size_t>(x);
        const double profile = rs[i].get<double>() + (x - i) * (rs[i + 1].get<double>() - rs[i].get<double>());
        const double offset = p.head<2>().norm() - profile;
        ASSERT_GE(offset, -tol) << p.transpose();
        ASSERT_LE(offset, 2.0 * band + tol) << p.transpose();
        ++body;
        if (offset > 0.6 * band) ++raised;
    }
    ASSERT_GT(body, cloud.count / 2);
    EXPECT_GT(raised, body / 20); // the net covers part of the ovoid...
    EXPECT_LT(raised, body / 2);  // ...and leaves lozenges of bare stone between its bands
}

TEST(SynthTruth, FragmentLiesInItsSectorOfTheDrum)
{
    TempDir dir;
    const SyntheticReport report = generate(SyntheticKind::Fragment, coarse(0.003), dir / "f.ply");
    const nlohmann::json t = readTruth(report.truthPath);
    EXPECT_EQ(t["kind"], "fragment");
    const nlohmann::json& f = t["fragment"];
    Eigen::Matrix4d m;
    for (int i = 0; i < 16; ++i) m(i / 4, i % 4) = f["poseInDrum"][i].get<double>();
    EXPECT_TRUE((m * poseOf(t).matrix()).isIdentity(1e-9));

    const Cloud cloud = readCloud(dir / "f.ply", t);
    const double tol = slack(t);
    const double radius = t["radius"].get<double>();
    const double depth = t["grooves"]["depth"].get<double>();
    const double rough = f["fractureBound"].get<double>();
    const double inner = f["innerRadius"].get<double>();
    std::size_t outer = 0, top = 0, innerFace = 0, bottom = 0;
    for (const Eigen::Vector3d& p : cloud.points) {
        const double r = p.head<2>().norm();
        const double dTheta = std::remainder(std::atan2(p.y(), p.x()) - f["thetaCentre"].get<double>(), kTwoPi);
        ASSERT_LE(r, radius + tol);
        ASSERT_GE(r, inner - rough - tol);
        ASSERT_LE(p.z(), t["height"].get<double>() + tol);
        ASSERT_GE(p.z(), f["zMin"].get<double>() - rough - tol);
        ASSERT_LE(std::fabs(dTheta), f["halfAngle"].get<double>() + (rough + tol) / inner);
        const bool clearOfFractures = std::fabs(dTheta) < f["halfAngle"].get<double>() - (rough + tol) / inner &&
                                      p.z() > f["zMin"].get<double>() + rough + tol;
        if (clearOfFractures && r > radius - depth - tol && p.z() < t["height"].get<double>() - 0.003) {
            ++outer; // the fluted outer face: its flutes are the drum's
            const double phi = std::remainder(std::atan2(p.y(), p.x()) - t["grooves"]["phase"].get<double>(),
                                              t["grooves"]["pitch"].get<double>());
            if (r < radius - 0.5 * depth) {
                ASSERT_LT(std::fabs(phi), t["grooves"]["halfWidth"].get<double>());
            }
        }
        if (p.z() > t["height"].get<double>() - 0.003 - tol) ++top;
        if (r < inner + rough + tol) ++innerFace;
        if (p.z() < f["zMin"].get<double>() + rough + tol) ++bottom;
    }
    EXPECT_GT(outer, cloud.count / 10);
    EXPECT_GT(top, cloud.count / 20);
    EXPECT_GT(innerFace, cloud.count / 20);
    EXPECT_GT(bottom, cloud.count / 20);
}
