#pragma once
// The shading options of `stylos-cli unroll`: parsing, running the chosen shading, and checking the
// output image paths before any long computation starts.
#include "CommandLine.h"

#include "stylos/core/image/ImageWriter.h"
#include "stylos/core/shading/HeightShading.h"
#include "stylos/core/shading/LightShading.h"
#include "stylos/core/shading/SkydomeShading.h"
#include "stylos/core/util/Result.h"

#include <optional>
#include <string>

namespace stylos::cli {

enum class ShadingKind { Height, Light, Skydome };

struct ShadingRequest {
    ShadingKind kind = ShadingKind::Skydome;
    core::shading::SkydomeOptions skydome;
    core::shading::LightShadingOptions light;
    core::shading::HeightShadingOptions height;
    bool stretch = true; ///< skydome: stretch the 1–99 % range to [0, 1] (false: the exact Ω / 2π)
};

const char* shadingName(ShadingKind kind);
/** --shading, --directions, --raw, --light-azimuth, --light-elevation; false with @p problem set on a usage error. */
bool parseShading(CommandLine& cl, ShadingRequest& request, unsigned threads, std::string& problem);
/** Runs the requested shading on @p field. */
core::Result<core::shading::ShadedImage> shade(const core::shading::HeightField& field, const ShadingRequest& request);
/** The image extensions the writer takes: .png/.tif/.tiff/.exr for the shading, .tif/.tiff/.exr for the
 *  heights, no 8/16-bit EXR. InvalidArgument with the problem otherwise. */
core::Status checkImagePaths(const std::string& output, const std::string& heights,
                             std::optional<core::image::SampleFormat> bits);

} // namespace stylos::cli
