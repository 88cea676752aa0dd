// stylos-cli ao IN -o OUT.ply|OUT.poct [--directions D] [--level L] [--method slices|depthmap]
//               [--upper-hemisphere] [--cosine] [--bias B] [--receivers leaves|cells] [--one-sided] [--depth N] [--threads N] [--columns LAYOUT] [--scan N]
//               [--up AXIS] [--unit mm|cm|m] [--offset X,Y,Z] [--json]
#include "CommandLine.h"

#include "stylos/core/util/Stopwatch.h"
#include "Commands.h"
#include "ConsoleProgress.h"
#include "ReadArguments.h"

#include "stylos/core/ao/AmbientOcclusion.h"
#include "stylos/core/ao/AoCells.h"
#include "stylos/core/ao/SkydomeLayer.h"
#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/ScratchFolder.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <thread>

namespace stylos::cli {

namespace {

namespace ao = core::ao;
namespace oct = core::octree;
namespace fs = std::filesystem;
using core::Clock;
using core::secondsSince;

struct AoRequest {
    std::string input, output;
    bool poctInput = false, plyOutput = false, json = false, leafReceivers = true;
    std::optional<int> level;
    std::optional<double> smoothing; ///< metres; unset: SkydomeLayerOptions's default (edges of the level's cells)
    ao::AoOptions options;
    oct::BuildOptions build;
    core::io::ReadOptions read;

