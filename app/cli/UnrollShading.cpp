#include "UnrollShading.h"

#include "stylos/core/shading/ContrastStretch.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <numbers>

namespace stylos::cli {

namespace {

std::string lowerExtension(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

core::Error invalid(const std::string& problem) { return core::Error{core::ErrorCode::InvalidArgument, problem}; }

} // namespace

const char* shadingName(ShadingKind kind)
{
    switch (kind) {
    case ShadingKind::Height: return "height";
    case ShadingKind::Light: return "light";
    case ShadingKind::Skydome: return "skydome";
    }
    return "skydome";
}

bool parseShading(CommandLine& cl, ShadingRequest& request, unsigned threads, std::string& problem)
{
    const std::string name = cl.value("shading").value_or("skydome");
    if (name == "height") request.kind = ShadingKind::Height;
    else if (name == "light") request.kind = ShadingKind::Light;
    else if (name == "skydome") request.kind = ShadingKind::Skydome;
    else return problem = "unknown shading \"" + name + "\" (height, light or skydome)", false;
    long long directions = request.skydome.directions;
    double azimuth = 315.0, elevation = 45.0;
    if (!cl.integer("directions", directions) || !cl.number("light-azimuth", azimuth) ||
        !cl.number("light-elevation", elevation))
        return problem = cl.error(), false;
    if (directions < 1 || directions > 4096) return problem = "--directions must be between 1 and 4096", false;
    if (elevation < 0.0 || elevation > 90.0) return problem = "--light-elevation must be between 0 and 90 degrees", false;
    if (cl.value("directions") && request.kind != ShadingKind::Skydome)
        return problem = "--directions applies to --shading skydome only", false;
    if (cl.flag("raw") && request.kind != ShadingKind::Skydome)
        return problem = "--raw applies to --shading skydome only", false;
    request.stretch = !cl.flag("raw");
    if ((cl.value("light-azimuth") || cl.value("light-elevation")) && request.kind != ShadingKind::Light)
        return problem = "--light-azimuth and --light-elevation apply to --shading light only", false;
    request.skydome.directions = static_cast<int>(directions);
    request.skydome.threads = threads;
    request.light.azimuth = azimuth * std::numbers::pi / 180.0;
    request.light.elevation = elevation * std::numbers::pi / 180.0;
    return true;
}

core::Result<core::shading::ShadedImage> shade(const core::shading::HeightField& field, const ShadingRequest& request)
{
    switch (request.kind) {
    case ShadingKind::Height: return core::shading::shadeHeight(field, request.height);
    case ShadingKind::Light: return core::shading::shadeLight(field, request.light);
    case ShadingKind::Skydome: break;
    }
    auto sky = core::shading::shadeSkydome(field, request.skydome);
    if (sky && request.stretch) {
        if (auto range = core::shading::stretchContrast(*sky); !range) return range.error();
    }
    return sky;
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
    return {};
}

} // namespace stylos::cli
