// --up, --unit and --offset on the commands that read points: the bounds `info` gives, the octree `build`
// writes, the axis `unroll` fits, all in the corrected frame (Z up, metres); a value off the lists is a usage
// error (exit 2) naming the option and the value, on every command; they do not apply to a .poct.
#include "CliRunner.h"
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>

using stylos::test::runCli;
using stylos::test::TempDir;

namespace {

/** Three points in millimetres, Y up in the file, with unit normals. */
const char* yUpMillimetres = "# x y z nx ny nz\n"
                             "1000 2000 3000 0 1 0\n"
                             "-500 250 125 0.6 0 0.8\n"
                             "0 0 0 0 0 1\n";

TEST(CliImportFrame, InfoGivesTheBoundsInTheCorrectedFrame)
{
    TempDir dir;
    stylos::test::writeText(dir / "scan.xyz", yUpMillimetres);
    const auto run = runCli({"info", (dir / "scan.xyz").string(), "--up", "+Y", "--unit", "mm", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    // (x, y, z) mm → (x, −z, y) m
    EXPECT_EQ(j["bounds"]["min"], (std::vector<double>{-0.5, -3, 0}));
    EXPECT_EQ(j["bounds"]["max"], (std::vector<double>{1, 0, 2}));
    EXPECT_EQ(j["points"], 3);

    // The offset goes first, in the file's units; "y" is "+Y".
    const auto shifted = runCli({"info", (dir / "scan.xyz").string(), "--up", "y", "--unit", "mm",
                                 "--offset=1000,2000,3000", "--json"});
    ASSERT_EQ(shifted.exitCode, 0) << shifted.err;
    const auto k = nlohmann::json::parse(shifted.out);
    EXPECT_EQ(k["bounds"]["min"], (std::vector<double>{-1.5, 0, -2}));
    EXPECT_EQ(k["bounds"]["max"], (std::vector<double>{0, 3, 0}));
}

TEST(CliImportFrame, BuildWritesTheOctreeInTheCorrectedFrame)
{
    TempDir dir;
    stylos::test::writeText(dir / "scan.xyz", yUpMillimetres);
    const auto out = (dir / "scan.poct").string();
    const auto run = runCli({"build", (dir / "scan.xyz").string(), "-o", out, "--depth", "4", "--up", "+Y",
                             "--unit", "mm", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto info = runCli({"info", out, "--json"});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    const auto j = nlohmann::json::parse(info.out);
    // The root box: the cube around x −0.5..1, y −3..0, z 0..2 — edge 3, centred on (0.25, −1.5, 1).
    EXPECT_EQ(j["root_box"]["size"], 3.0) << info.out;
    EXPECT_EQ(j["root_box"]["origin"], (std::vector<double>{0.25 - 1.5, -1.5 - 1.5, 1.0 - 1.5})) << info.out;
}

TEST(CliImportFrame, UnrollFitsTheAxisOfTheTurnedAndScaledDrum)
{
    TempDir dir;
    const auto scan = (dir / "drum.ply").string();
    ASSERT_EQ(runCli({"generate", "drum", "-o", scan, "--spacing", "0.02", "--seed", "3"}).exitCode, 0);
    const auto plain = runCli({"unroll", scan, "-o", (dir / "plain.png").string(), "--shading", "height", "--json"});
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    // +X up: the drum's axis (Z in the file) becomes X; centimetres: a hundred times smaller.
    const auto turned = runCli({"unroll", scan, "-o", (dir / "turned.png").string(), "--shading", "height", "--up",
                                "+X", "--unit", "cm", "--json"});
    ASSERT_EQ(turned.exitCode, 0) << turned.err;
    const auto p = nlohmann::json::parse(plain.out), t = nlohmann::json::parse(turned.out);
    // The axis fitted in the file (nearly Z) turned by (x, y, z) → (−z, y, x), up to its sign.
    const std::array<double, 3> d{p["axis_dir"][0], p["axis_dir"][1], p["axis_dir"][2]};
    const std::array<double, 3> e{t["axis_dir"][0], t["axis_dir"][1], t["axis_dir"][2]};
    EXPECT_GT(std::abs(d[2]), 0.99);
    const double sign = e[0] * -d[2] > 0 ? 1.0 : -1.0;
    EXPECT_NEAR(sign * e[0], -d[2], 1e-3);  // the fit converges within 0.1 mrad either way
    EXPECT_NEAR(sign * e[1], d[1], 1e-3);
    EXPECT_NEAR(sign * e[2], d[0], 1e-3);
    EXPECT_NEAR(t["radius"].get<double>() * 100.0, p["radius"].get<double>(), 1e-3 * p["radius"].get<double>());
    EXPECT_EQ(t["points"], p["points"]);
}

TEST(CliImportFrame, ABadAxisOrUnitIsAUsageErrorNamingItOnEveryCommand)
{
    TempDir dir;
    stylos::test::writeText(dir / "scan.xyz", yUpMillimetres);
    const std::string in = (dir / "scan.xyz").string();
    const std::vector<std::vector<std::string>> commands = {
        {"info", in},
        {"build", in, "-o", (dir / "o.poct").string()},
        {"normals", in, "-o", (dir / "o.ply").string()},
        {"ao", in, "-o", (dir / "o.ply").string()},
        {"unroll", in, "-o", (dir / "o.png").string()},
        {"guides", in, "-o", (dir / "o.json").string()},
    };
    for (const auto& command : commands) {
        auto up = command;
        up.insert(up.end(), {"--up", "w"});
        const auto badUp = runCli(up);
        EXPECT_EQ(badUp.exitCode, 2) << command[0];
        EXPECT_NE(badUp.err.find("--up must be one of +X, -X, +Y, -Y, +Z or -Z, not \"w\""), std::string::npos)
            << command[0] << ": " << badUp.err;
        auto unit = command;
        unit.insert(unit.end(), {"--unit", "inch"});
        const auto badUnit = runCli(unit);
        EXPECT_EQ(badUnit.exitCode, 2) << command[0];
        EXPECT_NE(badUnit.err.find("--unit must be one of mm, cm or m, not \"inch\""), std::string::npos)
            << command[0] << ": " << badUnit.err;
        auto offset = command;
        offset.insert(offset.end(), {"--offset", "1,2"});
        const auto badOffset = runCli(offset);
        EXPECT_EQ(badOffset.exitCode, 2) << command[0];
        EXPECT_NE(badOffset.err.find("--offset needs 3 numbers, got 2"), std::string::npos)
            << command[0] << ": " << badOffset.err;
    }
    EXPECT_EQ(runCli({"build", "--synthetic-drum", "1000", "-o", (dir / "s.poct").string(), "--up", "y"}).exitCode, 2);
}

TEST(CliImportFrame, AnOctreeIsNotTurnedAgain)
{
    TempDir dir;
    stylos::test::writeText(dir / "scan.xyz", yUpMillimetres);
    const auto poct = (dir / "scan.poct").string();
    ASSERT_EQ(runCli({"build", (dir / "scan.xyz").string(), "-o", poct, "--depth", "3"}).exitCode, 0);
    for (const auto& command : std::vector<std::vector<std::string>>{
             {"info", poct, "--up", "+Y"},
             {"ao", poct, "-o", (dir / "o.ply").string(), "--unit", "mm"},
             {"unroll", poct, "-o", (dir / "o.png").string(), "--up", "+X"},
             {"guides", poct, "-o", (dir / "o.json").string(), "--offset", "1,2,3"}}) {
        const auto run = runCli(command);
        EXPECT_EQ(run.exitCode, 2) << command[0];
        EXPECT_NE(run.err.find(poct), std::string::npos) << command[0] << ": " << run.err;
    }
}

} // namespace
