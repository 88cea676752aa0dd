// stylos-cli dock: a generated fragment docked against a generated drum of the same design gives the
// contract's keys, a rotation, z unobservable, and lands on the true pose from a start turned by 2° about
// the axis; --guides is used, locks hold; a missing drum, a plain fragment, a far start and bad options fail
// naming the problem.
#include "CliRunner.h"
#include "TestSupport.h"

#include "stylos/core/io/ImportFrame.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <iomanip>

using stylos::test::runCli;
using stylos::test::TempDir;

namespace {

Eigen::Affine3d poseOf(const std::filesystem::path& truth)
{
    const auto j = nlohmann::json::parse(std::ifstream(truth));
    Eigen::Matrix4d m;
    for (int i = 0; i < 16; ++i) m(i / 4, i % 4) = j["pose"][std::size_t(i)].get<double>();
    return Eigen::Affine3d(m);
}

std::string poseArgument(const Eigen::Affine3d& a)
{
    std::ostringstream s;
    s.precision(17);
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) s << a.linear()(i, k) << ",";
    s << a.translation().x() << "," << a.translation().y() << "," << a.translation().z();
    return s.str();
}

struct Scene {
    TempDir dir;
    std::string drum, fragment, guides;
    Eigen::Affine3d truth;
    Eigen::Vector3d axisPoint, axisDir;

    Scene()
    {
        drum = (dir / "drum.ply").string();
        fragment = (dir / "fragment.ply").string();
        guides = (dir / "guides.json").string();
        EXPECT_EQ(runCli({"generate", "drum", "-o", drum, "--spacing", "0.004", "--seed", "101", "--design-seed", "21"}).exitCode, 0);
        EXPECT_EQ(runCli({"generate", "fragment", "-o", fragment, "--spacing", "0.003", "--seed", "5", "--design-seed", "21"}).exitCode, 0);
        const auto g = runCli({"guides", drum, "-o", guides, "--json"});
        EXPECT_EQ(g.exitCode, 0) << g.err;
        const auto j = nlohmann::json::parse(g.out);
        for (int k = 0; k < 3; ++k) axisPoint[k] = j["axis_point"][std::size_t(k)], axisDir[k] = j["axis_dir"][std::size_t(k)];
        truth = poseOf(dir / "drum.truth.json") * poseOf(dir / "fragment.truth.json").inverse();
    }

    /** The true pose turned by @p degrees about the drum's axis. */
    Eigen::Affine3d turned(double degrees) const
    {
        return Eigen::Translation3d(axisPoint) * Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, axisDir) *
               Eigen::Translation3d(-axisPoint) * truth;
    }
};

const Scene& scene()
{
    static Scene s;
    return s;
}

Eigen::Affine3d poseFromJson(const nlohmann::json& j)
{
    Eigen::Affine3d a = Eigen::Affine3d::Identity();
    for (int i = 0; i < 9; ++i) a.linear()(i / 3, i % 3) = j["rotation"][std::size_t(i)].get<double>();
    for (int k = 0; k < 3; ++k) a.translation()[k] = j["translation"][std::size_t(k)].get<double>();
    return a;
}

double angleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
    return Eigen::AngleAxisd(a * b.transpose()).angle() * 180.0 / std::numbers::pi;
}

} // namespace

