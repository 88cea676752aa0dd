// stylos-cli annotate IN.poct --layer material|toolmark --raster LABELS.png --map DEV.png.json -o OUT.poct
//                     [--legend LEGEND.json] [--json]
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"

#include "stylos/core/annotation/LabelArea.h"
#include "stylos/core/annotation/LabelRaster.h"
#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/util/Stopwatch.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

namespace stylos::cli {

namespace {

namespace ann = core::annotation;
namespace oct = core::octree;

int fail(const core::Error& error)
{
    std::cerr << "stylos-cli: " << error.message << "\n";
    return ExitFailure;
}

} // namespace

int runAnnotate(const std::vector<std::string>& args)
{
    CommandLine cl("annotate", "IN.poct --layer material|toolmark --raster LABELS.png --map DEV.png.json -o OUT.poct [options]",
                   {{"output", "OUT.poct", "the octree with the layer written (may be IN: rewritten atomically)", "o"},
                    {"layer", "NAME", "material or toolmark"},
                    {"raster", "LABELS", "8-bit PNG or TIFF of class ids (0 = leave as is) on the développée's grid"},
                    {"map", "DEV.png.json", "the développée's map, the sidecar that stylos-cli unroll wrote"},
                    {"legend", "LEGEND.json", "the classes (default: the default vocabulary, docs/annotation.md)"},
                    {"json", "", "print one JSON object on stdout"}});
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Labels the leaves of an octree from a label raster painted on its développée: every leaf whose\n"
                     "centre maps (by the développée's map) to a pixel holding class c != 0 gets c; the others keep\n"
                     "their label. Reports, per class, the leaf count and the surface area on the object.\n"
                  << cl.usage();
        return ExitOk;
    }
    if (cl.positionals().size() != 1) return usageError(cl, "annotate takes exactly one input octree");
    const std::string input = cl.positionals()[0];
    const std::string output = cl.value("output").value_or("");
    const std::string rasterPath = cl.value("raster").value_or("");
    const std::string mapPath = cl.value("map").value_or("");
    if (output.empty() || rasterPath.empty() || mapPath.empty() || !cl.value("layer"))
        return usageError(cl, "annotate needs --layer, --raster, --map and -o OUT.poct");
    const auto layer = ann::layerFromName(*cl.value("layer"));
    if (!layer) return usageError(cl, "unknown layer \"" + *cl.value("layer") + "\" (material or toolmark)");
    if (std::filesystem::path(output).extension() != ".poct") return usageError(cl, "the output must be a .poct file, not \"" + output + "\"");

    // Usage checked: an output that cannot be written is found before the work.
    if (const std::string problem = outputProblem(output); !problem.empty()) return failure(problem);
    const auto start = core::Clock::now();
    ann::Legend legend = ann::Legend::defaults();
    if (const auto path = cl.value("legend")) {
        auto read = ann::Legend::read(*path);
        if (!read) return fail(read.error());
        legend = std::move(read).value();
    }
    auto opened = oct::PackedOctree::open(input);
    if (!opened) return fail(opened.error());
    const oct::PackedOctree& octree = *opened;
    auto map = core::unroll::UnrollMap::readSidecar(mapPath);
    if (!map) return fail(map.error());
    auto raster = ann::readLabelRaster(rasterPath);
    if (!raster) return fail(raster.error());
    if (auto s = ann::checkLabelRaster(*raster, rasterPath, *map, mapPath, legend, *layer); !s) return fail(s.error());
    auto labels = ann::readLeafLabels(octree, *layer);
    if (!labels) return fail(labels.error());

    std::uint64_t changed = 0;
    {
        ConsoleProgress progress("mapping the leaves of " + input + " onto " + rasterPath);
        // What the développée shows: not the leaves under it (a fragment's inner break face), as in the workbench.
        auto pixels = ann::leafPixels(octree, *map, &progress, ann::paintDepth(map->pixelSize()));
        if (!pixels) return fail(pixels.error());
        changed = ann::applyLabelRaster(*raster, *pixels, *labels);
        // A map made from another object (the drum's, given with a fragment's octree) leaves most painted pixels
        // without a leaf of this octree under them: said, since the labels written are then mostly not the painting.
        std::vector<std::uint8_t> under(raster->ids.size(), 0);
        for (const std::int64_t p : *pixels)
            if (p >= 0) under[std::size_t(p)] = 1;
        std::uint64_t painted = 0, covered = 0;
        for (std::size_t i = 0; i < under.size(); ++i)
            if (raster->ids[i] != 0) ++painted, covered += under[i];
        if (painted > 0 && 2 * covered < painted)
            std::fprintf(stderr, "stylos-cli: warning: only %llu of the %llu painted pixels of %s have leaves of %s under "
                         "them (%.0f %%): was %s made from this octree's développée?\n",
                         static_cast<unsigned long long>(covered), static_cast<unsigned long long>(painted),
                         rasterPath.c_str(), input.c_str(), 100.0 * double(covered) / double(painted), mapPath.c_str());
    }
    auto areas = ann::leafAreas(octree);
    if (!areas) return fail(areas.error());
    const auto measures = ann::measureClasses(*labels, *areas);
    {
        ConsoleProgress progress("writing " + output);
        auto written = ann::writeLeafLabels(octree, *layer, *labels, output, &progress);
        if (!written) return fail(written.error());
    }
    const double seconds = core::secondsSince(start);

    nlohmann::json classes = nlohmann::json::array();
    std::array<bool, 256> listed{};
    for (const ann::LegendClass& c : legend.classes(*layer)) {
        classes.push_back({{"id", c.id}, {"name", c.name}, {"cells", measures[c.id].cells}, {"area_m2", measures[c.id].areaM2}});
        listed[c.id] = true;
    }
    for (int id = 1; id < 256; ++id) // ids stored earlier that this legend lacks
        if (!listed[std::size_t(id)] && measures[std::size_t(id)].cells)
            classes.push_back({{"id", id}, {"name", ""}, {"cells", measures[std::size_t(id)].cells},
                               {"area_m2", measures[std::size_t(id)].areaM2}});
    if (cl.flag("json")) {
        nlohmann::json j{{"input", input},     {"output", output},          {"layer", ann::layerName(*layer)},
                         {"leaves", labels->size()}, {"changed", changed},  {"unlabelled_cells", measures[0].cells},
                         {"classes", classes}, {"seconds", seconds}};
        std::cout << j.dump() << "\n";
    } else {
        std::printf("labelled %llu of %zu leaves of %s (layer %s) from %s; wrote %s\n", static_cast<unsigned long long>(changed),
                    labels->size(), input.c_str(), ann::layerName(*layer), rasterPath.c_str(), output.c_str());
        for (const auto& c : classes)
            std::printf("  %3d %-24s %10llu cells %10.4f m2\n", c["id"].get<int>(), c["name"].get<std::string>().c_str(),
                        static_cast<unsigned long long>(c["cells"].get<std::uint64_t>()), c["area_m2"].get<double>());
    }
    return ExitOk;
}

} // namespace stylos::cli
