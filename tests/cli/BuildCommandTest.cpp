// stylos-cli build: both methods give the same bytes, the JSON contract (and its agreement with info),
// usage errors (exit 2), a memory limit too small (exit 1, nothing written), a file without normals,
// the procedural input, and Ctrl-C.
#include "CliRunner.h"
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "stylos/core/io/PointFileFormat.h"

#include <chrono>
#include <fstream>
#include <map>
#include <string>
#include <thread>

extern char** environ;

using stylos::test::runCli;
using stylos::test::TempDir;
namespace fs = std::filesystem;

namespace {

/** A generated drum of ~10 k points (with true normals unless @p normals is false). */
std::string generateDrum(const TempDir& dir, bool normals = true, const std::string& name = "drum.ply")
{
    const auto path = (dir / name).string();
    std::vector<std::string> args{"generate", "drum", "-o", path, "--spacing", "0.02", "--seed", "5"};
    if (normals) args.push_back("--normals");
    const auto run = runCli(args);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return path;
}

std::size_t entriesIn(const fs::path& dir) { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), {})); }

const std::vector<std::string> kBuildKeys{"points", "cells", "leaves", "depth", "method", "seconds",
                                          "construction_bytes", "file_bytes", "skipped_points", "passes",
                                          "normals_estimated", "normal_scans", "cells_per_level", "peak_rss_bytes"};

} // namespace

TEST(CliBuild, BothMethodsWriteTheSameBytesAndTheJsonAgreesWithInfo)
{
    TempDir dir;
    const auto scan = generateDrum(dir);
    const auto a = (dir / "optimal.poct").string(), b = (dir / "streaming.poct").string();
    const auto ra = runCli({"build", scan, "-o", a, "--depth", "9", "--json"});
    ASSERT_EQ(ra.exitCode, 0) << ra.err;
    const auto rb = runCli({"build", scan, "-o", b, "--depth", "9", "--method", "streaming", "--json"});
    ASSERT_EQ(rb.exitCode, 0) << rb.err;
    EXPECT_EQ(stylos::test::readBytes(a), stylos::test::readBytes(b));

    const auto ja = nlohmann::json::parse(ra.out), jb = nlohmann::json::parse(rb.out);
    for (const auto& key : kBuildKeys) EXPECT_TRUE(ja.contains(key)) << key;
    EXPECT_EQ(ja["method"], "optimal");
    EXPECT_EQ(jb["method"], "streaming");
    EXPECT_EQ(ja["depth"], 9);
    EXPECT_EQ(ja["passes"], 11);           // bounds, one marking pass per level 0..8, the leaves
    EXPECT_EQ(jb["passes"], 2);            // bounds, then the one pass
    EXPECT_EQ(ja["normals_estimated"], false);
    EXPECT_EQ(ja["skipped_points"], 0);
    EXPECT_EQ(ja["file_bytes"], fs::file_size(a));
    for (const auto& key : {"points", "cells", "leaves", "cells_per_level", "file_bytes"}) EXPECT_EQ(ja[key], jb[key]) << key;
    std::uint64_t sum = 0;
    for (const auto& c : ja["cells_per_level"]) sum += c.get<std::uint64_t>();
    EXPECT_EQ(ja["cells"].get<std::uint64_t>(), sum);
    EXPECT_EQ(ja["cells_per_level"].size(), 10u);
    EXPECT_EQ(ja["cells_per_level"][0], 1);
    EXPECT_EQ(ja["leaves"], ja["cells_per_level"][9]);
    EXPECT_GT(ja["peak_rss_bytes"].get<std::uint64_t>(), 0u);
    EXPECT_GE(ja["construction_bytes"].get<std::uint64_t>(), 7 * ja["cells"].get<std::uint64_t>());

    const auto scanInfo = nlohmann::json::parse(runCli({"info", scan, "--json"}).out);
    EXPECT_EQ(ja["points"], scanInfo["points"]);
    const auto info = runCli({"info", a, "--json"});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    const auto ji = nlohmann::json::parse(info.out);
    for (const auto& key : {"points", "cells", "leaves", "depth", "cells_per_level", "file_bytes", "normal_code"})
        EXPECT_EQ(ji[key], ja[key]) << key;
    EXPECT_EQ(entriesIn(dir.path()), 4u); // scan, truth, two octrees: nothing left over
}

