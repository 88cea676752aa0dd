// stylos-cli guides DRUM -o GUIDES.json [--axis PX,PY,PZ,DX,DY,DZ] [--flutes N] [--threads N]
//                   [--columns LAYOUT] [--scan N] [--up AXIS] [--unit mm|cm|m] [--offset X,Y,Z] [--json]
#include "AxisArgument.h"
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"
#include "ReadArguments.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/dock/GuidesFile.h"
#include "stylos/core/util/AtomicTextFile.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <numbers>

namespace stylos::cli {

namespace {

namespace dock = core::dock;

struct GuidesRequest {
    dock::GuideOptions options;
    core::cloud::CloudLoadOptions load;
    std::string input, output;
    bool json = false;
};

/** Reads the command line into @p r; false (with @p problem set) on a usage error. */
bool parseRequest(CommandLine& cl, GuidesRequest& r, std::string& problem)
{
    if (cl.positionals().size() != 1) return problem = "guides takes exactly one drum file", false;
    r.input = cl.positionals()[0];
    r.output = cl.value("output").value_or("");
    if (r.output.empty()) return problem = "guides needs -o GUIDES.json", false;
    if (lowerExtension(r.output) != ".json") return problem = "the output must be a .json file, not \"" + r.output + "\"", false;
    if (sameFile(r.input, r.output)) return problem = "the output " + r.output + " would replace the input", false;
    r.json = cl.flag("json");
    if (const auto axis = cl.value("axis")) {
        core::unroll::Axis a;
        if (!parseAxis(*axis, a, problem)) return false;
        r.options.axis = a;
    }
    long long flutes = 0, threads = 0;
    if (!cl.integer("flutes", flutes) || !cl.integer("threads", threads)) return problem = cl.error(), false;
    if (cl.value("flutes") && (flutes < 3 || flutes > 1000)) return problem = "--flutes must be between 3 and 1000", false;
    if (threads < 0 || threads > 1024) return problem = "--threads must be between 0 and 1024", false;
    r.options.flutes = int(flutes);
    r.options.threads = unsigned(threads);
    if (!parseReadOptions(cl, r.load.read, problem)) return false;
    if (core::cloud::isPoctPath(r.input) && (cl.value("columns") || cl.value("scan") || hasFrameOptions(cl)))
        return problem = "--columns, --scan, --up, --unit and --offset apply to a point-file input only, "
                         "not to the octree " + r.input, false;
    return true;
}

int fail(const core::Error& error)
{
    std::cerr << "stylos-cli: " << error.message << "\n";
    return ExitFailure;
}

} // namespace

int runGuides(const std::vector<std::string>& args)
{
    CommandLine cl("guides", "DRUM -o GUIDES.json [options]",
                   withFrameOptions({{"output", "GUIDES.json", "the guides: axis, leading radius, flutes and their bottom lines", "o"},
                    {"axis", "PX,PY,PZ,DX,DY,DZ", "use this axis (metres) and fit only the radius and flutes"},
                    {"flutes", "N", "the flute count, 3..1000 (default: found among 12..64)"},
                    {"threads", "N", "worker threads of the surface fit (default: all cores)"},
                    {"columns", "LAYOUT", "point-file input: column layout of a text file, e.g. x,y,z"},
                    scanOption(),
                    {"json", "", "print the guides as one JSON object on stdout"}}));
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Fits the guides of an intact fluted drum: the axis of its leading cylinder, the leading radius\n"
                     "(the envelope of the fillets between the flutes), the flute count, depth and phase, and each\n"
                     "flute's bottom line, parallel to the axis, in the file's frame. Input: a point file or a .poct.\n"
                  << cl.usage();
        return ExitOk;
    }
    GuidesRequest r;
    std::string problem;
    if (!parseRequest(cl, r, problem)) return usageError(cl, problem);
    if (const std::string target = outputProblem(r.output); !target.empty()) return failure(target);

    const auto start = std::chrono::steady_clock::now();
    auto cloud = core::cloud::loadPointCloud(r.input, r.load);
    if (!cloud) return fail(cloud.error());
    cloud->source = r.input;
    ConsoleProgress progress("fitting the guides of " + r.input);
    auto guides = dock::fitDrumGuides(*cloud, r.options, &progress);
    if (!guides) return fail(guides.error());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const std::string text = dock::guidesToJson(*guides, seconds).dump();
    if (auto s = core::writeTextFileAtomically(r.output, text + "\n"); !s) return fail(s.error());
    if (r.json) {
        std::cout << text << "\n";
    } else {
        const dock::DrumGuides& g = *guides;
        char cone[80] = "";
        if (g.slope != 0.0) std::snprintf(cone, sizeof cone, ", tapering %+.3f mm per metre (a cone)", g.slope * 1e3);
        std::printf("guides of %s in %s: %d flutes %.3f mm deep, phase %.4f deg, leading radius %.3f mm%s, "
                    "RMS %.3f mm (read %.2f s, guides %.2f s, total %.2f s)\n",
                    r.input.c_str(), r.output.c_str(), g.flutes, g.fluteDepth * 1e3, g.phase * 180.0 / std::numbers::pi,
                    g.radius * 1e3, cone, g.rms * 1e3, seconds - g.seconds, g.seconds, seconds);
    }
    return ExitOk;
}

} // namespace stylos::cli
