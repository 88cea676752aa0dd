// stylos-cli build IN -o OUT.poct [--depth L] [--method optimal|streaming] [--memory-limit MiB]
//                   [--normal-code octahedral16|paper15] [--threads N] [--columns LAYOUT] [--scan N]
//                   [--up AXIS] [--unit mm|cm|m] [--offset X,Y,Z] [--json]
// stylos-cli build --synthetic-drum POINTS [--seed N] [--ordered] -o OUT.poct [same options]
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"
#include "ReadArguments.h"
#include "PoctInfo.h"

#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/synth/SyntheticStream.h"

#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace stylos::cli {

namespace {

namespace oct = core::octree;

/** Peak resident memory of this process so far, bytes (Linux reports ru_maxrss in KiB). */
std::uint64_t peakRssBytes()
{
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;
}

/** What this process holds now, bytes (/proc/self/statm's resident pages); 0 when unknown. Before a build it is
 *  the fixed part of every peak: the shared libraries' pages (Qt and what it loads; OpenImageIO is loaded only
 *  when an image is written) and their static data, about 14 MiB on Debian 12. */
std::uint64_t residentBytes()
{
    std::FILE* statm = std::fopen("/proc/self/statm", "r");
    if (!statm) return 0;
    unsigned long long size = 0, resident = 0;
    const bool read = std::fscanf(statm, "%llu %llu", &size, &resident) == 2;
    std::fclose(statm);
    const long page = sysconf(_SC_PAGESIZE);
    return read && page > 0 ? resident * static_cast<std::uint64_t>(page) : 0;
}

/** Besides the construction structure and the baseline: the reader's batches, the normal tables, the writer's
 *  buffers and (for a file without normals) the estimator's working set within its own budget. */
constexpr std::uint64_t WorkingReserve = std::uint64_t(64) << 20;

std::string mebibytes(std::uint64_t bytes) { return std::to_string((bytes + (1u << 19)) >> 20) + " MiB"; }

/** The build's options from the command line; false (with @p problem set) on a usage error. */
bool parseBuildOptions(CommandLine& cl, oct::BuildOptions& options, std::string& problem)
{
    long long depth = options.depth, mib = 0, threads = options.threads;
    if (!cl.integer("depth", depth) || !cl.integer("memory-limit", mib) || !cl.integer("threads", threads)) {
        problem = cl.error();
        return false;
    }
    if (depth < oct::MinOctreeDepth || depth > oct::MaxOctreeDepth) {
        problem = "--depth must be between " + std::to_string(oct::MinOctreeDepth) + " and " +
                  std::to_string(oct::MaxOctreeDepth);
        return false;
    }
    if (cl.value("memory-limit") && (mib < 1 || mib > (1 << 20))) {
        problem = "--memory-limit must be between 1 and 1048576 MiB";
        return false;
    }
    if (threads < 1 || threads > 1024) {
        problem = "--threads must be between 1 and 1024";
        return false;
    }
    const std::string method = cl.value("method").value_or("optimal");
    if (method != "optimal" && method != "streaming") {
        problem = "unknown method \"" + method + "\" (optimal or streaming)";
        return false;
    }
    const auto code = normalCodeFromName(cl.value("normal-code").value_or("octahedral16"));
    if (!code) {
        problem = "unknown normal code \"" + *cl.value("normal-code") + "\" (octahedral16 or paper15)";
        return false;
    }
    options.depth = static_cast<int>(depth);
    options.memoryLimit = static_cast<std::uint64_t>(mib) << 20;
    options.threads = static_cast<unsigned>(threads);
    options.method = method == "streaming" ? oct::BuildMethod::Streaming : oct::BuildMethod::Optimal;
    options.normalCode = *code;
    return true;
}

/** The procedural input of --synthetic-drum; false (with @p problem set) on a usage error. */
bool parseSynthetic(CommandLine& cl, core::synth::SyntheticStreamOptions& stream, std::string& problem)
{
    long long points = 0, seed = static_cast<long long>(stream.seed);
    if (!cl.integer("synthetic-drum", points) || !cl.integer("seed", seed)) {
        problem = cl.error();
        return false;
    }
    if (points < 1) {
        problem = "--synthetic-drum needs a positive number of points";
        return false;
    }
    if (seed < 0) {
        problem = "--seed must be non-negative";
        return false;
    }
    stream.points = static_cast<std::uint64_t>(points);
    stream.seed = static_cast<std::uint64_t>(seed);
    stream.shuffled = !cl.flag("ordered");
    return true;
}

void printSummary(const std::string& input, const std::string& output, const oct::BuildReport& r,
                  std::uint64_t peakRss, std::uint64_t baseline)
{
    const double cells = static_cast<double>(std::max<std::uint64_t>(r.cells, 1));
    std::printf("built %s from %s: %llu points -> %llu cells (%llu leaves), depth %d, %s, %.3f s\n",
                output.c_str(), input.c_str(), static_cast<unsigned long long>(r.points),
                static_cast<unsigned long long>(r.cells), static_cast<unsigned long long>(r.leaves), r.depth,
                oct::buildMethodName(r.method), r.seconds);
    std::printf("construction %.1f MiB (%.2f bytes/cell), file %.1f MiB (%.2f bytes/cell), peak RSS %.1f MiB "
                "(%.1f MiB held before the build)\n",
                r.constructionBytes / 1048576.0, r.constructionBytes / cells, r.fileBytes / 1048576.0,
                r.fileBytes / cells, peakRss / 1048576.0, baseline / 1048576.0);
    if (r.skippedPoints > 0)
        std::printf("skipped %llu points with NaN or infinite coordinates\n",
                    static_cast<unsigned long long>(r.skippedPoints));
    if (r.normalsEstimated && r.normalScans > 0)
        std::printf("normals estimated (the input had none), each point's from its own scan (%u scans, column %s)\n",
                    r.normalScans, r.normalScanColumn.c_str());
    else if (r.normalsEstimated)
        std::printf("normals estimated (the input had none)\n");
}

} // namespace

