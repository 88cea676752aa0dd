// stylos_octree_benchmark: the packed octree's targets (issue 3, docs/benchmarks.md).
//
//   stylos_octree_benchmark [--points N] [--dir DIR] [--depth L] [--threads T] [--memory-limit MiB]
//                           [--cut-threshold PX] [--cut-budget N] [--keep]
//     Generates the drum as a binary PLY with true normals (generateScan at the spacing that gives about
//     N points; default 30 M) and a shuffled copy of it (bounded memory), then for each input × method
//     (optimal, streaming) builds the octree in a forked child (so its peak RSS is that build's alone)
//     and reports: points, cells, leaves, seconds, M points/s, construction bytes/cell, peak RSS against
//     7 B × cells + 64 MiB, file bytes/cell, whether both methods wrote the same bytes, and the time to
//     open the .poct and compute a view cut of up to 1 M cells (camera 2 m from the drum) in a fresh child.
//   stylos_octree_benchmark --synthetic N [--memory-limit MiB] [--depth L] [--ordered] [--dir DIR]
//     Builds the procedural drum of N points (never stored) with Optimal: seconds and peak RSS.
//   stylos_octree_benchmark --stream N
//     Speed of the procedural point stream alone, one thread (best of 3, each order).
// A table goes to stderr, one JSON document to stdout. Inputs in DIR are reused when present.
#include "BenchmarkFiles.h"

#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/octree/ViewCut.h"
#include "stylos/core/synth/SyntheticScan.h"
#include "stylos/core/synth/SyntheticStream.h"

#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
namespace oct = stylos::core::octree;
namespace synth = stylos::core::synth;
using nlohmann::json;

namespace {

struct Settings {
    std::uint64_t points = 30'000'000;
    fs::path dir = fs::temp_directory_path() / "stylos-octree-benchmark";
    int depth = 13;
    unsigned threads = 2;
    std::uint64_t memoryLimitMib = 0;
    double cutThreshold = 0.5;
    std::uint64_t cutBudget = 1'000'000;
    bool keep = false;
    std::uint64_t synthetic = 0;
    bool ordered = false;
    std::uint64_t stream = 0;
};

double since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/** CPU time of the calling thread, seconds (unlike wall time, not inflated when other processes run). */
double threadCpuSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

[[noreturn]] void die(const std::string& message)
{
    std::cerr << "stylos_octree_benchmark: " << message << "\n";
    std::exit(1);
}

struct ChildResult {
    json result;
    std::uint64_t peakRssBytes = 0;
    double cpuSeconds = 0;  ///< user + system time of the child, all its threads
};

/** Runs @p work in a forked child; returns its JSON, peak RSS and CPU time. */
ChildResult inChild(const std::function<json()>& work)
{
    int fds[2];
    if (pipe(fds) != 0) die("pipe failed");
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid < 0) die("fork failed");
    if (pid == 0) {
        close(fds[0]);
        const std::string text = work().dump();
        for (std::size_t done = 0; done < text.size();) {
            const ssize_t n = write(fds[1], text.data() + done, text.size() - done);
            if (n <= 0) _exit(2);
            done += static_cast<std::size_t>(n);
        }
        _exit(0);
    }
    close(fds[1]);
    std::string text;
    char buffer[4096];
    for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
    close(fds[0]);
    int status = 0;
    struct rusage usage {};
    wait4(pid, &status, 0, &usage);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || text.empty()) die("a measurement's child process failed");
    auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
    return {json::parse(text), static_cast<std::uint64_t>(usage.ru_maxrss) * 1024,
            seconds(usage.ru_utime) + seconds(usage.ru_stime)};
}

json reportJson(const oct::BuildReport& r)
{
    return {{"points", r.points},   {"cells", r.cells},       {"leaves", r.leaves},
            {"seconds", r.seconds}, {"passes", r.passes},     {"construction_bytes", r.constructionBytes},
            {"file_bytes", r.fileBytes}, {"cells_per_level", r.cellsPerLevel}};
}

/** 64-bit FNV-1a over 8-byte words of a file (and its length): equal files, equal hashes. */
std::uint64_t fileHash(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::vector<char> chunk(1 << 20);
    std::uint64_t h = 0xcbf29ce484222325ull ^ fs::file_size(path);
    while (in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        const std::size_t n = static_cast<std::size_t>(in.gcount());
        std::memset(chunk.data() + n, 0, (8 - n % 8) % 8);
        for (std::size_t i = 0; i < n; i += 8) {
            std::uint64_t w;
            std::memcpy(&w, chunk.data() + i, 8);
            h = (h ^ w) * 0x100000001b3ull;
        }
    }
    return h;
}

