#include "stylos/core/image/ImageWriter.h"

#include "ImageMetadata.h"
#include "ScanlineImageOutput.h"

#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

namespace stylos::core::image {

namespace {

Error invalid(const std::filesystem::path& path, const std::string& problem)
{
    return Error::at(ErrorCode::InvalidArgument, path.string(), "", problem);
}

const char* sampleName(SampleFormat sample)
{
    switch (sample) {
    case SampleFormat::UInt8: return "8-bit";
    case SampleFormat::UInt16: return "16-bit";
    case SampleFormat::Float32: return "32-bit float";
    }
    return "?";
}

/** The sample format for a shading in @p file, or InvalidArgument for a combination it cannot hold. */
Result<SampleFormat> shadingSample(const std::filesystem::path& path, ImageFileFormat file,
                                   std::optional<SampleFormat> requested)
{
    switch (file) {
    case ImageFileFormat::Png:
        if (requested == SampleFormat::Float32) return invalid(path, "PNG cannot hold 32-bit float samples (use .tif or .exr)");
        return requested.value_or(SampleFormat::UInt8);
    case ImageFileFormat::Tiff:
        return requested.value_or(SampleFormat::UInt16);
    case ImageFileFormat::Exr:
        if (requested && *requested != SampleFormat::Float32)
            return invalid(path, std::string("OpenEXR images are written as 32-bit float, not ") + sampleName(*requested)
                                     + " (use .png or .tif)");
        return SampleFormat::Float32;
    }
    return invalid(path, "unknown image format");
}

/** Heights are 32-bit float in TIFF or EXR only. */
Status checkHeightFormat(const std::filesystem::path& path, ImageFileFormat file, std::optional<SampleFormat> requested)
{
    if (file == ImageFileFormat::Png)
        return invalid(path, "heights need 32-bit float samples, which PNG cannot hold (use .tif or .exr)");
    if (requested && *requested != SampleFormat::Float32)
        return invalid(path, std::string("heights are written as 32-bit float, not ") + sampleName(*requested));
    return {};
}

Status checkGeometry(const std::filesystem::path& path, int width, int height, double pixelSize)
{
    if (width <= 0 || height <= 0)
        return invalid(path, "cannot write an image of " + std::to_string(width) + " x " + std::to_string(height) + " pixels");
    if (!(pixelSize > 0.0) || !std::isfinite(pixelSize))
        return invalid(path, "pixel size " + std::to_string(pixelSize) + " m is not a positive number");
    return {};
}

/** The shading value @p v clamped to [0, 1] (NaN → 0), rounded to the nearest level of T. */
template <typename T>
T quantise(float v)
{
    if (!(v > 0.0f)) return T(0);
    if constexpr (std::is_floating_point_v<T>) {
        return v < 1.0f ? v : 1.0f;
    } else {
        constexpr double top = double(std::numeric_limits<T>::max());
        return v < 1.0f ? T(double(v) * top + 0.5) : T(top);
    }
}

template <typename T>
void fillShadedRow(const shading::ShadedImage& image, int row, T* out)
{
    constexpr T opaque = std::is_floating_point_v<T> ? T(1) : std::numeric_limits<T>::max();
    const std::size_t first = std::size_t(row) * std::size_t(image.width);
    for (int x = 0; x < image.width; ++x) {
        const bool covered = image.coverage[first + std::size_t(x)] != 0;
        out[2 * x] = covered ? quantise<T>(image.values[first + std::size_t(x)]) : T(0);
        out[2 * x + 1] = covered ? opaque : T(0);
    }
}

void fillHeightRow(const shading::HeightField& field, int row, float* out)
{
    const std::size_t first = field.index(0, row);
    const auto heights = field.heights();
    const auto states = field.states();
    for (int x = 0; x < field.width(); ++x) {
        const bool has = states[first + std::size_t(x)] != shading::PixelState::Empty;
        out[2 * x] = has ? heights[first + std::size_t(x)] : 0.0f;
        out[2 * x + 1] = has ? 1.0f : 0.0f;
    }
}

} // namespace

std::uint8_t shadeToByte(float v) { return quantise<std::uint8_t>(v); }

Status writeShadedImage(const shading::ShadedImage& image, const std::filesystem::path& path,
                        const ImageWriteOptions& options)
{
    auto file = imageFileFormat(path);
    if (!file) return file.error();
    auto sample = shadingSample(path, *file, options.format);
    if (!sample) return sample.error();
    if (auto s = checkGeometry(path, image.width, image.height, image.pixelSize); !s) return s;
    if (auto s = checkMetadata(path, options.metadata); !s) return s;
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    assert(image.values.size() == pixels && image.coverage.size() == pixels
           && "writeShadedImage(): values and coverage must hold width x height elements");
    (void)pixels;

    const ScanlineImageJob job{image.width, image.height, image.pixelSize, *file, *sample, "shading", &options};
    switch (*sample) {
    case SampleFormat::UInt8:
        return writeScanlineImage(path, job, [&](int row, void* out) { fillShadedRow(image, row, static_cast<std::uint8_t*>(out)); });
    case SampleFormat::UInt16:
        return writeScanlineImage(path, job, [&](int row, void* out) { fillShadedRow(image, row, static_cast<std::uint16_t*>(out)); });
    case SampleFormat::Float32:
        return writeScanlineImage(path, job, [&](int row, void* out) { fillShadedRow(image, row, static_cast<float*>(out)); });
    }
    return invalid(path, "unknown sample format");
}

Status writeHeightImage(const shading::HeightField& field, const std::filesystem::path& path,
                        const ImageWriteOptions& options)
{
    auto file = imageFileFormat(path);
    if (!file) return file.error();
    if (auto s = checkHeightFormat(path, *file, options.format); !s) return s;
    if (auto s = checkGeometry(path, field.width(), field.height(), field.pixelSize()); !s) return s;
    if (auto s = checkMetadata(path, options.metadata); !s) return s;

    const ScanlineImageJob job{field.width(), field.height(), field.pixelSize(), *file, SampleFormat::Float32, "height_m",
                               &options};
    return writeScanlineImage(path, job, [&](int row, void* out) { fillHeightRow(field, row, static_cast<float*>(out)); });
}

} // namespace stylos::core::image
