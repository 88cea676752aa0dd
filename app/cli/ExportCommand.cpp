// stylos-cli export IN.poct -o OUT.ply|las [--layers material,toolmark,ambient] [--legend LEGEND.json] [--json]
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"

#include "stylos/core/annotation/LeafExport.h"
#include "stylos/core/annotation/LeafLas.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/Stopwatch.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace stylos::cli {

namespace {

namespace ann = core::annotation;

} // namespace

int runExport(const std::vector<std::string>& args)
{
    CommandLine cl("export", "IN.poct -o OUT.ply|las [--layers material,toolmark,ambient] [--json]",
                   {{"output", "OUT", "one point per leaf with the layers: .ply (properties) or .las (LAS 1.4, format 6)", "o"},
                    {"layers", "LIST", "comma-separated: material, toolmark (uchar ids), ambient (float); default material,toolmark"},
                    {"legend", "FILE", "LAS: the legend (JSON, as in a project) whose class names go into the file; default: the default vocabulary"},
                    {"json", "", "print one JSON object on stdout"}});
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Writes one point per leaf of an octree (its centre, metres, the file's frame) with the annotation\n"
                     "layers (class ids, 0 = unlabelled) and the 3D skydome: as PLY properties named after them, or as\n"
                     "LAS 1.4 point format 6 (material → classification 64 + id, with a classification lookup;\n"
                     "toolmark and ambient → extra bytes; the legend in a \"Stylos\" VLR).\n"
                  << cl.usage();
        return ExitOk;
    }
    if (cl.positionals().size() != 1) return usageError(cl, "export takes exactly one input octree");
    const std::string input = cl.positionals()[0];
    const std::string output = cl.value("output").value_or("");
    if (output.empty()) return usageError(cl, "export needs -o OUT.ply|las");
    const std::string ext = lowerExtension(output);
    if (ext != ".ply" && ext != ".las") return usageError(cl, "the output must be a .ply or .las file, not \"" + output + "\"");
    if (cl.value("legend") && ext != ".las") return usageError(cl, "--legend goes with a .las output");
    std::vector<std::string> layers;
    std::stringstream list(cl.value("layers").value_or("material,toolmark"));
    for (std::string name; std::getline(list, name, ',');) {
        if (!ann::isExportableLayer(name)) return usageError(cl, "unknown layer \"" + name + "\" (material, toolmark, ambient)");
        if (std::find(layers.begin(), layers.end(), name) != layers.end()) return usageError(cl, "layer \"" + name + "\" given twice");
        layers.push_back(name);
    }

    // Usage checked: an output that cannot be written is found before the work.
    if (const std::string problem = outputProblem(output); !problem.empty()) return failure(problem);
    const auto start = core::Clock::now();
    auto opened = core::octree::PackedOctree::open(input);
    if (!opened) {
        std::cerr << "stylos-cli: " << opened.error().message << "\n";
        return ExitFailure;
    }
    ann::Legend legend = ann::Legend::defaults();
    if (const auto file = cl.value("legend")) {
        auto read = ann::Legend::read(*file);
        if (!read) {
            std::cerr << "stylos-cli: " << read.error().message << "\n";
            return ExitFailure;
        }
        legend = std::move(read).value();
    }
    std::uint64_t points = 0;
    {
        ConsoleProgress progress("exporting the leaves of " + input);
        auto written = ext == ".las" ? ann::exportLeafLas(*opened, layers, legend, output, &progress)
                                     : ann::exportLeafPly(*opened, layers, output, &progress);
        if (!written) {
            std::cerr << "stylos-cli: " << written.error().message << "\n";
            return ExitFailure;
        }
        points = *written;
    }
    const double seconds = core::secondsSince(start);
    if (cl.flag("json")) {
        std::cout << nlohmann::json{{"output", output}, {"points", points}, {"layers", layers}, {"seconds", seconds}}.dump() << "\n";
    } else {
        std::string names;
        for (const auto& n : layers) names += (names.empty() ? "" : ", ") + n;
        std::printf("wrote %llu points with %s to %s in %.2f s\n", static_cast<unsigned long long>(points),
                    names.empty() ? "no layers" : names.c_str(), output.c_str(), seconds);
    }
    return ExitOk;
}

} // namespace stylos::cli
