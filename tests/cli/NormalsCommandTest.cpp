// stylos-cli normals: a PLY with normals for every point, usage errors, bad input leaves nothing.
#include "CliRunner.h"
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using stylos::test::runCli;
using stylos::test::TempDir;

TEST(CliNormals, EstimatesNormalsForEveryPoint)
{
    TempDir dir;
    const auto scan = (dir / "drum.ply").string(), out = (dir / "drum-n.ply").string();
    ASSERT_EQ(runCli({"generate", "fragment", "-o", scan, "--spacing", "0.01"}).exitCode, 0);
    const auto run = runCli({"normals", scan, "-o", out, "--neighbours", "12", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    const auto info = runCli({"info", out, "--json"});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    const auto i = nlohmann::json::parse(info.out);
    EXPECT_EQ(i["points"], j["points"]);
    EXPECT_EQ(i["attributes"], (std::vector<std::string>{"normal", "scan_id"}));
    EXPECT_EQ(j["neighbours"], 12);
    // The generator's scans (stations with their registration errors) are kept apart, unless asked not to.
    EXPECT_GE(j["scans"].get<int>(), 2);
    EXPECT_EQ(j["scan_column"], "scan_id");
    const auto across = runCli({"normals", scan, "-o", out, "--across-scans", "--json"});
    ASSERT_EQ(across.exitCode, 0) << across.err;
    const auto a = nlohmann::json::parse(across.out);
    EXPECT_EQ(a["scans"], 0);
    EXPECT_EQ(a["scan_column"], "");
    const auto text = runCli({"normals", scan, "-o", out});
    ASSERT_EQ(text.exitCode, 0) << text.err;
    EXPECT_NE(text.out.find("each point's neighbours from its own scan (" + std::to_string(j["scans"].get<int>()) +
                            " scans, column scan_id)"), std::string::npos) << text.out;
}

TEST(CliNormals, UsageErrorsAndBadInput)
{
    TempDir dir;
    const auto out = (dir / "n.ply").string();
    EXPECT_EQ(runCli({"normals", "in.ply"}).exitCode, 2);
    EXPECT_EQ(runCli({"normals", "in.ply", "-o", out, "--neighbours", "2"}).exitCode, 2);
    EXPECT_EQ(runCli({"normals", "in.ply", "-o", out, "--viewpoint", "1,2"}).exitCode, 2);
    stylos::test::writeText(dir / "bad.ply", "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nend_header\n");
    const auto bad = runCli({"normals", (dir / "bad.ply").string(), "-o", out});
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("bad.ply"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1); // only bad.ply
}
