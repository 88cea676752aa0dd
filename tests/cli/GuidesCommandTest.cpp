// stylos-cli guides: a generated drum gives the contract's keys and types, the file holds the same object,
// the flute count, leading radius and axis agree with the truth, a given axis and count are used, a .poct
// gives the same flutes; a missing file and a plane of points exit 1 naming the file and write nothing;
// usage errors exit 2.
#include "CliRunner.h"
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

using stylos::test::runCli;
using stylos::test::TempDir;
namespace fs = std::filesystem;

namespace {

std::string generateDrum(const TempDir& dir, const std::string& spacing)
{
    const auto path = (dir / "drum.ply").string();
    const auto run = runCli({"generate", "drum", "-o", path, "--spacing", spacing, "--seed", "4"});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return path;
}

std::string readFile(const fs::path& path)
{
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void expectVector3(const nlohmann::json& v)
{
    ASSERT_TRUE(v.is_array());
    ASSERT_EQ(v.size(), 3u);
    for (const auto& x : v) EXPECT_TRUE(x.is_number_float());
}

std::size_t entriesIn(const fs::path& dir) { return std::size_t(std::distance(fs::directory_iterator(dir), {})); }

} // namespace

TEST(CliGuides, DrumGivesTheContractKeysAndTheFileEqualsTheJson)
{
    TempDir dir;
    const auto scan = generateDrum(dir, "0.004");
    const auto out = (dir / "guides.json").string();
    const auto run = runCli({"guides", scan, "-o", out, "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    const std::vector<std::string> keys{"axis_point", "axis_dir", "radius", "radius_slope", "flute_depth", "flutes",
                                        "flute_lines", "phase_deg", "rms", "profile", "seconds"};
    EXPECT_EQ(j.size(), keys.size());
    for (const auto& key : keys) EXPECT_TRUE(j.contains(key)) << key;
    expectVector3(j["axis_point"]);
    expectVector3(j["axis_dir"]);
    for (const char* key : {"radius", "flute_depth", "phase_deg", "rms", "seconds"})
        EXPECT_TRUE(j[key].is_number_float()) << key;
    EXPECT_EQ(j["radius_slope"].get<double>(), 0.0) << "an untapered drum is a cylinder";
    ASSERT_TRUE(j["flutes"].is_number_integer());
    ASSERT_TRUE(j["flute_lines"].is_array());
    EXPECT_EQ(j["flute_lines"].size(), j["flutes"].get<std::size_t>());
    for (const auto& line : j["flute_lines"]) {
        ASSERT_EQ(line.size(), 2u);
        expectVector3(line["point"]);
        expectVector3(line["direction"]);
        EXPECT_EQ(line["direction"], j["axis_dir"]);
    }
    ASSERT_TRUE(j["profile"].is_array());
    EXPECT_EQ(j["profile"].size(), 64u);
    EXPECT_EQ(nlohmann::json::parse(readFile(out)), j);

    const auto truth = nlohmann::json::parse(std::ifstream(dir / "drum.truth.json"));
    EXPECT_EQ(j["flutes"], truth["grooves"]["count"]);
    EXPECT_NEAR(j["radius"].get<double>(), truth["radius"].get<double>(), 0.0003);
    EXPECT_NEAR(j["flute_depth"].get<double>(), truth["grooves"]["depth"].get<double>(), 0.0005);
    EXPECT_GE(j["phase_deg"].get<double>(), 0.0);
    EXPECT_LT(j["phase_deg"].get<double>(), 360.0 / j["flutes"].get<double>());
    double dot = 0.0;
    for (int i = 0; i < 3; ++i) dot += j["axis_dir"][i].get<double>() * truth["axis"]["direction"][i].get<double>();
    EXPECT_GT(std::abs(dot), std::cos(0.05 * M_PI / 180.0));
    // Each flute line lies at the flute bottom radius from the axis.
    const double bottom = j["radius"].get<double>() - j["flute_depth"].get<double>();
    for (const auto& line : j["flute_lines"]) {
        double w[3], along = 0.0, sq = 0.0;
        for (int i = 0; i < 3; ++i) w[i] = line["point"][i].get<double>() - j["axis_point"][i].get<double>();
        for (int i = 0; i < 3; ++i) along += w[i] * j["axis_dir"][i].get<double>();
        for (int i = 0; i < 3; ++i) sq += std::pow(w[i] - along * j["axis_dir"][i].get<double>(), 2);
        EXPECT_NEAR(std::sqrt(sq), bottom, 1e-9);
        EXPECT_NEAR(along, 0.0, 1e-9);
    }
}

TEST(CliGuides, GivenAxisAndFlutesAreUsedAndTheTextSummaryIsPrinted)
{
    TempDir dir;
    const auto scan = generateDrum(dir, "0.006");
    const auto truth = nlohmann::json::parse(std::ifstream(dir / "drum.truth.json"));
    const auto& p = truth["axis"]["point"];
    const auto& d = truth["axis"]["direction"];
    std::string axis;
    for (const auto& v : {p[0], p[1], p[2], d[0], d[1], d[2]}) axis += (axis.empty() ? "" : ",") + v.dump();
    const auto out = (dir / "g.json").string();
    const auto run = runCli({"guides", scan, "-o", out, "--axis", axis, "--flutes", "48", "--threads", "1"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("48 flutes"), std::string::npos) << run.out;
    const auto j = nlohmann::json::parse(readFile(out));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(j["axis_dir"][i].get<double>(), d[i].get<double>(), 1e-12);
    EXPECT_EQ(j["flutes"], 48);
}

TEST(CliGuides, MissingFileAndPlaneExitOneNamingTheFileAndWriteNothing)
{
    TempDir dir;
    std::string plane;
    for (int i = 0; i < 4000; ++i)
        plane += std::to_string(0.01 * (i % 80)) + " " + std::to_string(0.02 * (i / 80)) + " " +
                 std::to_string(0.0005 * ((i * 7919) % 5)) + "\n";
    stylos::test::writeText(dir / "plane.xyz", plane);
    for (const std::string name : {"missing.ply", "plane.xyz"}) {
        const auto input = (dir / name).string();
        const auto out = dir / "g.json";
        const auto run = runCli({"guides", input, "-o", out.string(), "--json"});
        EXPECT_EQ(run.exitCode, 1) << name << ": " << run.err;
        EXPECT_NE(run.err.find(input), std::string::npos) << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        EXPECT_TRUE(run.out.empty()) << run.out;
        EXPECT_FALSE(fs::exists(out));
    }
    EXPECT_EQ(entriesIn(dir.path()), 1u);
}

TEST(CliGuides, UsageErrorsExitTwo)
{
    TempDir dir;
    const auto out = (dir / "g.json").string();
    const std::vector<std::vector<std::string>> bad{
        {"guides", "drum.ply", "-o", out, "--flutes", "2"},
        {"guides", "drum.ply", "-o", out, "--flutes", "many"},
        {"guides", "drum.ply", "-o", out, "--flutes", "1001"},
        {"guides", "drum.ply", "-o", out, "--axis", "1,2,3"},
        {"guides", "drum.ply", "-o", out, "--axis", "0,0,0,0,0,0"},
        {"guides", "drum.ply", "-o", out, "--threads", "-1"},
        {"guides", "drum.ply"},
        {"guides", "-o", out},
        {"guides", "a.ply", "b.ply", "-o", out},
        {"guides", "drum.ply", "-o", out, "--bogus"},
        {"guides", "drum.ply", "-o", (dir / "g.ply").string()}, // not a .json: never over a scan
        {"guides", "drum.ply", "-o", "drum.ply"},
    };
    for (const auto& args : bad) {
        const auto run = runCli(args);
        EXPECT_EQ(run.exitCode, 2) << args.back() << ": " << run.err;
        EXPECT_FALSE(run.err.empty());
    }
    EXPECT_FALSE(fs::exists(out));
    EXPECT_EQ(entriesIn(dir.path()), 0u);
    const auto named = runCli({"guides", "scan.ply", "-o", "scan.ply"});
    EXPECT_NE(named.err.find("the output must be a .json file, not \"scan.ply\""), std::string::npos) << named.err;
    EXPECT_EQ(runCli({"guides", "--help"}).exitCode, 0);
}

TEST(CliGuides, PoctInputGivesTheSameFlutes)
{
    TempDir dir;
    const auto scan = generateDrum(dir, "0.004");
    const auto poct = (dir / "drum.poct").string();
    ASSERT_EQ(runCli({"build", scan, "-o", poct}).exitCode, 0);
    const auto run = runCli({"guides", poct, "-o", (dir / "g.json").string(), "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    const auto truth = nlohmann::json::parse(std::ifstream(dir / "drum.truth.json"));
    EXPECT_EQ(j["flutes"], truth["grooves"]["count"]);
    EXPECT_NEAR(j["radius"].get<double>(), truth["radius"].get<double>(), 0.0003);
    EXPECT_NEAR(j["flute_depth"].get<double>(), truth["grooves"]["depth"].get<double>(), 0.0005);
}
