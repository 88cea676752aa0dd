// stylos_ao_benchmark: speed of the 3D skydome (issue 5, docs/benchmarks.md): 8 M leaf cells × 256
// directions in ≤ 20 s on 2 cores.
//
//   stylos_ao_benchmark [--poct FILE] [--dir DIR] [--points N] [--depth L] [--radius M] [--height M]
//                       [--level L] [--directions D] [--method depthmap|slices] [--threads T] [--repeat R]
//                       [--cosine] [--upper-hemisphere] [--leaf-receivers] [--one-sided]
//     Without --poct: the procedural fluted drum of SyntheticStream (scan order, N points, default 20 M,
//     radius 0.15 m, height 0.8 m: a slender column drum, whose leaf surface at depth 11 is about 8 M
//     cells of 0.39 mm, 2.5 points each) built with Streaming at depth L (default 11) in a forked child,
//     cached as DIR/ao-drum-N-rR-hH-dL.poct (DIR: the system temp folder's stylos-ao-benchmark) and
//     reused when present. Then opens the .poct, times cellsAtLevel(level, default the leaves) once and
//     computeAmbientOcclusion R times (default 1), and prints one JSON document: cells, directions,
//     method, threads, the seconds of each run and the best, ns per cell·direction (wall, and × threads:
//     per core), peak RSS of this process (the map, the cells and the sums; the build is in its child),
//     CPU seconds, the load average before and after (figures are only meaningful on an idle machine)
//     and the mean value (a sanity check). A one-line summary goes to stderr.
#include "stylos/core/ao/AmbientOcclusion.h"
#include "stylos/core/ao/AoCells.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/synth/SyntheticStream.h"

#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
namespace ao = stylos::core::ao;
namespace oct = stylos::core::octree;
namespace synth = stylos::core::synth;
using nlohmann::json;

namespace {

struct Settings {
    fs::path poct;
    fs::path dir = fs::temp_directory_path() / "stylos-ao-benchmark";
    std::uint64_t points = 20'000'000;
    int depth = 11;
    double radius = 0.15, height = 0.8;
    int level = -1;
    int directions = 256;
    ao::AoMethod method = ao::AoMethod::DepthMap;
    unsigned threads = 2;
    int repeat = 1;
    bool cosine = false, upper = false, leafReceivers = false, oneSided = false;
};

[[noreturn]] void die(const std::string& message)
{
    std::cerr << "stylos_ao_benchmark: " << message << "\n";
    std::exit(1);
}

double since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double loadAverage()
{
    double load[3] = {0, 0, 0};
    return getloadavg(load, 3) > 0 ? load[0] : -1.0;
}

/** The cached procedural drum, built in a forked child when absent (so its memory is not ours). */
fs::path drumOctree(const Settings& s)
{
    std::ostringstream name;
    name << "ao-drum-" << s.points << "-r" << s.radius << "-h" << s.height << "-d" << s.depth << ".poct";
    const fs::path path = s.dir / name.str();
    if (fs::exists(path)) return path;
    fs::create_directories(s.dir);
    std::fprintf(stderr, "building %s ...\n", path.c_str());
    std::fflush(nullptr);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) die("fork failed");
    if (pid == 0) {
        synth::SyntheticStreamOptions stream;
        stream.points = s.points;
        stream.radius = s.radius;
        stream.height = s.height;
        stream.shuffled = false;
        oct::BuildOptions options;
        options.depth = s.depth;
        options.method = oct::BuildMethod::Streaming;
        options.threads = s.threads;
        const oct::PointSourceFactory open = [stream] { return synth::openSyntheticStream(stream); };
        const auto report = oct::buildOctree(open, path, options);
        if (!report) {
            std::fprintf(stderr, "%s\n", report.error().message.c_str());
            _exit(1);
        }
        std::fprintf(stderr, "  %llu leaves, %llu cells\n", static_cast<unsigned long long>(report->leaves),
                     static_cast<unsigned long long>(report->cells));
        _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) die("building the drum failed");
    std::fprintf(stderr, "  built in %.1f s\n", since(start));
    return path;
}

double cpuSeconds()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    auto sec = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return sec(u.ru_utime) + sec(u.ru_stime);
}