TEST(CliDock, DocksOnTheTruePoseWithTheContractKeys)
{
    const Scene& s = scene();
    const auto run = runCli({"dock", s.fragment, "--drum", s.drum, "--guides", s.guides, "--pose",
                             poseArgument(s.turned(2.0)), "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    const std::vector<std::string> keys{"rotation", "translation", "rms_mm", "flute_shift", "unobservable",
                                        "uncertainty", "iterations", "seconds"};
    EXPECT_EQ(j.size(), keys.size());
    for (const auto& key : keys) EXPECT_TRUE(j.contains(key)) << key;
    ASSERT_EQ(j["rotation"].size(), 9u);
    ASSERT_EQ(j["translation"].size(), 3u);
    EXPECT_EQ(j["unobservable"], nlohmann::json::array({"z"}));
    for (const char* u : {"theta", "r", "tangent", "tilt_lean", "tilt_roll"}) EXPECT_TRUE(j["uncertainty"].contains(u)) << u;
    EXPECT_FALSE(j["uncertainty"].contains("z"));
    const Eigen::Affine3d docked = poseFromJson(j);
    EXPECT_TRUE((docked.linear().transpose() * docked.linear()).isApprox(Eigen::Matrix3d::Identity(), 1e-9));
    // Three scans with registration offsets (≤ 0.05°, 0.3 mm) on each side: the nominal truth within 0.1°.
    EXPECT_LT(angleDeg(docked.linear(), s.truth.linear()), 0.1);
    EXPECT_NEAR(j["flute_shift"].get<double>(), -2.0 / 7.5, 0.02); // turned back by 2° of a 7.5° pitch
    EXPECT_GT(j["rms_mm"].get<double>(), 0.1);
    EXPECT_LT(j["rms_mm"].get<double>(), 0.4);
}

TEST(CliDock, LockedRotationStaysAndWithoutGuidesTheDrumIsFitted)
{
    const Scene& s = scene();
    const Eigen::Affine3d start = s.turned(0.5);
    const auto run = runCli({"dock", s.fragment, "--drum", s.drum, "--pose", poseArgument(start), "--lock", "theta,tilt", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    EXPECT_LT(angleDeg(poseFromJson(j).linear(), start.linear()), 1e-9);
    EXPECT_EQ(j["uncertainty"].size(), 1u); // r: theta locks the place round the drum, the sideways slide with the turn
}

TEST(CliDock, BadInputFailsNamingTheProblem)
{
    const Scene& s = scene();
    TempDir dir;
    auto run = runCli({"dock", s.fragment, "--drum", (dir / "missing.ply").string()});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("missing.ply: no such file"), std::string::npos) << run.err;

    run = runCli({"dock", s.fragment, "--drum", s.drum, "--guides", s.guides}); // identity start: metres away
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("too far from the drum"), std::string::npos) << run.err;

    // With --guides the drum's points are not needed, but the file must still be a cloud (it names the frame).
    std::ofstream(dir / "junk.ply") << "hello\n";
    std::filesystem::create_directory(dir / "folder.ply");
    run = runCli({"dock", s.fragment, "--drum", (dir / "junk.ply").string(), "--guides", s.guides});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("junk.ply: byte 0: not a PLY file"), std::string::npos) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    run = runCli({"dock", s.fragment, "--drum", (dir / "folder.ply").string(), "--guides", s.guides});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("folder.ply: is a directory"), std::string::npos) << run.err;

    std::ofstream(dir / "bad.json") << "{\"axis_point\": [0, 0]}";
    run = runCli({"dock", s.fragment, "--drum", s.drum, "--guides", (dir / "bad.json").string()});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("bad.json: axis_point must be 3 finite numbers"), std::string::npos) << run.err;

    EXPECT_EQ(runCli({"dock", s.fragment}).exitCode, 2);
    EXPECT_EQ(runCli({"dock", s.fragment, "--drum", s.drum, "--lock", "yaw"}).exitCode, 2);
    run = runCli({"dock", s.fragment, "--drum", s.drum, "--pose", "1,0,0,0,1,0,0,0,2,0,0,0"});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("--pose: the first nine numbers are not a rotation: their rows are off orthonormal by 3 "
                           "(at most 1e-04 is taken)"), std::string::npos) << run.err;
    run = runCli({"dock", s.fragment, "--drum", s.drum, "--pose", "-1,0,0,0,1,0,0,0,1,0,0,0"});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("not a rotation (determinant -1, not +1)"), std::string::npos) << run.err;
    EXPECT_EQ(runCli({"dock", s.fragment, "--drum", s.drum, "--pose", "1,0,0"}).exitCode, 2);
    // Not numbers: a trailing comma (an empty twelfth), hexadecimal (strtod took both).
    run = runCli({"dock", s.fragment, "--drum", s.drum, "--pose", "1,0,0,0,1,0,0,0,1,0,0,0,"});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("--pose: \"\" is not a number"), std::string::npos) << run.err;
    run = runCli({"dock", s.fragment, "--drum", s.drum, "--pose", "1, 0,0,0,1,0,0,0,1 ,0x10,0,0"}); // spaces are fine
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("--pose: \"0x10\" is not a number"), std::string::npos) << run.err;
    // Lock names with spaces, as the number lists take them: taken.
    run = runCli({"dock", s.fragment, "--drum", s.drum, "--guides", s.guides, "--pose", poseArgument(s.turned(0.5)),
                  "--lock", "theta, tilt", "--json"});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    // θ locked 3° (0.4 flute) from its place: the registration does not settle, and says θ may be why.
    run = runCli({"dock", s.fragment, "--drum", s.drum, "--guides", s.guides, "--pose", poseArgument(s.turned(3.0)),
                  "--lock", "theta"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("did not converge in 60 iterations; θ is locked and may hold it off its flute: free θ, or "
                           "start it on its flute"), std::string::npos) << run.err;
    // A lock that names nothing.
    for (const char* lock : {"", "r,"}) {
        run = runCli({"dock", s.fragment, "--drum", s.drum, "--lock", lock});
        EXPECT_EQ(run.exitCode, 2) << lock;
        EXPECT_NE(run.err.find("--lock: unknown \"\""), std::string::npos) << run.err;
    }
}

