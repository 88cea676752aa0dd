// stylos-cli info on a .poct: the octree summary (text and JSON), the normal code and colour layer it
// reports, and corrupted, truncated or mislabelled files refused with one line (exit 1).
#include "CliRunner.h"
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

using stylos::test::runCli;
using stylos::test::TempDir;
namespace fs = std::filesystem;

namespace {

/** Builds a small octree of the procedural drum into @p path; returns build's JSON. */
nlohmann::json buildSynthetic(const std::string& path, const std::vector<std::string>& extra = {})
{
    std::vector<std::string> args{"build", "--synthetic-drum", "30000", "-o", path, "--depth", "8", "--json"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto run = runCli(args);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return run.exitCode == 0 ? nlohmann::json::parse(run.out) : nlohmann::json{};
}

} // namespace

TEST(CliPoctInfo, JsonDescribesTheOctree)
{
    TempDir dir;
    const auto path = (dir / "d.poct").string();
    const auto built = buildSynthetic(path);
    const auto run = runCli({"info", path, "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["file"], path);
    EXPECT_EQ(j["format"], "poct");
    EXPECT_EQ(j["version"], 1);
    EXPECT_EQ(j["depth"], 8);
    EXPECT_EQ(j["normal_code"], "octahedral16");
    EXPECT_EQ(j["points"], 30000);
    EXPECT_EQ(j["cells_per_level"], built["cells_per_level"]);
    EXPECT_EQ(j["cells"], built["cells"]);
    EXPECT_EQ(j["leaves"], built["leaves"]);
    EXPECT_EQ(j["file_bytes"], fs::file_size(path));
    EXPECT_DOUBLE_EQ(j["bytes_per_cell"].get<double>(),
                     static_cast<double>(fs::file_size(path)) / j["cells"].get<double>());
    // The builder stores each leaf's sampling spacing (float32, one per leaf) for the splats.
    EXPECT_EQ(j["attributes"], (std::vector<std::string>{"spacing"}));
    ASSERT_EQ(j["layers"].size(), 1u);
    EXPECT_EQ(j["layers"][0]["type"], "float32");
    EXPECT_EQ(j["layers"][0]["bytes"], 4 * j["leaves"].get<int>());
    // The root box is the cube around the drum (radius 0.55 m, height 0.5 m, axis z from 0): about
    // 1.1 m (the sampled points reach the fillet circle within a few mm), centred at z = 0.25 m.
    const double size = j["root_box"]["size"].get<double>();
    EXPECT_NEAR(size, 1.1, 0.01);
    EXPECT_NEAR(j["root_box"]["origin"][2].get<double>(), 0.25 - size / 2, 1e-9);
    for (int c = 0; c < 3; ++c)
        EXPECT_DOUBLE_EQ(j["bounds"]["max"][c].get<double>() - j["bounds"]["min"][c].get<double>(), size);
}

TEST(CliPoctInfo, TextSummary)
{
    TempDir dir;
    const auto path = (dir / "d.poct").string();
    const auto built = buildSynthetic(path, {"--normal-code", "paper15"});
    const auto run = runCli({"info", path});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    for (const std::string line : {"format:      poct (version 1)", "depth:       8", "normal code: paper15",
                                   "points:      30000", "  level  0:  1", "attributes:  spacing (float32 x 1)", "bytes per cell"})
        EXPECT_NE(run.out.find(line), std::string::npos) << line << "\n" << run.out;
    EXPECT_NE(run.out.find("cells:       " + std::to_string(built["cells"].get<std::uint64_t>())), std::string::npos)
        << run.out;
}

TEST(CliPoctInfo, ColourLayerIsListed)
{
    TempDir dir;
    // A small coloured cloud with normals: the leaves average the colours into a "colour" layer.
    std::string ply = "ply\nformat ascii 1.0\nelement vertex 64\nproperty float x\nproperty float y\nproperty float z\n"
                      "property float nx\nproperty float ny\nproperty float nz\n"
                      "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    for (int i = 0; i < 64; ++i)
        ply += std::to_string(i % 4) + " " + std::to_string((i / 4) % 4) + " " + std::to_string(i / 16) + " 0 0 1 " +
               std::to_string(i * 3) + " 10 20\n";
    stylos::test::writeText(dir / "c.ply", ply);
    const auto path = (dir / "c.poct").string();
    const auto build = runCli({"build", (dir / "c.ply").string(), "-o", path, "--depth", "3"});
    ASSERT_EQ(build.exitCode, 0) << build.err;
    const auto j = nlohmann::json::parse(runCli({"info", path, "--json"}).out);
    EXPECT_EQ(j["attributes"], (std::vector<std::string>{"colour", "spacing"}));
    ASSERT_EQ(j["layers"].size(), 2u);
    EXPECT_EQ(j["layers"][0]["type"], "uint8");
    EXPECT_EQ(j["layers"][0]["components"], 3);
    EXPECT_EQ(j["layers"][0]["bytes"], 3 * j["leaves"].get<int>());
    EXPECT_EQ(j["leaves"], 64); // a 4×4×4 grid of points 1 m apart, 8 cells per axis: one point per leaf
    EXPECT_NE(runCli({"info", path}).out.find("colour (uint8 x 3)"), std::string::npos);
}

TEST(CliPoctInfo, DamagedFilesExitWithOneAndOneLine)
{
    TempDir dir;
    const auto good = (dir / "good.poct").string();
    buildSynthetic(good);
    const auto bytes = stylos::test::readBytes(good);
    ASSERT_GT(bytes.size(), 1000u);

    auto truncated = bytes;
    truncated.resize(bytes.size() - 100);
    stylos::test::writeBytes(dir / "truncated.poct", truncated);
    auto flipped = bytes;
    flipped[bytes.size() - 10] = static_cast<char>(flipped[bytes.size() - 10] ^ 0x55); // in the last section
    stylos::test::writeBytes(dir / "flipped.poct", flipped);
    stylos::test::writeText(dir / "text.poct", "not an octree at all\n");
    stylos::test::writeText(dir / "empty.poct", "");
    auto headerOnly = bytes;
    headerOnly.resize(40);
    stylos::test::writeBytes(dir / "header.poct", headerOnly);

    for (const auto& name : {"truncated.poct", "flipped.poct", "text.poct", "empty.poct", "header.poct", "missing.poct"}) {
        const auto path = (dir / name).string();
        for (bool json : {false, true}) {
            std::vector<std::string> args{"info", path};
            if (json) args.push_back("--json");
            const auto run = runCli(args);
            EXPECT_EQ(run.exitCode, 1) << name;
            EXPECT_TRUE(run.out.empty()) << name << ": " << run.out;
            EXPECT_NE(run.err.find(path), std::string::npos) << run.err;
            EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        }
    }
    const auto flippedRun = runCli({"info", (dir / "flipped.poct").string()});
    EXPECT_NE(flippedRun.err.find("checksum"), std::string::npos) << flippedRun.err;
}

TEST(CliPoctInfo, AnOctreeIsRecognisedByItsSignatureWhateverItsName)
{
    TempDir dir;
    const auto path = (dir / "d.poct").string();
    buildSynthetic(path);
    fs::copy_file(path, dir / "renamed.bin");
    const auto run = runCli({"info", (dir / "renamed.bin").string(), "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(nlohmann::json::parse(run.out)["format"], "poct");
}
