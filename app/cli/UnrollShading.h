#pragma once
// The shading options of `stylos-cli unroll` (read into the core's DeveloppeeOptions), and the check of
// the output image paths before any long computation starts.
#include "CommandLine.h"

#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/image/ImageWriter.h"
#include "stylos/core/util/Result.h"

#include <optional>
#include <string>

namespace stylos::cli {

/** --shading, --directions, --raw, --light-azimuth, --light-elevation into @p options; false with @p problem
 *  set on a usage error. */
bool parseShading(CommandLine& cl, core::developpee::DeveloppeeOptions& options, std::string& problem);
/** The image extensions the writer takes: .png/.tif/.tiff/.exr for the shading, .tif/.tiff/.exr for the
 *  heights, no 8/16-bit EXR; three different files (the image, the heights, the image's .json map), none of
 *  them a folder, each in an existing folder. InvalidArgument with the problem otherwise (a usage error);
 *  WriteFailed when a target is a folder or its folder does not exist (outputProblem). */
core::Status checkImagePaths(const std::string& output, const std::string& heights,
                             std::optional<core::image::SampleFormat> bits);

} // namespace stylos::cli
