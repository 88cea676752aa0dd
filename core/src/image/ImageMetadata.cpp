#include "ImageMetadata.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>

namespace stylos::core::image {

namespace {

constexpr std::string_view kPixelSizeKey = "stylos:pixel_size_m";
constexpr std::string_view kContentKey = "stylos:content";
constexpr std::size_t kMaxKeyLength = 79; // a PNG text chunk's keyword limit

std::string lowercase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

Error badKey(const std::filesystem::path& path, const std::string& key, const std::string& why)
{
    return Error::at(ErrorCode::InvalidArgument, path.string(), "", "metadata key \"" + key + "\" " + why);
}

/** True when @p ns is "oiio" or the name of an OpenImageIO format (those prefixes steer the writers). */
bool isReservedNamespace(const std::string& ns)
{
    const std::string lower = lowercase(ns);
    if (lower == "oiio" || lower == "exr") return true;
    auto library = imageLibrary(); // without it no image is written, and writing says so
    const std::string formats = library ? (*library)->formatList() : std::string();
    std::string_view rest = formats;
    while (!rest.empty()) {
        const std::size_t comma = rest.find(',');
        if (rest.substr(0, comma) == lower) return true;
        rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
    }
    return false;
}

} // namespace

Result<ImageFileFormat> imageFileFormat(const std::filesystem::path& path)
{
    const std::string extension = lowercase(path.extension().string());
    if (extension == ".png") return ImageFileFormat::Png;
    if (extension == ".tif" || extension == ".tiff") return ImageFileFormat::Tiff;
    if (extension == ".exr") return ImageFileFormat::Exr;
    return Error::at(ErrorCode::InvalidArgument, path.string(), "",
                     "unsupported image extension \"" + path.extension().string() + "\" (use .png, .tif, .tiff or .exr)");
}

Status checkMetadata(const std::filesystem::path& path, const std::map<std::string, std::string>& metadata)
{
    for (const auto& [key, value] : metadata) {
        const std::size_t colon = key.find(':');
        if (colon == std::string::npos || colon == 0 || colon + 1 == key.size())
            return badKey(path, key, "is not of the form namespace:name");
        if (key.size() > kMaxKeyLength)
            return badKey(path, key, "is longer than " + std::to_string(kMaxKeyLength) + " characters");
        const bool plain = std::all_of(key.begin(), key.end(), [](unsigned char c) {
            return std::isalnum(c) || c == '_' || c == '.' || c == '-' || c == ':';
        });
        if (!plain) return badKey(path, key, "may hold only letters, digits, '_', '.', '-' and ':'");
        if (key == kPixelSizeKey || key == kContentKey) return badKey(path, key, "is written by Stylos itself");
        if (isReservedNamespace(key.substr(0, colon)))
            return badKey(path, key, "uses a namespace reserved by OpenImageIO");
        if (value.find_first_of(std::string_view("\r\n\0", 3)) != std::string::npos)
            return Error::at(ErrorCode::InvalidArgument, path.string(), "",
                             "the value of metadata key \"" + key + "\" holds a line break or a NUL");
    }
    return {};
}

std::string shortestDecimal(double value)
{
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed);
    return std::string(text, result.ptr);
}

void addImageMetadata(ImageHeader& header, ImageFileFormat format, double pixelSize, const std::string& content,
                      const std::map<std::string, std::string>& metadata)
{
    switch (format) {
    case ImageFileFormat::Png: {
        // OIIO turns the resolution into the pHYs chunk (integer pixels per metre); it truncates its
        // own unit conversions, so give it whole pixels per metre.
        const double perMetre = std::round(1.0 / pixelSize);
        if (perMetre >= 1.0 && perMetre <= 2147483647.0) {
            header.set("XResolution", float(perMetre));
            header.set("YResolution", float(perMetre));
            header.set("ResolutionUnit", std::string("m"));
        }
        break;
    }
    case ImageFileFormat::Tiff:
        header.set("XResolution", float(0.01 / pixelSize));
        header.set("YResolution", float(0.01 / pixelSize));
        header.set("ResolutionUnit", std::string("cm"));
        break;
    case ImageFileFormat::Exr:
        // OIIO maps XResolution to OpenEXR's standard xDensity (pixels per inch). It converts other
        // units the wrong way (OIIO 2.4), so give it inches directly.
        header.set("XResolution", float(0.0254 / pixelSize));
        header.set("ResolutionUnit", std::string("in"));
        break;
    }

    std::map<std::string, std::string> text = metadata;
    text.emplace(std::string(kPixelSizeKey), shortestDecimal(pixelSize));
    text.emplace(std::string(kContentKey), content);
    std::string description;
    for (const auto& [key, value] : text) {
        header.set(key, value);
        if (!description.empty()) description += '\n';
        description += key + "=" + value;
    }
    header.set("ImageDescription", description);
    header.set("Software", std::string("Stylos"));
}

} // namespace stylos::core::image