int runBuild(const std::vector<std::string>& args)
{
    CommandLine cl("build", "IN -o OUT.poct [options]  |  build --synthetic-drum POINTS -o OUT.poct [options]",
                   withFrameOptions({{"output", "OUT.poct", "the packed octree to write", "o"},
                    {"depth", "L", "leaf level, 1..21 (default 12; a cell is the root box / 2^L)"},
                    {"method", "NAME", "optimal (one pass per level, least memory; default) or streaming (one pass)"},
                    {"memory-limit", "MiB", "stop (writing nothing) if the process would exceed this: what it holds at start + 64 MiB of buffers + the construction structure"},
                    {"normal-code", "NAME", "octahedral16 (default) or paper15"},
                    {"threads", "N", "worker threads (default 2)"},
                    {"columns", "LAYOUT", "column layout of a text input, e.g. x,y,z,nx,ny,nz"},
                    scanOption(),
                    {"synthetic-drum", "POINTS", "input: a procedural fluted drum of POINTS points, never stored"},
                    {"seed", "N", "seed of --synthetic-drum (default 1)"},
                    {"ordered", "", "--synthetic-drum in scan-like order (default: random order)"},
                    {"json", "", "print one JSON object on stdout"}}));
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Builds a packed point octree (.poct) from a point file (normals are estimated when it has\n"
                     "none) or from the procedural drum of --synthetic-drum.\n"
                  << cl.usage();
        return ExitOk;
    }
    const bool synthetic = cl.value("synthetic-drum").has_value();
    if (synthetic && !cl.positionals().empty())
        return usageError(cl, "build takes either an input file or --synthetic-drum, not both");
    if (!synthetic && cl.positionals().size() != 1) return usageError(cl, "build takes exactly one input file");
    core::io::ReadOptions read;
    {
        std::string problem;
        if (!parseReadOptions(cl, read, problem)) return usageError(cl, problem);
    }
    if (synthetic && read.scan) return usageError(cl, "--scan applies to an input file only");
    if (synthetic && hasFrameOptions(cl)) return usageError(cl, "--up, --unit and --offset apply to an input file only");
    if (!synthetic && (cl.value("seed") || cl.flag("ordered")))
        return usageError(cl, "--seed and --ordered apply to --synthetic-drum only");
    const auto output = cl.value("output");
    if (!output || output->empty()) return usageError(cl, "build needs -o OUT.poct");
    if (!core::io::hasPoctExtension(*output)) return usageError(cl, "the output must be a .poct file, not \"" + *output + "\"");

    oct::BuildOptions options;
    core::synth::SyntheticStreamOptions stream;
    std::string problem;
    if (!parseBuildOptions(cl, options, problem) || (synthetic && !parseSynthetic(cl, stream, problem)))
        return usageError(cl, problem);

    // --memory-limit bounds the whole process: what it already holds and the buffers come off the octree's share.
    const std::uint64_t limit = options.memoryLimit, baseline = residentBytes();
    if (limit > 0) {
        if (limit < baseline + WorkingReserve + (std::uint64_t(1) << 20)) {
            std::cerr << "stylos-cli: --memory-limit " << mebibytes(limit) << " is below what a build needs besides its "
                      << "octree: " << mebibytes(baseline) << " this process already holds (its libraries and their data) "
                      << "and " << mebibytes(WorkingReserve) << " of buffers; give at least "
                      << mebibytes(baseline + WorkingReserve + (std::uint64_t(2) << 20)) << "\n";
            return ExitFailure;
        }
        options.memoryLimit = limit - baseline - WorkingReserve;
    }

    // Usage checked: an output that cannot be written is found before the work.
    if (const std::string problem = outputProblem(*output); !problem.empty()) return failure(problem);
    const std::string input = synthetic ? "synthetic-drum" : cl.positionals()[0];
    ConsoleProgress progress("building " + *output);
    auto build = [&]() -> core::Result<oct::BuildReport> {
        if (synthetic) {
            const oct::PointSourceFactory open = [stream] { return core::synth::openSyntheticStream(stream); };
            return oct::buildOctree(open, *output, options, &progress);
        }
        return oct::buildOctreeFile(input, *output, options, &progress, read);
    };
    const auto report = build();
    if (!report) {
        std::cerr << "stylos-cli: " << report.error().message;
        if (report.error().code == core::ErrorCode::OutOfBudget && limit > 0)
            std::cerr << " (of the " << mebibytes(limit) << " given, " << mebibytes(baseline)
                      << " are this process's libraries and their data, " << mebibytes(WorkingReserve) << " its buffers)";
        std::cerr << "\n";
        return ExitFailure;
    }
    const oct::BuildReport& r = report.value();
    const std::uint64_t peakRss = peakRssBytes();
    if (cl.flag("json")) {
        nlohmann::json j{{"input", input},
                         {"output", *output},
                         {"points", r.points},
                         {"cells", r.cells},
                         {"leaves", r.leaves},
                         {"depth", r.depth},
                         {"method", oct::buildMethodName(r.method)},
                         {"normal_code", normalCodeName(options.normalCode)},
                         {"seconds", r.seconds},
                         {"construction_bytes", r.constructionBytes},
                         {"file_bytes", r.fileBytes},
                         {"skipped_points", r.skippedPoints},
                         {"passes", r.passes},
                         {"normals_estimated", r.normalsEstimated},
                         {"normal_scans", r.normalScans},
                         {"cells_per_level", r.cellsPerLevel},
                         {"peak_rss_bytes", peakRss},
                         {"baseline_rss_bytes", baseline}};
        if (synthetic) j["synthetic"] = {{"points", stream.points}, {"seed", stream.seed}, {"ordered", !stream.shuffled}};
        std::cout << j.dump() << "\n";
    } else {
        printSummary(input, *output, r, peakRss, baseline);
    }
    return ExitOk;
}

} // namespace stylos::cli
