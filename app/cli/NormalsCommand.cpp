// stylos-cli normals IN -o OUT.ply [--neighbours K] [--viewpoint X,Y,Z] [--memory-limit MiB] [--quality] [--json]
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"
#include "ReadArguments.h"

#include "stylos/core/normals/NormalFileEstimation.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <chrono>
#include <iostream>

namespace stylos::cli {

namespace {

bool parseTriple(const std::string& text, std::array<double, 3>& out)
{
    const char* p = text.data();
    const char* end = text.data() + text.size();
    for (int i = 0; i < 3; ++i) {
        const auto [next, ec] = std::from_chars(p, end, out[i]);
        if (ec != std::errc()) return false;
        p = next;
        if (i < 2) {
            if (p == end || *p != ',') return false;
            ++p;
        }
    }
    return p == end;
}

} // namespace

int runNormals(const std::vector<std::string>& args)
{
    CommandLine cl("normals", "IN -o OUT.ply [options]",
                   withFrameOptions({{"output", "OUT.ply", "binary PLY to write: the points with normals and their attributes", "o"},
                    {"neighbours", "K", "neighbours per point for the PCA (default 16, 3..256)"},
                    {"viewpoint", "X,Y,Z", "orient toward this scanner position (default: away from the centroid)"},
                    {"memory-limit", "MiB", "memory for points held at once; larger clouds are tiled (default 256)"},
                    {"threads", "N", "worker threads (default: all cores)"},
                    {"quality", "", "also write the surface variation as a scalar \"surface_variation\""},
                    {"across-scans", "", "take neighbours across scans (default: from the point's own scan when the "
                                         "input has a scan_id, scan_index or scan column)"},
                    {"columns", "LAYOUT", "column layout of a text input, e.g. x,y,z,i,r,g,b"},
                    scanOption(),
                    {"json", "", "print one JSON object on stdout"}}));
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Estimates normals (k-nearest-neighbour PCA, consistently oriented) for a scan.\n" << cl.usage();
        return ExitOk;
    }
    if (cl.positionals().size() != 1) return usageError(cl, "normals takes exactly one input file");
    const auto output = cl.value("output");
    if (!output || output->empty()) return usageError(cl, "normals needs -o OUT.ply");

    core::normals::NormalFileOptions options;
    long long k = static_cast<long long>(options.normals.neighbours), mib = 256, threads = 0;
    if (!cl.integer("neighbours", k) || !cl.integer("memory-limit", mib) || !cl.integer("threads", threads))
        return usageError(cl, cl.error());
    if (k < 3 || k > 256) return usageError(cl, "--neighbours must be between 3 and 256");
    if (mib < 1 || mib > (1 << 20)) return usageError(cl, "--memory-limit must be between 1 and 1048576 MiB");
    if (threads < 0 || threads > 1024) return usageError(cl, "--threads must be between 0 and 1024");
    options.normals.neighbours = static_cast<std::size_t>(k);
    options.normals.threads = static_cast<unsigned>(threads);
    options.memoryBudget = static_cast<std::size_t>(mib) << 20;
    options.writeQuality = cl.flag("quality");
    options.perScan = !cl.flag("across-scans");
    if (std::string problem; !parseReadOptions(cl, options.read, problem)) return usageError(cl, problem);
    if (const auto vp = cl.value("viewpoint")) {
        if (!parseTriple(*vp, options.normals.viewpoint)) return usageError(cl, "--viewpoint expects X,Y,Z");
        options.normals.orientation = core::normals::NormalOrientation::TowardViewpoint;
    }

    const std::string input = cl.positionals()[0];
    // Usage checked: an output that cannot be written is found before the work.
    if (const std::string problem = outputProblem(*output); !problem.empty()) return failure(problem);
    ConsoleProgress progress("normals " + input);
    const auto start = std::chrono::steady_clock::now();
    auto report = core::normals::estimateNormalsForFile(input, *output, options, &progress);
    if (!report) {
        std::cerr << "stylos-cli: " << report.error().message << "\n";
        return ExitFailure;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (cl.flag("json")) {
        nlohmann::json j{{"input", input},
                         {"output", *output},
                         {"points", report->normals.points},
                         {"degenerate", report->normals.degenerate},
                         {"skipped_non_finite", report->skippedPoints},
                         {"tiles", report->tiles},
                         {"neighbours", options.normals.neighbours},
                         {"scans", report->scans},
                         {"scan_column", report->scanColumn},
                         {"seconds", seconds}};
        std::cout << j.dump() << "\n";
    } else {
        std::cout << "wrote " << report->normals.points << " points with normals to " << *output << " in " << seconds
                  << " s";
        if (report->tiles > 0) std::cout << " (" << report->tiles << " tiles)";
        if (report->scans > 0)
            std::cout << ", each point's neighbours from its own scan (" << report->scans << " scans, column "
                      << report->scanColumn << ")";
        std::cout << "\n";
    }
    return ExitOk;
}

} // namespace stylos::cli
