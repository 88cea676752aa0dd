// stylos-cli info FILE [--json] [--columns LAYOUT]; a .poct file gets the octree summary (PoctInfo).
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"
#include "PoctInfo.h"

#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointFileSummary.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

namespace stylos::cli {

namespace {

nlohmann::json toJson(const std::string& file, const core::io::PointFileSummary& s)
{
    nlohmann::json j;
    j["file"] = file;
    j["format"] = s.format;
    j["points"] = s.points;
    j["declared_points"] = s.declaredPoints ? nlohmann::json(*s.declaredPoints) : nlohmann::json(nullptr);
    j["skipped_non_finite"] = s.skipped;
    if (s.min) j["bounds"] = {{"min", *s.min}, {"max", *s.max}};
    else j["bounds"] = nullptr;
    j["attributes"] = s.attributes;
    j["file_bytes"] = s.fileBytes;
    return j;
}

void printText(const std::string& file, const core::io::PointFileSummary& s)
{
    std::printf("file:       %s\nformat:     %s\npoints:     %llu\n", file.c_str(), s.format.c_str(),
                static_cast<unsigned long long>(s.points));
    if (s.skipped > 0)
        std::printf("skipped:    %llu (NaN or infinite coordinates)\n", static_cast<unsigned long long>(s.skipped));
    if (s.min)
        std::printf("bounds:     min (%.6f, %.6f, %.6f)\n            max (%.6f, %.6f, %.6f)\n"
                    "size:       %.6f x %.6f x %.6f\n",
                    (*s.min)[0], (*s.min)[1], (*s.min)[2], (*s.max)[0], (*s.max)[1], (*s.max)[2],
                    (*s.max)[0] - (*s.min)[0], (*s.max)[1] - (*s.min)[1], (*s.max)[2] - (*s.min)[2]);
    else
        std::printf("bounds:     (no points)\n");
    std::string attrs;
    for (const auto& a : s.attributes) attrs += (attrs.empty() ? "" : ", ") + a;
    std::printf("attributes: %s\n", attrs.empty() ? "(none)" : attrs.c_str());
}

/** " .ply .las ..." : the extensions the readers open (@p readable) or recognise and refuse. */
std::string extensionList(bool readable)
{
    std::string list;
    for (const auto& e : core::io::pointFileExtensions())
        if (core::io::isReadable(e.format) == readable) list += " ." + std::string(e.extension);
    return list;
}

} // namespace

int runInfo(const std::vector<std::string>& args)
{
    CommandLine cl("info", "FILE [--json]",
                   {{"json", "", "print one JSON object on stdout"},
                    {"columns", "LAYOUT", "column layout of a text file, e.g. x,y,z,i,r,g,b (_ skips a column)"}});
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Format, point count, bounds and attributes of a point file; for a .poct octree: depth,\n"
                     "normal code, root box, cells per level, bytes per cell and attribute layers.\n"
                  << "Point files:" << extensionList(true) << " (recognised and refused:" << extensionList(false)
                  << ").\n"
                  << cl.usage();
        return ExitOk;
    }
    if (cl.positionals().size() != 1) return usageError(cl, "info takes exactly one FILE");

    const std::string file = cl.positionals()[0];
    if (isPoctFile(file)) return runPoctInfo(file, cl.flag("json"));
    core::io::ReadOptions options;
    options.columns = cl.value("columns").value_or("");
    ConsoleProgress progress("reading " + file);
    auto summary = core::io::summarizePointFile(file, options, &progress);
    if (!summary) {
        std::cerr << "stylos-cli: " << summary.error().message << "\n";
        return ExitFailure;
    }
    if (cl.flag("json")) std::cout << toJson(file, *summary).dump() << "\n";
    else printText(file, *summary);
    return ExitOk;
}

} // namespace stylos::cli