/** A perspective camera 2 m from the centre of @p box, looking at it (1280 × 800, 45° vertical). */
oct::CutCamera drumCamera(const oct::RootBox& box)
{
    const double c[3] = {box.origin[0] + box.size / 2, box.origin[1] + box.size / 2, box.origin[2] + box.size / 2};
    double f[3] = {-1.0, -0.3, -0.35};
    const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (double& v : f) v /= fl;
    oct::CutCamera cam;
    for (int i = 0; i < 3; ++i) cam.eye[static_cast<std::size_t>(i)] = c[i] - 2.0 * f[i];
    // View: s = f × up, u = s × f (up = +z); projection: OpenGL perspective.
    double s[3] = {f[1], -f[0], 0.0};
    const double sl = std::hypot(s[0], s[1]);
    s[0] /= sl;
    s[1] /= sl;
    const double u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
    const double fovy = M_PI / 4, aspect = 1.6, zn = 0.05, zf = 100.0, t = 1.0 / std::tan(fovy / 2);
    const double e[3] = {cam.eye[0], cam.eye[1], cam.eye[2]};
    const double view[4][4] = {{s[0], s[1], s[2], -(s[0] * e[0] + s[1] * e[1] + s[2] * e[2])},
                               {u[0], u[1], u[2], -(u[0] * e[0] + u[1] * e[1] + u[2] * e[2])},
                               {-f[0], -f[1], -f[2], f[0] * e[0] + f[1] * e[1] + f[2] * e[2]},
                               {0, 0, 0, 1}};
    const double proj[4][4] = {{t / aspect, 0, 0, 0}, {0, t, 0, 0},
                               {0, 0, (zf + zn) / (zn - zf), 2 * zf * zn / (zn - zf)}, {0, 0, -1, 0}};
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) {
            double v = 0;
            for (int k = 0; k < 4; ++k) v += proj[row][k] * view[k][col];
            cam.viewProjection[static_cast<std::size_t>(col * 4 + row)] = v;
        }
    cam.pixelsPerRadian = 800.0 / fovy;
    return cam;
}

json measureCut(const fs::path& poct, const Settings& settings)
{
    auto [j, rss, cpu] = inChild([&] {
        const auto start = std::chrono::steady_clock::now();
        auto octree = oct::PackedOctree::open(poct);
        if (!octree) return json{{"error", octree.error().message}};
        const double open = since(start);
        oct::CutOptions options;
        options.pixelThreshold = settings.cutThreshold;
        options.pointBudget = settings.cutBudget;
        const auto cut = oct::computeViewCut(*octree, drumCamera(octree->box()), options);
        return json{{"open_seconds", open},
                    {"cut_seconds", since(start) - open},
                    {"seconds", since(start)},
                    {"cut_cells", cut.cells.size()},
                    {"budget_reached", cut.budgetReached},
                    {"deepest_level", cut.deepestLevel}};
    });
    j["peak_rss_bytes"] = rss;
    j["cpu_seconds"] = cpu;
    return j;
}

/** Generates the drum PLY with normals at about @p points points (reused when present). */
fs::path drumInput(const Settings& settings)
{
    const double spacing = 0.0005 * std::sqrt(16.8e6 / static_cast<double>(settings.points));
    const fs::path path = settings.dir / ("drum-" + std::to_string(settings.points) + ".ply");
    if (fs::exists(path)) return path;
    std::fprintf(stderr, "generating %s (spacing %.6f m) ...\n", path.c_str(), spacing);
    synth::SyntheticOptions options;
    options.spacing = spacing;
    options.writeNormals = true;
    const auto start = std::chrono::steady_clock::now();
    auto report = synth::generateScan(synth::SyntheticKind::Drum, options, path);
    if (!report) die(report.error().message);
    std::fprintf(stderr, "  %llu points in %.1f s\n", static_cast<unsigned long long>(report->points), since(start));
    return path;
}

fs::path shuffledInput(const fs::path& ordered)
{
    const fs::path path = ordered.parent_path() / (ordered.stem().string() + "-shuffled.ply");
    if (fs::exists(path)) return path;
    std::fprintf(stderr, "shuffling into %s ...\n", path.c_str());
    const auto start = std::chrono::steady_clock::now();
    const auto n = stylos::bench::writeShuffledCopy(ordered, path, 12345);
    std::fprintf(stderr, "  %llu points in %.1f s\n", static_cast<unsigned long long>(n), since(start));
    return path;
}

