// stylos-cli unroll IN -o OUT.png|tif|exr [--surface cylinder|cone|revolution] [--axis PX,PY,PZ,DX,DY,DZ]
//                    [--shading height|light|skydome] [--directions D] [--smoothing M] [--pixel-size M] [--cut-angle DEG]
//                    [--heights OUT.tif|exr] [--bits 8|16] [--threads N] [--columns LAYOUT] [--scan N]
//                    [--up AXIS] [--unit mm|cm|m] [--offset X,Y,Z] [--json]
#include "AxisArgument.h"

#include "stylos/core/util/Stopwatch.h"
#include "CommandLine.h"
#include "Commands.h"
#include "ConsoleProgress.h"
#include "ReadArguments.h"
#include "UnrollShading.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/image/ImageWriter.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <vector>

namespace stylos::cli {

namespace {

namespace unroll = core::unroll;
namespace dev = core::developpee;
using core::Clock;
using core::secondsSince;

struct UnrollRequest {
    dev::DeveloppeeOptions options;
    std::string input, output, heights;
    std::optional<core::image::SampleFormat> bits;
    bool json = false;
};

/** Reads the command line into @p r; false (with @p problem set) on a usage error. */
bool parseRequest(CommandLine& cl, UnrollRequest& r, std::string& problem)
{
    if (cl.positionals().size() != 1) return problem = "unroll takes exactly one input file", false;
    r.input = cl.positionals()[0];
    r.output = cl.value("output").value_or("");
    if (r.output.empty()) return problem = "unroll needs -o OUT.png|tif|exr", false;
    r.heights = cl.value("heights").value_or("");
    r.json = cl.flag("json");
    const auto kind = unroll::surfaceKindFromName(cl.value("surface").value_or("cylinder"));
    if (!kind) return problem = "unknown surface \"" + *cl.value("surface") + "\" (cylinder, cone or revolution)", false;
    r.options.surface = *kind;
    if (const auto axis = cl.value("axis")) {
        unroll::Axis a;
        if (!parseAxis(*axis, a, problem)) return false;
        r.options.axis = a;
    }
    double pixel = 0, cut = 0, smoothing = 0;
    long long threads = 0, bits = 0;
    if (!cl.number("pixel-size", pixel) || !cl.number("cut-angle", cut) || !cl.integer("threads", threads) ||
        !cl.integer("bits", bits) || !cl.number("smoothing", smoothing))
        return problem = cl.error(), false;
    if (cl.value("smoothing")) {
        if (!(smoothing >= 0 && std::isfinite(smoothing)))
            return problem = "--smoothing must be a length of 0 or more metres (0: the raw heights)", false;
        r.options.smoothing = smoothing;
    }
    if (cl.value("pixel-size")) {
        if (!(pixel > 0)) return problem = "--pixel-size must be a positive length in metres", false;
        r.options.pixelSize = pixel;
    }
    if (cl.value("cut-angle")) r.options.cutAngle = cut * std::numbers::pi / 180.0;
    if (threads < 0 || threads > 1024) return problem = "--threads must be between 0 and 1024", false;
    r.options.threads = static_cast<unsigned>(threads);
    if (cl.value("bits")) {
        if (bits != 8 && bits != 16) return problem = "--bits must be 8 or 16", false;
        r.bits = bits == 8 ? core::image::SampleFormat::UInt8 : core::image::SampleFormat::UInt16;
    }
    r.options.fillHoles = !cl.flag("no-fill");
    if (!parseReadOptions(cl, r.options.read, problem)) return false;
    if (core::cloud::isPoctPath(r.input) && (cl.value("columns") || cl.value("scan") || hasFrameOptions(cl)))
        return problem = "--columns, --scan, --up, --unit and --offset apply to a point-file input only, "
                         "not to the octree " + r.input, false;
    return parseShading(cl, r.options, problem);
}

int fail(const core::Error& error)
{
    std::cerr << "stylos-cli: " << error.message << "\n";
    return ExitFailure;
}

nlohmann::json vectorJson(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

} // namespace

int runUnroll(const std::vector<std::string>& args)
{
    CommandLine cl("unroll", "IN -o OUT.png|tif|exr [options]",
                   withFrameOptions({{"output", "OUT", "the développée image: .png (8-bit), .tif (16-bit) or .exr (float)", "o"},
                    {"surface", "KIND", "cylinder (default), cone or revolution"},
                    {"axis", "PX,PY,PZ,DX,DY,DZ", "use this axis (metres) and fit only the radius or profile"},
                    {"shading", "NAME", "skydome (default), light or height"},
                    {"directions", "D", "skydome azimuths, 1..4096 (default 40)"},
                    {"raw", "", "skydome: write the exact fraction of the sky, not the 1-99 % contrast stretch"},
                    {"smoothing", "M", "skydome: Gaussian sigma smoothing the heights first, metres (default: from the measured noise; 0: raw heights)"},
                    {"light-azimuth", "DEG", "light: clockwise from up (default 315, upper left)"},
                    {"light-elevation", "DEG", "light: above the horizon, 0..90 (default 45)"},
                    {"pixel-size", "M", "metres per pixel (default: the sampling spacing, at least 3 leaf edges of a .poct)"},
                    {"cut-angle", "DEG", "azimuth of the seam about the axis (default: where there are fewest points)"},
                    {"heights", "FILE", "also write the raw heights in metres (.tif or .exr, float)"},
                    {"bits", "N", "8 or 16 bits per sample for PNG and TIFF"},
                    {"no-fill", "", "leave the small holes empty instead of filling them"},
                    {"threads", "N", "worker threads (default: all cores)"},
                    {"columns", "LAYOUT", "point-file input: column layout of a text file, e.g. x,y,z"},
                    scanOption(),
                    {"json", "", "print one JSON object on stdout"}}));
    if (!cl.parse(args)) return usageError(cl, cl.error());
    if (cl.helpRequested()) {
        std::cout << "Unrolls a scan of a drum (or any surface of revolution) into a développée: fits the surface,\n"
                     "projects every point to (arc length, height along the axis, height off the surface), fills small\n"
                     "holes and shades the height field. Writes the image and OUT.json, the map between its pixels and 3D.\n"
                  << cl.usage();
        return ExitOk;
    }
    UnrollRequest r;
    std::string problem;
    if (!parseRequest(cl, r, problem)) return usageError(cl, problem);
    if (auto s = checkImagePaths(r.output, r.heights, r.bits); !s)
        return s.error().code == core::ErrorCode::WriteFailed ? failure(s.error().message) : usageError(cl, s.error().message);

    const auto start = Clock::now();
    ConsoleProgress progress("unrolling " + r.input);
    auto made = dev::computeDeveloppee(r.input, r.options, &progress);
    if (!made) return fail(made.error());
    const dev::Developpee& d = *made;
    const char* shadingKey = dev::shadingInfo(r.options.shading).key;

    core::image::ImageWriteOptions write;
    write.format = r.bits;
    write.metadata = {{"stylos:shading", shadingKey}, {"stylos:source", r.input}};
    // All or nothing: a write that fails takes back the files this run wrote before it.
    std::vector<std::string> written;
    const auto failAfter = [&](const core::Error& error) {
        std::error_code ignored;
        for (const std::string& file : written) std::filesystem::remove(file, ignored);
        return fail(error);
    };
    if (auto s = core::image::writeShadedImage(d.shaded, r.output, write); !s) return fail(s.error());
    written.push_back(r.output);
    if (!r.heights.empty()) {
        core::image::ImageWriteOptions heights;
        heights.metadata = {{"stylos:source", r.input}};
        if (auto s = core::image::writeHeightImage(d.field, r.heights, heights); !s) return failAfter(s.error());
        written.push_back(r.heights);
    }
    const std::string sidecar = r.output + ".json";
    if (auto s = d.map.writeSidecar(sidecar); !s) return failAfter(s.error());
    const double seconds = secondsSince(start);

    const unroll::Surface& surface = d.fit.surface;
    const unroll::UnrollReport& u = d.unroll;
    if (r.json) {
        nlohmann::json j{{"input", r.input},
                         {"output", r.output},
                         {"sidecar", sidecar},
                         {"surface", unroll::surfaceKindName(surface.kind())},
                         {"axis_point", vectorJson(surface.axis().point)},
                         {"axis_dir", vectorJson(surface.axis().direction)},
                         {"radius", surface.referenceRadius()},
                         {"width", d.field.width()},
                         {"height", d.field.height()},
                         {"pixel_size", u.pixelSize},
                         {"cut_angle", u.cutAngle * 180.0 / std::numbers::pi},
                         {"arc", u.arc * 180.0 / std::numbers::pi},
                         {"shading", shadingKey},
                         {"directions", r.options.shading == dev::Shading::Skydome ? r.options.directions : 0},
                         {"height_noise", d.heightNoise},
                         {"smoothing", d.smoothing},
                         {"filled_fraction", u.filledFraction},
                         {"coverage", u.coverage},
                         {"sampling_spacing", u.samplingSpacing},
                         {"points", u.points},
                         {"points_used", u.pointsUsed},
                         {"points_off_surface", u.pointsOffSurface},
                         {"fit_rms", d.fit.rmsResidual},
                         {"inlier_fraction", d.fit.inlierFraction},
                         {"load_seconds", d.timings.load},
                         {"fit_seconds", d.timings.fit},
                         {"unroll_seconds", u.seconds},
                         {"shading_seconds", d.timings.shading},
                         {"seconds", seconds}};
        if (surface.kind() == unroll::SurfaceKind::Cone) j["slope"] = surface.slope();
        std::cout << j.dump() << "\n";
    } else {
        std::printf("unrolled %s to %s (%d x %d pixels of %.3f mm): %s, radius %.2f mm, fit RMS %.3f mm, %.1f %% covered, %.1f %% filled\n",
                    r.input.c_str(), r.output.c_str(), d.field.width(), d.field.height(),
                    u.pixelSize * 1e3, unroll::surfaceKindName(surface.kind()), surface.referenceRadius() * 1e3,
                    d.fit.rmsResidual * 1e3, u.coverage * 100.0, u.filledFraction * 100.0);
        if (r.options.shading == dev::Shading::Skydome)
            std::printf("height noise %.3f mm; skydome on heights smoothed by a Gaussian of %.3f mm%s\n", d.heightNoise * 1e3,
                        d.smoothing * 1e3, d.smoothing > 0 ? "" : " (none: raw heights)");
        std::printf("read %.2f s, fit %.2f s, unroll %.2f s, %s shading %.2f s, total %.2f s; map in %s\n",
                    d.timings.load, d.timings.fit, u.seconds, shadingKey, d.timings.shading, seconds,
                    sidecar.c_str());
    }
    return ExitOk;
}

} // namespace stylos::cli