Settings parse(int argc, char** argv)
{
    Settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) die(a + " needs a value");
            return argv[++i];
        };
        if (a == "--poct")
            s.poct = next();
        else if (a == "--dir")
            s.dir = next();
        else if (a == "--points")
            s.points = std::stoull(next());
        else if (a == "--depth")
            s.depth = std::stoi(next());
        else if (a == "--radius")
            s.radius = std::stod(next());
        else if (a == "--height")
            s.height = std::stod(next());
        else if (a == "--level")
            s.level = std::stoi(next());
        else if (a == "--directions")
            s.directions = std::stoi(next());
        else if (a == "--threads")
            s.threads = unsigned(std::stoul(next()));
        else if (a == "--repeat")
            s.repeat = std::max(1, std::stoi(next()));
        else if (a == "--cosine")
            s.cosine = true;
        else if (a == "--upper-hemisphere")
            s.upper = true;
        else if (a == "--leaf-receivers")
            s.leafReceivers = true;
        else if (a == "--one-sided")
            s.oneSided = true;
        else if (a == "--method") {
            const auto m = ao::aoMethodFromName(next());
            if (!m) die("--method must be depthmap or slices");
            s.method = *m;
        } else
            die("unknown argument " + a + " (see the comment at the top of AoBenchmark.cpp)");
    }
    return s;
}

} // namespace

int main(int argc, char** argv)
{
    const Settings s = parse(argc, argv);
    const fs::path path = s.poct.empty() ? drumOctree(s) : s.poct;
    auto octree = oct::PackedOctree::open(path);
    if (!octree) die(octree.error().message);
    const int level = s.level < 0 ? octree->depth() : s.level;

    const double loadBefore = loadAverage();
    const double cpuStart = cpuSeconds();
    auto start = std::chrono::steady_clock::now();
    auto cells = ao::cellsAtLevel(*octree, level);
    if (!cells) die(cells.error().message);
    // --leaf-receivers: every leaf measured at its own centre against the level's cells (what
    // stylos-cli ao does by default); the work counted per leaf.
    ao::AoReceivers receivers;
    if (s.leafReceivers) {
        auto read = ao::leafReceivers(*octree, *cells);
        if (!read) die(read.error().message);
        receivers = std::move(read).value();
    }
    const double cellsSeconds = since(start);

    ao::AoOptions options;
    options.directions = s.directions;
    options.method = s.method;
    options.threads = s.threads;
    options.cosineWeighted = s.cosine;
    options.upperHemisphere = s.upper;
    options.twoSided = !s.oneSided;
    std::vector<double> seconds;
    double mean = 0;
    for (int r = 0; r < s.repeat; ++r) {
        start = std::chrono::steady_clock::now();
        auto values = s.leafReceivers ? ao::computeAmbientOcclusion(*cells, receivers, options)
                                      : ao::computeAmbientOcclusion(*cells, options);
        seconds.push_back(since(start));
        if (!values) die(values.error().message);
        mean = std::accumulate(values->begin(), values->end(), 0.0) / double(std::max<std::size_t>(1, values->size()));
    }
    const double cpu = cpuSeconds() - cpuStart;
    const double best = *std::min_element(seconds.begin(), seconds.end());
    const double work = double(s.leafReceivers ? receivers.size() : cells->size()) * double(s.directions);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);

    const json out{{"file", path.string()},
                   {"level", level},
                   {"cells", cells->size()},
                   {"directions", s.directions},
                   {"method", ao::aoMethodName(s.method)},
                   {"leaf_receivers", s.leafReceivers},
                   {"two_sided", s.leafReceivers && !s.oneSided},
                   {"threads", s.threads},
                   {"cosine_weighted", s.cosine},
                   {"upper_hemisphere", s.upper},
                   {"cells_seconds", cellsSeconds},
                   {"seconds_all", seconds},
                   {"seconds", best},
                   {"ns_per_cell_direction", best / work * 1e9},
                   {"ns_per_cell_direction_per_core", best * s.threads / work * 1e9},
                   {"cpu_seconds", cpu},
                   {"peak_rss_bytes", std::uint64_t(usage.ru_maxrss) * 1024},
                   {"load_average_before", loadBefore},
                   {"load_average_after", loadAverage()},
                   {"mean_value", mean}};
    std::fprintf(stderr,
                 "%s: %zu cells × %d directions, %u threads: cells %.2f s, skydome %.2f s (best of %d), "
                 "%.2f ns per cell·direction (%.2f per core), peak RSS %.0f MiB, load %.2f → %.2f\n",
                 ao::aoMethodName(s.method), cells->size(), s.directions, s.threads, cellsSeconds, best, s.repeat,
                 best / work * 1e9, best * s.threads / work * 1e9, double(usage.ru_maxrss) / 1024.0, loadBefore,
                 out["load_average_after"].get<double>());
    std::cout << out.dump(2) << "\n";
    return 0;
}