    /** Each leaf measured at its own position and normal: leaf receivers asked for, and DepthMap (the
     *  Slices method measures cells only). */
    bool measuresLeaves() const { return leafReceivers && options.method == ao::AoMethod::DepthMap; }
};

/** Reads and checks the command line (all but the level against the octree); false with @p problem set. */
bool parseRequest(CommandLine& cl, AoRequest& r, std::string& problem)
{
    if (cl.positionals().size() != 1) return problem = "ao takes exactly one input file", false;
    r.input = cl.positionals()[0];
    r.output = cl.value("output").value_or("");
    if (r.output.empty()) return problem = "ao needs -o OUT.ply or -o OUT.poct", false;
    const std::string ext = lowerExtension(r.output);
    if (ext != ".ply" && ext != ".poct")
        return problem = "the output must be a .ply or .poct file, not \"" + r.output + "\"", false;
    r.plyOutput = ext == ".ply";
    r.json = cl.flag("json");

    long long directions = r.options.directions, threads = 0, depth = r.build.depth, level = -1;
    const bool biasGiven = cl.value("bias").has_value();
    double bias = r.options.bias;
    if (!cl.integer("directions", directions) || !cl.integer("threads", threads) || !cl.integer("depth", depth) ||
        !cl.integer("level", level) || !cl.number("bias", bias))
        return problem = cl.error(), false;
    if (cl.value("smoothing")) {
        double smoothing = 0.0;
        if (!cl.number("smoothing", smoothing)) return problem = cl.error(), false;
        if (!(smoothing >= 0.0 && smoothing <= 1.0))
            return problem = "--smoothing must be a radius in metres between 0 (off) and 1", false;
        r.smoothing = smoothing;
    }
    if (directions < 1 || directions > 65536) return problem = "--directions must be between 1 and 65536", false;
    if (threads < 0 || threads > 1024) return problem = "--threads must be between 0 and 1024", false;
    if (!(bias >= 0.0) || !std::isfinite(bias)) return problem = "--bias must be a finite number of cell edges ≥ 0", false;
    if (const auto name = cl.value("method")) {
        const auto method = ao::aoMethodFromName(*name);
        if (!method) return problem = "unknown method \"" + *name + "\" (slices or depthmap)", false;
        r.options.method = *method;
    }
    r.options.directions = int(directions);
    r.options.threads = unsigned(threads);
    if (const auto receivers = cl.value("receivers")) {
        if (*receivers != "leaves" && *receivers != "cells")
            return problem = "--receivers must be leaves or cells, not \"" + *receivers + "\"", false;
        r.leafReceivers = *receivers == "leaves";
    }
    if (r.smoothing && *r.smoothing > 0.0 && !r.measuresLeaves())
        return problem = "--smoothing applies to leaf receivers (--receivers leaves, --method depthmap) only", false;
    if (biasGiven) r.options.bias = r.options.receiverBias = bias;
    r.options.upperHemisphere = cl.flag("upper-hemisphere");
    r.options.cosineWeighted = cl.flag("cosine");
    r.options.twoSided = !cl.flag("one-sided");

    r.poctInput = core::cloud::isPoctPath(r.input) || lowerExtension(r.input) == ".poct";
    if (r.poctInput && (cl.value("depth") || cl.value("columns") || cl.value("scan") || hasFrameOptions(cl)))
        return problem = "--depth, --columns, --scan, --up, --unit and --offset apply to a point-file input only, "
                         "not to the octree " + r.input, false;
    if (depth < oct::MinOctreeDepth || depth > oct::MaxOctreeDepth)
        return problem = "--depth must be between " + std::to_string(oct::MinOctreeDepth) + " and " +
                         std::to_string(oct::MaxOctreeDepth), false;
    r.build.depth = int(depth);
    // One pass over the (normal-estimated) points: the same cells and memory as Optimal's pass per level,
    // which only pays under a memory limit, which this command does not take.
    r.build.method = oct::BuildMethod::Streaming;
    r.build.threads = threads > 0 ? unsigned(threads) : std::max(1u, std::thread::hardware_concurrency());
    if (!parseReadOptions(cl, r.read, problem)) return false;
    if (cl.value("level")) {
        const int deepest = r.poctInput ? oct::MaxOctreeDepth : r.build.depth;
        if (level < 0 || level > deepest)
            return problem = "--level must be between 0 and " + std::to_string(deepest) +
                             (r.poctInput ? "" : " (the --depth of the octree built from " + r.input + ")"), false;
        r.level = int(level);
    }
    if ((!r.poctInput || r.plyOutput) && sameFile(r.input, r.output))
        return problem = "the output " + r.output + " would replace the input (only a .poct is updated in place)", false;
    return true;
}

int fail(const core::Error& error)
{
    std::cerr << "stylos-cli: " << error.message << "\n";
    return ExitFailure;
}

} // namespace

int runAo(const std::vector<std::string>& args)
{
    CommandLine cl("ao", "IN -o OUT.ply|OUT.poct [options]",
                   withFrameOptions({{"output", "OUT", "leaf centres + ambient (.ply), or the octree + \"ambient\" layer (.poct; IN: in place)", "o"},
                    {"directions", "D", "directions over the sphere (or hemisphere), 1..65536 (default 256)"},
                    {"level", "L", "octree level of the skydome's cells (default: the deepest level whose cells still form a closed surface); values spread to the leaves"},
                    {"method", "NAME", std::string("slices or depthmap (default ") +
                                           ao::aoMethodName(ao::AoOptions{}.method) + ")"},
                    {"upper-hemisphere", "", "only directions above the world's horizon (z > 0), as CloudCompare's PCV"},
                    {"cosine", "", "weight each direction by the cosine to the normal (irradiance)"},
                    {"bias", "B", "self-shadowing tolerance in cell edges: with leaf receivers beyond the occluder cube's reach along the leaf's normal (default 0.5); with cell receivers above the cell's tangent plane (default 1)"},
                    {"smoothing", "M", "with leaf receivers: each leaf's value averaged with its neighbours' on the same surface within M metres (normals within 37°; default 1.5 edges of the level's cells, at most 8 sampling spacings; 0: the raw values)"},
                    {"receivers", "WHERE", "leaves (default: each leaf at its own centre and normal, against the level's cells; depthmap) or cells (each cell's value spread to its leaves)"},
                    {"one-sided", "", "leaves: measure only the side the normal points to (default: both sides, the one that sees more, so a normal turned into the object does not read dark)"},
                    {"depth", "N", "point-file input: leaf level of the octree built first, 1..21 (default 12)"},
                    {"columns", "LAYOUT", "point-file input: column layout of a text file, e.g. x,y,z"},
                    scanOption(),
                    {"threads", "N", "worker threads (default: all cores)"},
                    {"json", "", "print one JSON object on stdout"}}));
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Computes the 3D skydome (ambient occlusion) of a packed octree: for every cell, the fraction of\n"
                     "the sky around its normal that no other cell hides. IN is a .poct or a point file (any format\n"
                     "`info` reads), whose octree is then built first in a temporary folder beside OUT.\n"
                  << cl.usage();
        return ExitOk;
    }
    AoRequest r;
    std::string problem;
    if (!parseRequest(cl, r, problem)) return usageError(cl, problem);
    if (const std::string target = outputProblem(r.output); !target.empty()) return failure(target);

