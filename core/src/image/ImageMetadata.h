#pragma once
// Internal: the file format chosen from an extension, and the metadata an image carries
// (resolution, stylos text attributes, ImageDescription). See ImageWriter.h for what each format holds.
#include "stylos/core/image/ImageLibrary.h"
#include "stylos/core/util/Result.h"

#include <filesystem>
#include <map>
#include <string>

namespace stylos::core::image {

enum class ImageFileFormat { Png, Tiff, Exr };

/** The format of @p path's extension (case-insensitive .png, .tif, .tiff, .exr) or InvalidArgument. */
Result<ImageFileFormat> imageFileFormat(const std::filesystem::path& path);

/** InvalidArgument naming @p path when a key or value of @p metadata cannot be stored (ImageWriter.h). */
Status checkMetadata(const std::filesystem::path& path, const std::map<std::string, std::string>& metadata);

/** The shortest decimal text that reads back to exactly @p value. */
std::string shortestDecimal(double value);

/**
 * Sets on @p header the resolution for @p format from @p pixelSize (metres), the text attributes
 * "stylos:pixel_size_m", "stylos:content" = @p content, every entry of @p metadata, "Software", and
 * the ImageDescription that repeats them as "key=value" lines.
 */
void addImageMetadata(ImageHeader& header, ImageFileFormat format, double pixelSize, const std::string& content,
                      const std::map<std::string, std::string>& metadata);

} // namespace stylos::core::image