json runFileBenchmark(const Settings& settings)
{
    const fs::path ordered = drumInput(settings);
    const fs::path shuffled = shuffledInput(ordered);
    json cases = json::array();
    std::fprintf(stderr, "\n%-9s %-9s %10s %10s %10s %7s %7s %8s %8s %9s %9s %8s %5s %8s\n", "input", "method",
                 "points", "cells", "leaves", "s", "cpu s", "Mpts/s", "constr", "peakRSS", "RSSbudget", "file", "same", "cut s");
    std::fprintf(stderr, "%-9s %-9s %10s %10s %10s %7s %7s %8s %8s %9s %9s %8s %5s %8s\n", "", "", "", "", "", "", "", "",
                 "B/cell", "MiB", "MiB", "B/cell", "", "");
    for (const auto& [name, input] : {std::pair{"ordered", ordered}, std::pair{"shuffled", shuffled}}) {
        std::vector<json> results;
        for (const auto method : {oct::BuildMethod::Optimal, oct::BuildMethod::Streaming}) {
            const fs::path out = settings.dir / (std::string(name) + "-" + oct::buildMethodName(method) + ".poct");
            auto [r, rss, cpu] = inChild([&] {
                oct::BuildOptions options;
                options.depth = settings.depth;
                options.method = method;
                options.threads = settings.threads;
                options.memoryLimit = settings.memoryLimitMib << 20;
                auto report = oct::buildOctreeFile(input, out, options);
                return report ? reportJson(*report) : json{{"error", report.error().message}};
            });
            if (r.contains("error")) die(r["error"].get<std::string>());
            const double cells = r["cells"].get<double>();
            r["input"] = name;
            r["file"] = input.filename().string();
            r["method"] = oct::buildMethodName(method);
            r["mpoints_per_s"] = r["points"].get<double>() / r["seconds"].get<double>() / 1e6;
            r["construction_bytes_per_cell"] = r["construction_bytes"].get<double>() / cells;
            r["file_bytes_per_cell"] = r["file_bytes"].get<double>() / cells;
            r["peak_rss_bytes"] = rss;
            r["cpu_seconds"] = cpu;
            r["rss_budget_bytes"] = 7 * r["cells"].get<std::uint64_t>() + (64ull << 20);
            r["rss_within_budget"] = rss <= r["rss_budget_bytes"].get<std::uint64_t>();
            r["file_hash"] = fileHash(out);
            r["view_cut"] = measureCut(out, settings);
            results.push_back(r);
            if (!settings.keep && method == oct::BuildMethod::Streaming) fs::remove(out);
        }
        const bool same = results[0]["file_hash"] == results[1]["file_hash"];
        for (auto& r : results) {
            r["byte_identical"] = same;
            std::fprintf(stderr, "%-9s %-9s %10llu %10llu %10llu %7.2f %7.2f %8.2f %8.2f %9.1f %9.1f %8.2f %5s %8.3f\n",
                         name, r["method"].get<std::string>().c_str(), r["points"].get<unsigned long long>(),
                         r["cells"].get<unsigned long long>(), r["leaves"].get<unsigned long long>(),
                         r["seconds"].get<double>(), r["cpu_seconds"].get<double>(), r["mpoints_per_s"].get<double>(),
                         r["construction_bytes_per_cell"].get<double>(), r["peak_rss_bytes"].get<double>() / 1048576,
                         r["rss_budget_bytes"].get<double>() / 1048576, r["file_bytes_per_cell"].get<double>(),
                         same ? "yes" : "NO", r["view_cut"]["seconds"].get<double>());
            cases.push_back(r);
        }
        if (!settings.keep) fs::remove(settings.dir / (std::string(name) + "-optimal.poct"));
    }
    std::fprintf(stderr, "view cut: open + cut of <= %llu cells at %.2f px, camera 2 m from the drum; peak RSS of "
                         "each build in its own child process\n",
                 static_cast<unsigned long long>(settings.cutBudget), settings.cutThreshold);
    return {{"depth", settings.depth}, {"threads", settings.threads}, {"cases", cases}};
}