// A fragment held 1.5° off its place by Lock θ ends far off the flute profile: said on stderr, with the drum's own RMS;
// a good dock says nothing of the kind.
TEST(CliDock, APoorDockIsSaid)
{
    const Scene& s = scene();
    const auto held = runCli({"dock", s.fragment, "--drum", s.drum, "--guides", s.guides, "--pose",
                              poseArgument(s.turned(1.5)), "--lock", "theta", "--json"});
    ASSERT_EQ(held.exitCode, 0) << held.err;
    EXPECT_NE(held.err.find(" mm RMS from the flute profile, "), std::string::npos) << held.err;
    EXPECT_NE(held.err.find("times the drum's own"), std::string::npos) << held.err;
    EXPECT_GT(nlohmann::json::parse(held.out)["rms_mm"].get<double>(), 1.0); // the JSON as before
    const auto good = runCli({"dock", s.fragment, "--drum", s.drum, "--guides", s.guides, "--pose",
                              poseArgument(s.turned(2.0)), "--json"});
    ASSERT_EQ(good.exitCode, 0) << good.err;
    EXPECT_EQ(good.err.find("RMS from the flute profile"), std::string::npos) << good.err;
}

// A pose as other tools print it, to 6 decimals (its rows off orthonormal by ~1e-6), is taken and made a rotation: it
// docks as the exact one does (it was refused as "not a rotation").
TEST(CliDock, APoseToSixDecimalsIsTaken)
{
    const Scene& s = scene();
    const Eigen::Affine3d start = s.turned(2.0);
    std::ostringstream rounded;
    rounded << std::fixed << std::setprecision(6);
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) rounded << start.linear()(i, k) << ", "; // spaces after the commas, as typed
    rounded << start.translation().x() << ", " << start.translation().y() << ", " << start.translation().z();
    const auto run = runCli({"dock", s.fragment, "--drum", s.drum, "--guides", s.guides, "--pose", rounded.str(), "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    const Eigen::Affine3d docked = poseFromJson(j);
    EXPECT_TRUE((docked.linear().transpose() * docked.linear()).isApprox(Eigen::Matrix3d::Identity(), 1e-9));
    EXPECT_LT(angleDeg(docked.linear(), s.truth.linear()), 0.1);
    EXPECT_NEAR(j["flute_shift"].get<double>(), -2.0 / 7.5, 0.02);
}

TEST(CliDock, TheImportFrameAppliesToBothPointFiles)
{
    // Read Y-up (--up +Y turns both files by the same R), the dock is the same one seen in the turned frame:
    // R·P·Rᵀ from R·start·Rᵀ.
    const Scene& s = scene();
    const std::array<double, 9> r = stylos::core::io::ImportFrame{stylos::core::io::UpAxis::PosY}.rotation();
    Eigen::Affine3d rot = Eigen::Affine3d::Identity();
    for (int i = 0; i < 9; ++i) rot.linear()(i / 3, i % 3) = r[std::size_t(i)];
    const Eigen::Affine3d start = s.turned(2.0);
    const auto plain = runCli({"dock", s.fragment, "--drum", s.drum, "--pose", poseArgument(start), "--json"});
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    const auto framed = runCli({"dock", s.fragment, "--drum", s.drum, "--up", "+Y", "--pose",
                                poseArgument(rot * start * rot.inverse()), "--json"});
    ASSERT_EQ(framed.exitCode, 0) << framed.err;
    const Eigen::Affine3d expected = rot * poseFromJson(nlohmann::json::parse(plain.out)) * rot.inverse();
    const Eigen::Affine3d docked = poseFromJson(nlohmann::json::parse(framed.out));
    EXPECT_LT(angleDeg(docked.linear(), expected.linear()), 1e-3);
    EXPECT_LT((docked.translation() - expected.translation()).norm(), 2e-4); // 0.2 mm: the solve's own tolerance

    // Two octrees are already in their frame: the options are refused, naming both.
    TempDir dir;
    const std::string a = (dir / "a.poct").string(), b = (dir / "b.poct").string();
    for (const std::string& f : {a, b}) std::ofstream(f, std::ios::binary) << "\x89POCT\r\n\x1a\n"; // the signature
    const auto refused = runCli({"dock", a, "--drum", b, "--unit", "mm"});
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_NE(refused.err.find("--up, --unit and --offset apply to point-file inputs only, and both " + a + " and " + b +
                               " are octrees"),
              std::string::npos)
        << refused.err;
    const auto badUnit = runCli({"dock", s.fragment, "--drum", s.drum, "--unit", "inch"});
    EXPECT_EQ(badUnit.exitCode, 2);
    EXPECT_NE(badUnit.err.find("--unit must be one of"), std::string::npos) << badUnit.err;
}
