// stylos-cli info FILE [--json] [--columns LAYOUT] [--scan N] [--up AXIS] [--unit UNIT] [--offset X,Y,Z]
// (the bounds in the corrected frame); a .poct file gets the octree summary (PoctInfo).
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"
#include "PoctInfo.h"
#include "ReadArguments.h"

#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointFileSummary.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <optional>
#include <iostream>

namespace stylos::cli {

namespace {

nlohmann::json toJson(const core::io::ScanInfo& scan, std::size_t index)
{
    const auto& m = scan.pose;
    nlohmann::json j;
    j["index"] = index;
    j["name"] = scan.name;
    if (!scan.guid.empty()) j["guid"] = scan.guid;
    j["points"] = scan.points;
    j["rotation"] = {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]};
    j["translation"] = {m[3], m[7], m[11]};
    if (scan.quaternion) j["quaternion"] = *scan.quaternion;
    return j;
}

nlohmann::json toJson(const std::string& file, const core::io::PointFileSummary& s, std::optional<std::size_t> read)
{
    nlohmann::json j;
    j["file"] = file;
    j["format"] = s.format;
    j["points"] = s.points;
    j["declared_points"] = s.declaredPoints ? nlohmann::json(*s.declaredPoints) : nlohmann::json(nullptr);
    j["skipped_non_finite"] = s.skipped;
    j["skipped_missing"] = s.missing;
    if (!s.scans.empty()) {
        j["scans"] = nlohmann::json::array();
        for (std::size_t i = 0; i < s.scans.size(); ++i) j["scans"].push_back(toJson(s.scans[i], i));
        if (read) j["scan_read"] = *read; // --scan: the points, bounds and attributes are this scan's only
    }
    if (s.min) j["bounds"] = {{"min", *s.min}, {"max", *s.max}};
    else j["bounds"] = nullptr;
    j["attributes"] = s.attributes;
    j["file_bytes"] = s.fileBytes;
    return j;
}

void printText(const std::string& file, const core::io::PointFileSummary& s, std::optional<std::size_t> read)
{
    std::printf("file:       %s\nformat:     %s\npoints:     %llu\n", file.c_str(), s.format.c_str(),
                static_cast<unsigned long long>(s.points));
    if (s.skipped > 0)
        std::printf("skipped:    %llu (NaN or infinite coordinates)\n", static_cast<unsigned long long>(s.skipped));
    if (s.missing > 0)
        std::printf("missing:    %llu (marked invalid or without a return by the scanner, skipped)\n",
                    static_cast<unsigned long long>(s.missing));
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
    if (!s.scans.empty() && read)
        std::printf("scans:      %zu (only scan %zu read: the points, bounds and attributes above are its own)\n",
                    s.scans.size(), *read);
    else if (!s.scans.empty())
        std::printf("scans:      %zu\n", s.scans.size());
    for (std::size_t i = 0; i < s.scans.size(); ++i) {
        const auto& scan = s.scans[i];
        const auto& m = scan.pose;
        std::printf("  scan %zu:   \"%s\", %llu points\n", i, scan.name.c_str(),
                    static_cast<unsigned long long>(scan.points));
        if (scan.quaternion)
            std::printf("            rotation (w x y z) %.9g %.9g %.9g %.9g, translation %.6f %.6f %.6f\n",
                        (*scan.quaternion)[0], (*scan.quaternion)[1], (*scan.quaternion)[2], (*scan.quaternion)[3],
                        m[3], m[7], m[11]);
        else
            std::printf("            rotation rows (%.9g %.9g %.9g) (%.9g %.9g %.9g) (%.9g %.9g %.9g), "
                        "translation %.6f %.6f %.6f\n",
                        m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10], m[3], m[7], m[11]);
    }
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
                   withFrameOptions({{"json", "", "print one JSON object on stdout"},
                    {"columns", "LAYOUT", "column layout of a text file, e.g. x,y,z,i,r,g,b (_ skips a column)"},
                    scanOption()}));
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Format, point count, bounds and attributes of a point file, and the scans of an E57 or PTX\n"
                     "file (name, points, pose); for a .poct octree: depth, normal code, root box, cells per level,\n"
                     "bytes per cell and attribute layers.\n"
                  << "Point files:" << extensionList(true) << " (recognised and refused:" << extensionList(false)
                  << ").\n"
                  << cl.usage();
        return ExitOk;
    }
    if (cl.positionals().size() != 1) return usageError(cl, "info takes exactly one FILE");

    const std::string file = cl.positionals()[0];
    if (isPoctFile(file)) {
        if (hasFrameOptions(cl))
            return usageError(cl, "--up, --unit and --offset apply to a point file, not to the octree " + file);
        return runPoctInfo(file, cl.flag("json"));
    }
    core::io::ReadOptions options;
    if (std::string problem; !parseReadOptions(cl, options, problem)) return usageError(cl, problem);
    ConsoleProgress progress("reading " + file);
    auto summary = core::io::summarizePointFile(file, options, &progress);
    if (!summary) {
        std::cerr << "stylos-cli: " << summary.error().message << "\n";
        return ExitFailure;
    }
    if (cl.flag("json")) std::cout << toJson(file, *summary, options.scan).dump() << "\n";
    else printText(file, *summary, options.scan);
    return ExitOk;
}

} // namespace stylos::cli
