// stylos-cli generate: the file and its truth, reproducibility, usage errors, nothing left on failure.
#include "CliRunner.h"
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using stylos::test::runCli;
using stylos::test::TempDir;

TEST(CliGenerate, WritesTheScanAndItsTruthReproducibly)
{
    TempDir dir;
    // Same name in two folders: the header names the truth file, so the bytes must match exactly.
    std::filesystem::create_directories(dir / "again");
    const auto a = (dir / "a.ply").string(), b = (dir / "again" / "a.ply").string();
    const auto run = runCli({"generate", "drum", "-o", a, "--spacing", "0.01", "--seed", "7", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["truth"], (dir / "a.truth.json").string());
    const auto text = runCli({"generate", "drum", "-o", b, "--spacing", "0.01", "--seed", "7"});
    ASSERT_EQ(text.exitCode, 0);
    EXPECT_EQ(stylos::test::readBytes(a), stylos::test::readBytes(b));
    // The time to the hundredth of a second ("in 0.05 s"), not every digit ("in 0.0456435 s").
    const std::string points = std::to_string(j["points"].get<std::uint64_t>());
    const auto in = text.out.rfind(") in ");
    ASSERT_NE(in, std::string::npos) << text.out;
    EXPECT_EQ(text.out.rfind("wrote " + points + " points to " + b, 0), 0u) << text.out;
    const std::string time = text.out.substr(in + 5);
    ASSERT_GE(time.size(), 7u) << time; // "0.05 s\n"
    EXPECT_EQ(time.substr(time.size() - 3), " s\n") << time;
    EXPECT_EQ(time[time.size() - 6], '.') << time;

    const auto info = runCli({"info", a, "--json"});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_EQ(nlohmann::json::parse(info.out)["points"], j["points"]);
    std::ifstream truthFile(dir / "a.truth.json");
    const auto truth = nlohmann::json::parse(truthFile);
    EXPECT_EQ(truth["kind"], "drum");
    EXPECT_EQ(truth["grooves"]["count"], 48);
    EXPECT_EQ(truth["points"], j["points"]);
}

TEST(CliGenerate, UsageErrorsAndFailuresLeaveNothing)
{
    TempDir dir;
    const auto out = (dir / "x.ply").string();
    EXPECT_EQ(runCli({"generate", "drum", "-o", out, "--spacing", "0"}).exitCode, 2);
    EXPECT_EQ(runCli({"generate", "drum", "-o", out, "--spacing", "abc"}).exitCode, 2);
    EXPECT_EQ(runCli({"generate", "cube", "-o", out}).exitCode, 2);
    EXPECT_EQ(runCli({"generate", "drum"}).exitCode, 2);
    const auto las = runCli({"generate", "drum", "-o", (dir / "x.las").string()}); // it writes PLY only
    EXPECT_EQ(las.exitCode, 2);
    EXPECT_NE(las.err.find("the output must be a .ply file"), std::string::npos) << las.err;
    // A folder in the way: found before the work, and nothing left.
    std::filesystem::create_directory(dir / "folder.ply");
    const auto folder = runCli({"generate", "drum", "-o", (dir / "folder.ply").string(), "--spacing", "0.05"});
    EXPECT_EQ(folder.exitCode, 1);
    EXPECT_NE(folder.err.find("folder.ply is a folder; name a file"), std::string::npos) << folder.err;
    std::filesystem::remove(dir / "folder.ply");
    // Values the generator cannot take are usage errors, as the ranges the command checks itself.
    const auto huge = runCli({"generate", "drum", "-o", out, "--spacing", "0.0000001"});
    EXPECT_EQ(huge.exitCode, 2);
    EXPECT_NE(huge.err.find("x.ply: spacing 1e-07 m would give about 4.2"), std::string::npos) << huge.err;
    const auto coarse = runCli({"generate", "drum", "-o", out, "--spacing", "5"}); // "wrote 2 points"
    EXPECT_EQ(coarse.exitCode, 2);
    EXPECT_NE(coarse.err.find("x.ply: spacing 5 m would give about 0 points: too coarse to be a scan (at least 100)"),
              std::string::npos)
        << coarse.err;
    const auto taper = runCli({"generate", "drum", "-o", out, "--taper", "0.5"});
    EXPECT_EQ(taper.exitCode, 2);
    EXPECT_NE(taper.err.find("the taper must lie within a fifth of the radius (110 mm)"), std::string::npos) << taper.err;
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
}

// The truth sidecar is an output too: a read-only OUT.truth.json is refused before the work (it was replaced, its mode
// lost). Files replaced keep their mode — the scan, its truth, and a plate drawn over an earlier one.
TEST(CliGenerate, OutputsKeepTheirModeAndAReadOnlyTruthIsRefused)
{
    namespace fs = std::filesystem;
    TempDir dir;
    const auto ply = (dir / "d.ply").string(), truth = (dir / "d.truth.json").string();
    stylos::test::writeText(truth, "last week's truth");
    fs::permissions(truth, fs::perms::owner_read);
    auto run = runCli({"generate", "drum", "-o", ply, "--spacing", "0.03"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.err, "stylos-cli: " + truth + " is read-only; make it writable or name another file\n");
    EXPECT_FALSE(fs::exists(ply));

    const auto mode = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read;
    fs::permissions(truth, mode);
    stylos::test::writeText(ply, "x");
    fs::permissions(ply, mode);
    run = runCli({"generate", "drum", "-o", ply, "--spacing", "0.03"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_GT(fs::file_size(ply), 1000u);
    EXPECT_EQ(fs::status(ply).permissions() & fs::perms::all, mode);
    EXPECT_EQ(fs::status(truth).permissions() & fs::perms::all, mode);

    const auto png = (dir / "p.png").string();
    stylos::test::writeText(png, "x");
    fs::permissions(png, mode);
    run = runCli({"plate", ply, "-o", png, "--scale", "20", "--dpi", "72"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_GT(fs::file_size(png), 1000u);
    EXPECT_EQ(fs::status(png).permissions() & fs::perms::all, mode);
}
