// stylos_read_benchmark [--points N] [--text-points N] [--dir DIR] [FILES...]
// Reading speed (points/s, one thread, file in cache: best of 3 after a warm-up read) and peak resident
// memory of a whole read (measured in a forked child, so the generation of the inputs does not count).
// With FILES, measures those; otherwise generates binary PLY, LAS and text inputs of N points.
#include "BenchmarkFiles.h"

#include "stylos/core/io/PointFileFormat.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using namespace stylos;

namespace {

struct ReadResult {
    std::uint64_t points = 0;
    double seconds = 0;
};

ReadResult readOnce(const fs::path& path)
{
    auto reader = core::io::openPointReader(path);
    if (!reader) {
        std::cerr << reader.error().message << "\n";
        std::exit(1);
    }
    core::io::PointBatch batch;
    ReadResult r;
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
        auto got = (*reader)->read(batch, 1 << 16);
        if (!got) {
            std::cerr << got.error().message << "\n";
            std::exit(1);
        }
        if (*got == 0) break;
        r.points += *got;
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

/** Peak RSS (KiB) of a child process that reads the whole file once. */
long peakKibOfRead(const fs::path& path)
{
    const pid_t pid = fork();
    if (pid == 0) {
        readOnce(path);
        _exit(0);
    }
    int status = 0;
    struct rusage usage {};
    wait4(pid, &status, 0, &usage);
    return usage.ru_maxrss;
}

nlohmann::json measure(const fs::path& path)
{
    readOnce(path); // warm the page cache
    ReadResult best;
    for (int i = 0; i < 3; ++i) {
        const auto r = readOnce(path);
        if (best.seconds == 0 || r.seconds < best.seconds) best = r;
    }
    const long kib = peakKibOfRead(path);
    nlohmann::json j{{"file", path.filename().string()},
                     {"bytes", fs::file_size(path)},
                     {"points", best.points},
                     {"seconds", best.seconds},
                     {"mpoints_per_s", best.points / best.seconds / 1e6},
                     {"peak_rss_mib", kib / 1024.0}};
    std::fprintf(stderr, "%-28s %10llu points  %7.3f s  %7.1f Mpts/s  peak RSS %6.1f MiB\n",
                 path.filename().c_str(), static_cast<unsigned long long>(best.points), best.seconds,
                 best.points / best.seconds / 1e6, kib / 1024.0);
    return j;
}

} // namespace

int main(int argc, char** argv)
{
    std::uint64_t points = 10'000'000, textPoints = 2'000'000;
    fs::path dir = fs::temp_directory_path() / "stylos-read-benchmark";
    std::vector<fs::path> files;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--points" && i + 1 < argc) points = std::stoull(argv[++i]);
        else if (a == "--text-points" && i + 1 < argc) textPoints = std::stoull(argv[++i]);
        else if (a == "--dir" && i + 1 < argc) dir = argv[++i];
        else files.emplace_back(a);
    }
    if (files.empty()) {
        fs::create_directories(dir);
        const auto ply = dir / "drum.ply", las = dir / "drum.las", xyz = dir / "drum.xyz", xyzn = dir / "drum-n.xyz";
        std::fprintf(stderr, "generating inputs in %s ...\n", dir.c_str());
        if (!fs::exists(ply)) bench::writeBinaryPly(ply, points);
        if (!fs::exists(las)) bench::writeLas(las, points);
        if (!fs::exists(xyz)) bench::writeXyz(xyz, textPoints, false);
        if (!fs::exists(xyzn)) bench::writeXyz(xyzn, textPoints, true);
        files = {ply, las, xyz, xyzn};
    }
    nlohmann::json all = nlohmann::json::array();
    for (const auto& f : files) all.push_back(measure(f));
    std::cout << all.dump(2) << "\n";
    return 0;
}