json runSynthetic(const Settings& settings)
{
    const fs::path out = settings.dir / "synthetic.poct";
    synth::SyntheticStreamOptions stream;
    stream.points = settings.synthetic;
    stream.shuffled = !settings.ordered;
    auto [r, rss, cpu] = inChild([&] {
        oct::BuildOptions options;
        options.depth = settings.depth;
        options.method = oct::BuildMethod::Optimal;
        options.threads = settings.threads;
        options.memoryLimit = settings.memoryLimitMib << 20;
        const oct::PointSourceFactory open = [stream] { return synth::openSyntheticStream(stream); };
        auto report = oct::buildOctree(open, out, options);
        return report ? reportJson(*report) : json{{"error", report.error().message}};
    });
    r["peak_rss_bytes"] = rss;
    r["cpu_seconds"] = cpu;
    r["memory_limit_bytes"] = settings.memoryLimitMib << 20;
    r["ordered"] = settings.ordered;
    if (r.contains("error")) {
        std::fprintf(stderr, "synthetic %llu points: FAILED: %s\n", static_cast<unsigned long long>(settings.synthetic),
                     r["error"].get<std::string>().c_str());
        return r;
    }
    r["mpoints_per_s"] = r["points"].get<double>() / r["seconds"].get<double>() / 1e6;
    std::fprintf(stderr, "synthetic %llu points (%s), optimal, depth %d, limit %llu MiB: %llu cells, %.1f s "
                         "(%.2f M points/s; CPU %.1f s), construction %.1f MiB, peak RSS %.1f MiB, file %.1f MiB\n",
                 static_cast<unsigned long long>(settings.synthetic), settings.ordered ? "ordered" : "shuffled",
                 settings.depth, static_cast<unsigned long long>(settings.memoryLimitMib),
                 r["cells"].get<unsigned long long>(), r["seconds"].get<double>(), r["mpoints_per_s"].get<double>(),
                 cpu, r["construction_bytes"].get<double>() / 1048576, rss / 1048576.0,
                 r["file_bytes"].get<double>() / 1048576);
    if (!settings.keep) fs::remove(out);
    return r;
}

json runStream(const Settings& settings)
{
    json j;
    for (bool shuffled : {true, false}) {
        synth::SyntheticStreamOptions o;
        o.points = settings.stream;
        o.shuffled = shuffled;
        double bestWall = 0, bestCpu = 0;
        for (int rep = 0; rep < 3; ++rep) {
            auto reader = synth::openSyntheticStream(o);
            if (!reader) die(reader.error().message);
            stylos::core::io::PointBatch batch;
            const auto start = std::chrono::steady_clock::now();
            const double cpu = threadCpuSeconds();
            while ((*reader)->read(batch, 1 << 16).value() > 0) {}
            const double n = static_cast<double>(o.points) / 1e6;
            bestWall = std::max(bestWall, n / since(start));
            bestCpu = std::max(bestCpu, n / (threadCpuSeconds() - cpu));
        }
        const std::string key = shuffled ? "shuffled" : "ordered";
        j[key] = {{"mpoints_per_s", bestWall}, {"mpoints_per_cpu_s", bestCpu}};
        std::fprintf(stderr, "procedural stream, %s: %.1f M points/s wall, %.1f M points per CPU second (best of 3, "
                             "%llu points, one thread)\n",
                     key.c_str(), bestWall, bestCpu, static_cast<unsigned long long>(o.points));
    }
    double load[3] = {0, 0, 0};
    if (getloadavg(load, 3) > 0) {
        j["load_average"] = load[0];
        std::fprintf(stderr, "load average %.2f (wall-time figures are only meaningful on an idle machine)\n", load[0]);
    }
    return j;
}

} // namespace

int main(int argc, char** argv)
{
    Settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) die(a + " needs a value");
            return argv[++i];
        };
        if (a == "--points") s.points = std::stoull(next());
        else if (a == "--dir") s.dir = next();
        else if (a == "--depth") s.depth = std::stoi(next());
        else if (a == "--threads") s.threads = static_cast<unsigned>(std::stoul(next()));
        else if (a == "--memory-limit") s.memoryLimitMib = std::stoull(next());
        else if (a == "--cut-threshold") s.cutThreshold = std::stod(next());
        else if (a == "--cut-budget") s.cutBudget = std::stoull(next());
        else if (a == "--synthetic") s.synthetic = std::stoull(next());
        else if (a == "--stream") s.stream = std::stoull(next());
        else if (a == "--ordered") s.ordered = true;
        else if (a == "--keep") s.keep = true;
        else die("unknown argument " + a + " (see the comment at the top of OctreeBenchmark.cpp)");
    }
    fs::create_directories(s.dir);
    json out;
    if (s.stream > 0) out["stream"] = runStream(s);
    if (s.synthetic > 0) out["synthetic"] = runSynthetic(s);
    if (s.stream == 0 && s.synthetic == 0) out["builds"] = runFileBenchmark(s);
    std::cout << out.dump(2) << "\n";
    return s.synthetic > 0 && out["synthetic"].contains("error") ? 1 : 0;
}
