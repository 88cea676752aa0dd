// stylos-cli info: JSON contract, every shared fixture with its exact count, errors and exit codes.
#include "CliRunner.h"
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <nlohmann/json.hpp>

using stylos::test::runCli;
using stylos::test::TempDir;

namespace {
const char* tinyPly = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n"
                      "0 0 0 1 2 3\n1 -2 0.5 4 5 6\n0.25 1 2 7 8 9\n";
}

TEST(CliInfo, JsonFollowsTheContract)
{
    TempDir dir;
    stylos::test::writeText(dir / "t.ply", tinyPly);
    const auto run = runCli({"info", (dir / "t.ply").string(), "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["format"], "ply-ascii");
    EXPECT_EQ(j["points"], 3);
    EXPECT_EQ(j["bounds"]["min"], (std::vector<double>{0, -2, 0}));
    EXPECT_EQ(j["bounds"]["max"], (std::vector<double>{1, 1, 2}));
    EXPECT_EQ(j["attributes"], (std::vector<std::string>{"color"}));
}

TEST(CliInfo, TextOutputAndHelp)
{
    TempDir dir;
    stylos::test::writeText(dir / "t.ply", tinyPly);
    const auto run = runCli({"info", (dir / "t.ply").string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("points:     3"), std::string::npos) << run.out;
    const auto help = runCli({"info", "--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("usage: stylos-cli info"), std::string::npos);
}

TEST(CliInfo, UsageErrorsExitWithTwo)
{
    EXPECT_EQ(runCli({}).exitCode, 2);
    EXPECT_EQ(runCli({"frobnicate"}).exitCode, 2);
    EXPECT_EQ(runCli({"info"}).exitCode, 2);
    EXPECT_EQ(runCli({"info", "a.ply", "b.ply"}).exitCode, 2);
    const auto unknown = runCli({"info", "a.ply", "--bogus"});
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_NE(unknown.err.find("--bogus"), std::string::npos);
}

TEST(CliInfo, BadFilesExitWithOneAndOneLineNamingTheFile)
{
    TempDir dir;
    std::string truncated(tinyPly);
    truncated.resize(truncated.size() - 12);
    stylos::test::writeText(dir / "cut.ply", truncated);
    stylos::test::writeText(dir / "empty.xyz", "");
    stylos::test::writeText(dir / "what.bin", "\x01\x02\x03 not a point file");
    for (const auto& name : {"cut.ply", "empty.xyz", "what.bin", "missing.ply"}) {
        const auto path = (dir / name).string();
        const auto run = runCli({"info", path, "--json"});
        EXPECT_EQ(run.exitCode, 1) << name;
        EXPECT_TRUE(run.out.empty()) << name << ": partial output " << run.out;
        EXPECT_NE(run.err.find(path), std::string::npos) << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    }
}

TEST(CliInfo, EverySharedFixtureWithItsHeaderCount)
{
    SKIP_WITHOUT_SHARED_DATA();
    const auto data = stylos::test::sharedData();
    const std::vector<std::pair<std::string, std::uint64_t>> files = {
        {"scans/happy_buddha_1.1M.ply", 1099005},
        {"scans/lion_takanawa_342k.ply", 341989},
        {"scans/igea_134k.ply", 134345},
        {"formats/autzen_trim.las", 110000},
        {"formats/mvk-thin.las", 6280},
        {"formats/cgal_kitten.xyz", 5210},
        {"formats/pdal_test.pts", 19},
        {"formats/bun000_ascii_rangegrid.ply", 40256},
        {"formats/minimal-ply-1.0_ascii-unmodified-unknown.ply", 0},
        {"formats/minimal-ply-1.0_binary-unmodified-unknown.ply", 0},
    };
    for (const auto& [name, count] : files) {
        const auto run = runCli({"info", (data / name).string(), "--json"});
        ASSERT_EQ(run.exitCode, 0) << name << ": " << run.err;
        const auto j = nlohmann::json::parse(run.out);
        EXPECT_EQ(j["points"].get<std::uint64_t>() + j["skipped_non_finite"].get<std::uint64_t>(), count) << name;
        if (!j["declared_points"].is_null()) EXPECT_EQ(j["declared_points"].get<std::uint64_t>(), count) << name;
    }
    for (const auto& entry : std::filesystem::directory_iterator(data / "formats")) {
        const auto name = entry.path().filename().string();
        if (name.rfind("minimal-las", 0) != 0) continue;
        const auto run = runCli({"info", entry.path().string(), "--json"});
        ASSERT_EQ(run.exitCode, 0) << name << ": " << run.err;
        const auto j = nlohmann::json::parse(run.out);
        EXPECT_EQ(j["points"], j["declared_points"]) << name;
    }
}

TEST(CliInfo, E57AndPtxScansWithTheirPoses)
{
    SKIP_WITHOUT_SHARED_DATA();
    const auto formats = stylos::test::sharedData() / "formats";
    const auto ab = runCli({"info", (formats / "e57" / "A_B.e57").string(), "--json"});
    ASSERT_EQ(ab.exitCode, 0) << ab.err;
    const auto j = nlohmann::json::parse(ab.out);
    EXPECT_EQ(j["format"], "e57-1.0");
    EXPECT_EQ(j["points"], 6);
    EXPECT_EQ(j["declared_points"], 6);
    ASSERT_EQ(j["scans"].size(), 2u);
    EXPECT_EQ(j["scans"][0]["name"], "B2 - Cloud");
    EXPECT_EQ(j["scans"][0]["points"], 2);
    EXPECT_EQ(j["scans"][1]["name"], "A4 - Cloud");
    EXPECT_EQ(j["scans"][1]["rotation"], (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
    const auto one = runCli({"info", (formats / "e57" / "A_B.e57").string(), "--scan", "1", "--json"});
    ASSERT_EQ(one.exitCode, 0) << one.err;
    EXPECT_EQ(nlohmann::json::parse(one.out)["points"], 4);
    EXPECT_EQ(nlohmann::json::parse(one.out)["scan_read"], 1);
    EXPECT_FALSE(j.contains("scan_read")); // every scan read
    const auto oneText = runCli({"info", (formats / "e57" / "A_B.e57").string(), "--scan", "1"});
    EXPECT_NE(oneText.out.find("scans:      2 (only scan 1 read: the points, bounds and attributes above are its own)"),
              std::string::npos) << oneText.out;
    const auto none = runCli({"info", (formats / "e57" / "A_B.e57").string(), "--scan", "2"});
    EXPECT_EQ(none.exitCode, 1);
    EXPECT_NE(none.err.find("scan 2 does not exist"), std::string::npos) << none.err;
    EXPECT_EQ(runCli({"info", (formats / "e57" / "A_B.e57").string(), "--scan", "-1"}).exitCode, 2);

    const auto ptx = runCli({"info", (formats / "ptx" / "multiple-and-transform.ptx").string(), "--json"});
    ASSERT_EQ(ptx.exitCode, 0) << ptx.err;
    const auto p = nlohmann::json::parse(ptx.out);
    EXPECT_EQ(p["points"], 8);
    EXPECT_EQ(p["declared_points"], 8);
    ASSERT_EQ(p["scans"].size(), 2u);
    EXPECT_EQ(p["scans"][0]["rotation"], (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 2}));
    EXPECT_EQ(p["scans"][0]["translation"], (std::vector<double>{600000, 800000, 400}));
    const auto text = runCli({"info", (formats / "ptx" / "multiple-and-transform.ptx").string()});
    EXPECT_NE(text.out.find("scans:      2"), std::string::npos) << text.out;
}

TEST(CliInfo, CompressedAndInvalidFixturesAreRefusedClearly)
{
    SKIP_WITHOUT_SHARED_DATA();
    const auto formats = stylos::test::sharedData() / "formats";
    const auto laz = runCli({"info", (formats / "autzen_trim.laz").string()});
    EXPECT_EQ(laz.exitCode, 1);
    EXPECT_NE(laz.err.find("LAZ"), std::string::npos) << laz.err;
    EXPECT_NE(laz.err.find("laszip"), std::string::npos) << laz.err;
    for (const char* name : {"bad-crc.e57", "empty.e57", "InvalidCVHeader.e57"}) {
        const auto path = formats / "e57" / "invalid" / name;
        const auto run = runCli({"info", path.string()});
        EXPECT_EQ(run.exitCode, 1) << name;
        EXPECT_EQ(run.err.rfind("stylos-cli: " + path.string() + ": ", 0), 0u) << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        EXPECT_TRUE(run.out.empty()) << run.out;
    }
    for (const auto& entry : std::filesystem::directory_iterator(formats / "invalid")) {
        const auto run = runCli({"info", entry.path().string()});
        EXPECT_EQ(run.exitCode, 1) << entry.path();
        EXPECT_NE(run.err.find("remark"), std::string::npos) << run.err;
    }
}
