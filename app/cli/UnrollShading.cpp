#include "UnrollShading.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace stylos::cli {

namespace {

core::Error invalid(const std::string& problem) { return core::Error{core::ErrorCode::InvalidArgument, problem}; }

} // namespace

bool parseShading(CommandLine& cl, core::developpee::DeveloppeeOptions& options, std::string& problem)
{
    namespace dev = core::developpee;
    const std::string name = cl.value("shading").value_or(dev::shadingInfo(options.shading).key);
    const auto kind = dev::shadingFromKey(name);
    if (!kind) return problem = "unknown shading \"" + name + "\" (" + dev::shadingKeyList() + ")", false;
    options.shading = *kind;
    long long directions = options.directions;
    double azimuth = 315.0, elevation = 45.0;
    if (!cl.integer("directions", directions) || !cl.number("light-azimuth", azimuth) ||
        !cl.number("light-elevation", elevation))
        return problem = cl.error(), false;
    if (directions < dev::DeveloppeeOptions::kMinDirections || directions > dev::DeveloppeeOptions::kMaxDirections)
        return problem = "--directions must be between 1 and 4096", false;
    if (!(elevation >= 0.0 && elevation <= 90.0)) return problem = "--light-elevation must be between 0 and 90 degrees", false;
    if (!std::isfinite(azimuth)) return problem = "--light-azimuth must be a finite number of degrees", false;
    if (cl.value("directions") && options.shading != dev::Shading::Skydome)
        return problem = "--directions applies to --shading skydome only", false;
    if (cl.flag("raw") && options.shading != dev::Shading::Skydome)
        return problem = "--raw applies to --shading skydome only", false;
    options.stretch = !cl.flag("raw");
    if ((cl.value("light-azimuth") || cl.value("light-elevation")) && options.shading != dev::Shading::Light)
        return problem = "--light-azimuth and --light-elevation apply to --shading light only", false;
    options.directions = static_cast<int>(directions);
    if (cl.value("light-azimuth")) options.light.azimuth = azimuth * std::numbers::pi / 180.0;
    if (cl.value("light-elevation")) options.light.elevation = elevation * std::numbers::pi / 180.0;
    return true;
}

core::Status checkImagePaths(const std::string& output, const std::string& heights,
                             std::optional<core::image::SampleFormat> bits)
{
    const std::string ext = lowerExtension(output);
    if (ext != ".png" && ext != ".tif" && ext != ".tiff" && ext != ".exr")
        return invalid("the output must be a .png, .tif or .exr image, not \"" + output + "\"");
    if (ext == ".exr" && bits) return invalid("--bits applies to PNG and TIFF; an EXR image is always float");
    if (!heights.empty()) {
        const std::string h = lowerExtension(heights);
        if (h != ".tif" && h != ".tiff" && h != ".exr")
            return invalid("--heights must name a .tif or .exr file (float), not \"" + heights + "\"");
    }
    // Checked before the work, so that a target that cannot be written is not found after another was.
    namespace fs = std::filesystem;
    std::error_code ignored;
    const auto key = [&](const std::string& path) { return fs::weakly_canonical(fs::absolute(path), ignored); };
    const std::string map = output + ".json";
    if (!heights.empty() && (key(heights) == key(output) || key(heights) == key(map)))
        return invalid("--heights " + heights + " is the image or its map; name another file");
    for (const std::string& target : {output, map, heights}) {
        if (target.empty()) continue;
        if (std::string problem = outputProblem(target); !problem.empty())
            return core::Error{core::ErrorCode::WriteFailed, std::move(problem)};
    }
    return {};
}

} // namespace stylos::cli