    const auto start = Clock::now();
    // A point file: its octree first, in a folder beside the output that goes when this function returns.
    core::ScratchFolder scratch;
    fs::path octreePath = r.input;
    std::optional<oct::BuildReport> built;
    if (!r.poctInput) {
        if (auto s = scratch.create(fs::path(r.output), "ao"); !s) return fail(s.error());
        octreePath = scratch.path() / "octree.poct";
        ConsoleProgress progress("building the octree of " + r.input);
        auto report = oct::buildOctreeFile(r.input, octreePath, r.build, &progress, r.read);
        if (!report) return fail(report.error());
        built = std::move(report).value();
    }
    const double buildSeconds = built ? built->seconds : 0.0;

    const auto readStart = Clock::now();
    auto opened = oct::PackedOctree::open(octreePath);
    if (!opened) return fail(opened.error());
    const oct::PackedOctree& octree = opened.value();
    const int level = r.level.value_or(ao::closedSurfaceLevel(octree));
    if (level > octree.depth())
        return usageError(cl, "--level " + std::to_string(level) + " is outside the levels 0.." +
                                  std::to_string(octree.depth()) + " of " + r.input);
    const double openSeconds = secondsSince(readStart);
    const bool inPlace = !r.plyOutput && sameFile(octreePath, r.output);
    ao::SkydomeLayerOptions layer;
    layer.ao = r.options;
    layer.level = level;
    layer.leafReceivers = r.leafReceivers;
    layer.smoothingRadius = r.smoothing;
    layer.output = r.plyOutput ? ao::SkydomeOutput::Ply : ao::SkydomeOutput::Poct;
    ao::SkydomeLayerReport made;
    {
        ConsoleProgress progress("skydome of level " + std::to_string(level) + ", " +
                                 std::to_string(r.options.directions) + " directions, to " + r.output);
        auto report = ao::computeSkydomeLayer(octree, r.output, layer, &progress);
        if (!report) return fail(report.error());
        made = *report;
    }
    const double readSeconds = openSeconds + made.readSeconds;
    const double seconds = secondsSince(start);
    const double mean = made.meanAmbient;
    const unsigned threads = r.options.threads ? r.options.threads : std::max(1u, std::thread::hardware_concurrency());

    if (r.json) {
        nlohmann::json j{{"input", r.input},
                         {"output", r.output},
                         {"format", r.plyOutput ? "ply" : "poct"},
                         {"in_place", inPlace},
                         {"directions", r.options.directions},
                         {"cells", made.cells},
                         {"level", level},
                         {"depth", octree.depth()},
                         {"leaves", made.leaves},
                         {"method", ao::aoMethodName(r.options.method)},
                         {"upper_hemisphere", r.options.upperHemisphere},
                         {"cosine", r.options.cosineWeighted},
                         {"bias", r.measuresLeaves() ? r.options.receiverBias : r.options.bias},
                         {"receivers", r.measuresLeaves() ? "leaves" : "cells"},
                         {"two_sided", r.leafReceivers && ao::twoSidedApplies(r.options)},
                         {"smoothing", made.smoothingRadius},
                         {"smoothing_seconds", made.smoothSeconds},
                         {"threads", threads},
                         {"mean_ambient", mean},
                         {"octree_built", built.has_value()},
                         {"normals_estimated", built && built->normalsEstimated},
                         {"build_seconds", buildSeconds},
                         {"read_seconds", readSeconds},
                         {"ao_seconds", made.aoSeconds},
                         {"write_seconds", made.writeSeconds},
                         {"seconds", seconds}};
        std::cout << j.dump() << "\n";
    } else {
        if (built)
            std::printf("built the octree of %s first: %llu points -> %llu leaves, depth %d%s, %.2f s\n",
                        r.input.c_str(), static_cast<unsigned long long>(built->points),
                        static_cast<unsigned long long>(built->leaves), built->depth,
                        built->normalsEstimated ? " (normals estimated)" : "", buildSeconds);
        std::printf("skydome of %zu cells at level %d (%zu leaves), %d directions, %s: mean ambient %.4f; wrote %s%s\n",
                    static_cast<std::size_t>(made.cells), level, static_cast<std::size_t>(made.leaves), r.options.directions, ao::aoMethodName(r.options.method), mean,
                    r.output.c_str(), inPlace ? " (in place)" : "");
        std::printf("read %.2f s, skydome %.2f s, write %.2f s, total %.2f s\n", readSeconds, made.aoSeconds, made.writeSeconds,
                    seconds);
    }
    return ExitOk;
}

} // namespace stylos::cli