TEST(CliBuild, TextSummaryAndHelp)
{
    TempDir dir;
    const auto out = (dir / "d.poct").string();
    const auto run = runCli({"build", "--synthetic-drum", "20000", "-o", out, "--depth", "8"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("built " + out + " from synthetic-drum: 20000 points"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("bytes/cell"), std::string::npos) << run.out;
    const auto help = runCli({"build", "--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("usage: stylos-cli build"), std::string::npos);
    EXPECT_NE(help.out.find("--memory-limit"), std::string::npos);
}

TEST(CliBuild, UsageErrorsExitWithTwoAndWriteNothing)
{
    TempDir dir;
    const auto out = (dir / "o.poct").string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"build", "in.ply"}, "-o"},
        {{"build", "-o", out}, "input"},
        {{"build", "a.ply", "b.ply", "-o", out}, "input"},
        {{"build", "in.ply", "-o", (dir / "o.ply").string()}, ".poct"},
        {{"build", "in.ply", "-o", out, "--depth", "0"}, "--depth"},
        {{"build", "in.ply", "-o", out, "--depth", "22"}, "--depth"},
        {{"build", "in.ply", "-o", out, "--depth", "ten"}, "--depth"},
        {{"build", "in.ply", "-o", out, "--method", "fast"}, "fast"},
        {{"build", "in.ply", "-o", out, "--memory-limit", "0"}, "--memory-limit"},
        {{"build", "in.ply", "-o", out, "--memory-limit", "-3"}, "--memory-limit"},
        {{"build", "in.ply", "-o", out, "--memory-limit", "lots"}, "--memory-limit"},
        {{"build", "in.ply", "-o", out, "--normal-code", "paper16"}, "paper16"},
        {{"build", "in.ply", "-o", out, "--threads", "0"}, "--threads"},
        {{"build", "in.ply", "-o", out, "--seed", "3"}, "--synthetic-drum"},
        {{"build", "in.ply", "-o", out, "--synthetic-drum", "100"}, "not both"},
        {{"build", "--synthetic-drum", "0", "-o", out}, "--synthetic-drum"},
        {{"build", "--synthetic-drum", "100", "--seed", "-1", "-o", out}, "--seed"},
        {{"build", "in.ply", "-o", out, "--frobnicate"}, "--frobnicate"},
    };
    for (const auto& [args, word] : cases) {
        const auto run = runCli(args);
        EXPECT_EQ(run.exitCode, 2) << args.back();
        EXPECT_NE(run.err.find(word), std::string::npos) << run.err;
        EXPECT_TRUE(run.out.empty());
    }
    EXPECT_EQ(entriesIn(dir.path()), 0u);
}

TEST(CliBuild, MemoryLimitTooSmallFailsAndLeavesNothing)
{
    TempDir dir;
    const auto out = (dir / "big.poct").string();
    // ~600 k cells at depth 11: about 4 MiB of construction structure against a 1 MiB limit.
    for (const char* method : {"optimal", "streaming"}) {
        const auto run = runCli({"build", "--synthetic-drum", "150000", "-o", out, "--depth", "11", "--memory-limit",
                                 "1", "--method", method, "--json"});
        EXPECT_EQ(run.exitCode, 1) << method;
        EXPECT_TRUE(run.out.empty()) << run.out;
        EXPECT_NE(run.err.find("memory"), std::string::npos) << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        EXPECT_EQ(entriesIn(dir.path()), 0u) << method;
    }
    // The limit bounds the whole process: below what it holds at start plus its buffers, the build is refused
    // naming both.
    const auto below = runCli({"build", "--synthetic-drum", "150000", "-o", out, "--depth", "11", "--memory-limit", "64"});
    EXPECT_EQ(below.exitCode, 1);
    EXPECT_NE(below.err.find("--memory-limit 64 MiB is below what a build needs besides its octree: "), std::string::npos)
        << below.err;
    EXPECT_NE(below.err.find("this process already holds (its libraries and their data) and 64 MiB of buffers; give at least"),
              std::string::npos)
        << below.err;
    EXPECT_EQ(entriesIn(dir.path()), 0u);
    // With room for the octree (its ~4 MiB) above the baseline and the buffers, it fits, and the whole process
    // stays within the limit given.
    const auto measured = runCli({"build", "--synthetic-drum", "150000", "-o", out, "--depth", "11", "--json"});
    ASSERT_EQ(measured.exitCode, 0) << measured.err;
    const auto baseline = nlohmann::json::parse(measured.out)["baseline_rss_bytes"].get<std::uint64_t>();
    EXPECT_GT(baseline, 1u << 20);
    const std::uint64_t limitMib = (baseline >> 20) + 64 + 16;
    const auto fits = runCli({"build", "--synthetic-drum", "150000", "-o", out, "--depth", "11", "--memory-limit",
                              std::to_string(limitMib), "--json"});
    ASSERT_EQ(fits.exitCode, 0) << fits.err;
    const auto j = nlohmann::json::parse(fits.out);
    EXPECT_GT(j["construction_bytes"].get<std::uint64_t>(), 1u << 20);
    EXPECT_LE(j["peak_rss_bytes"].get<std::uint64_t>(), limitMib << 20);
    // Room for less than the octree: refused by the builder, the message saying where the rest went.
    const auto tight = runCli({"build", "--synthetic-drum", "150000", "-o", out, "--depth", "11", "--memory-limit",
                               std::to_string((baseline >> 20) + 64 + 2)});
    EXPECT_EQ(tight.exitCode, 1);
    EXPECT_NE(tight.err.find(" are this process's libraries and their data, 64 MiB its buffers)"), std::string::npos)
        << tight.err;
}

TEST(CliBuild, FileWithoutNormalsGetsThemEstimated)
{
    TempDir dir;
    const auto scan = generateDrum(dir, false);
    const auto out = (dir / "n.poct").string();
    const auto run = runCli({"build", scan, "-o", out, "--depth", "8", "--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["normals_estimated"], true);
    EXPECT_GE(j["normal_scans"].get<int>(), 2); // the generator's stations, each a scan with its registration error
    EXPECT_GT(j["points"].get<std::uint64_t>(), 5000u);
    const auto text = runCli({"build", scan, "-o", out, "--depth", "8"});
    ASSERT_EQ(text.exitCode, 0) << text.err;
    EXPECT_NE(text.out.find("normals estimated (the input had none), each point's from its own scan (" +
                            std::to_string(j["normal_scans"].get<int>()) + " scans, column scan_id)"),
              std::string::npos) << text.out;
    EXPECT_EQ(entriesIn(dir.path()), 3u); // scan, truth, octree: the estimated normals were temporary
}

TEST(CliBuild, PtxScansGetTheirNormalsScanByScanAsAPlyScanColumn)
{
    // The generator's drum (three stations, a scan_id column) rewritten as a PTX of three scans, one per
    // station (identity transforms): the PTX reader numbers each point's scan, so the normals are
    // estimated scan by scan as for the PLY, and the two octrees are the same bytes. Estimated whole (the
    // scans' sheets mixed), the PTX's normals, hence its octree, would differ.
    TempDir dir;
    const auto ply = generateDrum(dir, false);
    auto reader = stylos::core::io::openPointReader(ply);
    ASSERT_TRUE(reader) << reader.error().message;
    ASSERT_EQ((*reader)->header().schema.scalarNames, std::vector<std::string>{"scan_id"});
    auto all = stylos::test::readAllPoints(**reader, 4096);
    ASSERT_TRUE(all) << all.error().message;
    std::map<int, std::vector<std::size_t>> byScan;
    for (std::size_t i = 0; i < all->size(); ++i) byScan[int(all->scalars[0][i])].push_back(i);
    ASSERT_EQ(byScan.size(), 3u);
    const fs::path ptx = dir / "drum.ptx";
    {
        std::ofstream out(ptx);
        out.precision(17);
        for (const auto& [scan, points] : byScan) {
            out << "1\n" << points.size() << "\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
            for (std::size_t i : points)
                out << all->positions[3 * i] << ' ' << all->positions[3 * i + 1] << ' ' << all->positions[3 * i + 2]
                    << " 0.5\n";
        }
    }
    const auto fromPly = runCli({"build", ply, "-o", (dir / "ply.poct").string(), "--depth", "8", "--json"});
    ASSERT_EQ(fromPly.exitCode, 0) << fromPly.err;
    const auto fromPtx = runCli({"build", ptx.string(), "-o", (dir / "ptx.poct").string(), "--depth", "8", "--json"});
    ASSERT_EQ(fromPtx.exitCode, 0) << fromPtx.err;
    EXPECT_EQ(nlohmann::json::parse(fromPtx.out)["normal_scans"], 3);
    EXPECT_EQ(stylos::test::readBytes(dir / "ply.poct"), stylos::test::readBytes(dir / "ptx.poct"));
    const auto text = runCli({"build", ptx.string(), "-o", (dir / "ptx2.poct").string(), "--depth", "8"});
    EXPECT_NE(text.out.find("each point's from its own scan (3 scans, column scan_index)"), std::string::npos)
        << text.out;
}

TEST(CliBuild, BadInputExitsWithOneNamingTheFile)
{
    TempDir dir;
    stylos::test::writeText(dir / "bad.ply", "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nend_header\n");
    const auto out = (dir / "o.poct").string();
    for (const auto& name : {"bad.ply", "missing.ply"}) {
        const auto path = (dir / name).string();
        const auto run = runCli({"build", path, "-o", out, "--json"});
        EXPECT_EQ(run.exitCode, 1) << name;
        EXPECT_NE(run.err.find(path), std::string::npos) << run.err;
        EXPECT_TRUE(run.out.empty());
        EXPECT_FALSE(fs::exists(out));
    }
    EXPECT_EQ(entriesIn(dir.path()), 1u);
}

// An output made read-only is refused before the work and left as it was (it was replaced through the temporary file,
// its mode lost, even as root); a writable one is replaced and keeps its mode.
TEST(CliBuild, AReadOnlyOutputIsRefusedAndAReplacedOneKeepsItsMode)
{
    TempDir dir;
    const auto scan = generateDrum(dir);
    const fs::path out = dir / "kept.poct";
    stylos::test::writeText(out, "last week's octree");
    fs::permissions(out, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    const auto refused = runCli({"build", scan, "-o", out.string()});
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_EQ(refused.err, "stylos-cli: " + out.string() + " is read-only; make it writable or name another file\n");
    fs::permissions(out, fs::perms::owner_read | fs::perms::owner_write);
    {
        std::ifstream in(out);
        EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "last week's octree");
    }
    EXPECT_EQ(entriesIn(dir.path()), 3u); // the scan, its truth and the file: nothing else
    // Named without a folder ("kept.poct", in the working folder): refused too (the check came after "no folder").
    fs::permissions(out, fs::perms::owner_read);
    const fs::path here = fs::current_path();
    fs::current_path(dir.path());
    const auto bare = runCli({"build", scan, "-o", "kept.poct"});
    fs::current_path(here);
    EXPECT_EQ(bare.exitCode, 1);
    EXPECT_EQ(bare.err, "stylos-cli: kept.poct is read-only; make it writable or name another file\n");

    fs::permissions(out, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    const auto replaced = runCli({"build", scan, "-o", out.string()});
    ASSERT_EQ(replaced.exitCode, 0) << replaced.err;
    EXPECT_GT(fs::file_size(out), 1000u);
    EXPECT_EQ(fs::status(out).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST(CliBuild, SyntheticDrumIsReproducibleAndMethodIndependent)
{
    TempDir dir;
    const auto a = (dir / "a.poct").string(), b = (dir / "b.poct").string(), c = (dir / "c.poct").string();
    const auto ra = runCli({"build", "--synthetic-drum", "60000", "--seed", "3", "-o", a, "--depth", "10", "--json"});
    ASSERT_EQ(ra.exitCode, 0) << ra.err;
    const auto rb = runCli({"build", "--synthetic-drum", "60000", "--seed", "3", "-o", b, "--depth", "10",
                            "--method", "streaming"});
    ASSERT_EQ(rb.exitCode, 0) << rb.err;
    EXPECT_EQ(stylos::test::readBytes(a), stylos::test::readBytes(b));
    const auto j = nlohmann::json::parse(ra.out);
    EXPECT_EQ(j["points"], 60000);
    EXPECT_EQ(j["input"], "synthetic-drum");
    EXPECT_EQ(j["synthetic"]["seed"], 3);
    EXPECT_EQ(j["synthetic"]["ordered"], false);
    // Ordered: other points (a scan-like sweep), same count, both methods still agree.
    const auto rc = runCli({"build", "--synthetic-drum", "60000", "--seed", "3", "--ordered", "-o", c, "--depth", "10", "--json"});
    ASSERT_EQ(rc.exitCode, 0) << rc.err;
    EXPECT_EQ(nlohmann::json::parse(rc.out)["points"], 60000);
    EXPECT_NE(stylos::test::readBytes(a), stylos::test::readBytes(c));
    ASSERT_EQ(runCli({"build", "--synthetic-drum", "60000", "--seed", "3", "--ordered", "-o", b, "--depth", "10",
                      "--method", "streaming"}).exitCode, 0);
    EXPECT_EQ(stylos::test::readBytes(b), stylos::test::readBytes(c));
}

/** Whether process @p pid catches @p signal (Linux: the SigCgt mask of /proc/PID/status), polled until @p limit. */
static bool waitUntilCatching(pid_t pid, int signal, std::chrono::seconds limit)
{
    const auto end = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < end) {
        std::ifstream status("/proc/" + std::to_string(pid) + "/status");
        std::string line;
        while (std::getline(status, line))
            if (line.rfind("SigCgt:", 0) == 0 && (std::stoull(line.substr(7), nullptr, 16) >> (signal - 1)) & 1u)
                return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}

TEST(CliBuild, CtrlCCancelsCleanly)
{
    TempDir dir;
    const auto out = (dir / "huge.poct").string();
    const std::string errPath = (dir.path().parent_path() / (dir.path().filename().string() + ".err")).string();
    std::vector<std::string> store{STYLOS_CLI, "build", "--synthetic-drum", "2000000000", "-o", out, "--depth", "14"};
    std::vector<char*> argv;
    for (auto& s : store) argv.push_back(s.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    // Signal only once the CLI catches SIGINT (on a loaded machine start-up may take longer than any fixed
    // delay), then give it time to get well into the bounds pass.
    ASSERT_TRUE(waitUntilCatching(pid, SIGINT, std::chrono::seconds(20))) << "the CLI never installed its handler";
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    kill(pid, SIGINT);
    int status = 0;
    const auto start = std::chrono::steady_clock::now();
    double seconds = 0;
    while (waitpid(pid, &status, WNOHANG) == 0) { // a build that ignores the cancel is killed after 10 s
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (seconds > 10) kill(pid, SIGKILL);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    const std::vector<char> err = stylos::test::readBytes(errPath);
    fs::remove(errPath);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 1);
    EXPECT_LT(seconds, 2.0);
    EXPECT_NE(std::string(err.begin(), err.end()).find("cancel"), std::string::npos);
    EXPECT_EQ(entriesIn(dir.path()), 0u);
}

TEST(CliBuild, AnEmptyScanIsNamedNotItsTemporaryNormals)
{
    // ZeroPoints.e57 reads (no normals, so they are estimated into a temporary file) and then has nothing to
    // build: the message names the file the user gave, never the temporary.
    SKIP_WITHOUT_SHARED_DATA();
    TempDir dir;
    const auto input = (stylos::test::sharedData() / "formats" / "e57" / "ZeroPoints.e57").string();
    const auto out = (dir / "z.poct").string();
    const auto run = runCli({"build", input, "-o", out});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.err, "stylos-cli: " + input + ": no points to build an octree from\n");
    EXPECT_EQ(entriesIn(dir.path()), 0u);
}
