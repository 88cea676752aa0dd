// Label rasters on a développée's grid: 8-bit PNG/TIFF files, checks, and the transfer to and from leaves.
#include "stylos/core/annotation/LabelRaster.h"

#include "stylos/core/annotation/AssemblyLeafIndex.h"
#include "stylos/core/util/TextCase.h"

#include "../image/TemporaryImageFile.h"

#include "stylos/core/image/ImageLibrary.h"

#include <Eigen/Core>

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

namespace stylos::core::annotation {

namespace {

namespace fs = std::filesystem;

bool isRasterExtension(const fs::path& path)
{
    const std::string ext = lowerExtension(path);
    return ext == ".png" || ext == ".tif" || ext == ".tiff";
}

std::string pixelText(std::size_t index, int width)
{
    return "pixel (" + std::to_string(index % std::size_t(width)) + ", " + std::to_string(index / std::size_t(width)) + ")";
}

} // namespace

Result<LabelRaster> readLabelRaster(const fs::path& path)
{
    const std::string name = path.string();
    std::error_code error;
    const auto status = fs::status(path, error);
    if (!fs::exists(status)) return Error::at(ErrorCode::NotFound, name, {}, "no such file");
    if (fs::is_directory(status)) return Error::at(ErrorCode::Unreadable, name, {}, "is a directory");
    if (!isRasterExtension(path)) return Error::at(ErrorCode::UnknownFormat, name, {}, "a label raster must be .png or .tif");
    auto library = image::imageLibrary();
    if (!library) return Error::at(ErrorCode::Unsupported, name, {}, "cannot read images: " + library.error().message);
    std::string problem;
    auto in = (*library)->openReader(name, &problem);
    if (!in) return Error::at(ErrorCode::Unreadable, name, {}, "cannot read the image: " + problem);
    const image::ImageHeader& spec = in->header();
    if (!spec.sampleKnown || spec.sample != image::ImageSample::UInt8)
        return Error::at(ErrorCode::Unsupported, name, {}, "a label raster has 8-bit samples, not " + spec.sampleName);
    if (spec.channels != 1 && !(spec.channels == 2 && spec.alphaChannel == 1))
        return Error::at(ErrorCode::Unsupported, name, {},
                         std::to_string(spec.channels) + " channels: a label raster is one grey channel of class ids, not colours");
    if (spec.width < 1 || spec.height < 1 || spec.depth > 1) return Error::at(ErrorCode::Unsupported, name, {}, "not a 2D image");
    LabelRaster raster(spec.width, spec.height);
    if (!in->readImage(0, 1, image::ImageSample::UInt8, raster.ids.data()))
        return Error::at(ErrorCode::Unreadable, name, {}, "cannot read the pixels: " + in->takeError());
    return raster;
}

Status writeLabelRaster(const LabelRaster& raster, const fs::path& path, double pixelSize)
{
    const std::string name = path.string();
    if (!isRasterExtension(path)) return Error::at(ErrorCode::InvalidArgument, name, {}, "a label raster must be .png or .tif");
    if (raster.width < 1 || raster.height < 1 || raster.ids.size() != std::size_t(raster.width) * std::size_t(raster.height))
        return Error::at(ErrorCode::InvalidArgument, name, {}, "an empty or inconsistent label raster");
    if (!(pixelSize > 0) || !std::isfinite(pixelSize))
        return Error::at(ErrorCode::InvalidArgument, name, {}, "the pixel size must be positive and finite");
    auto temporary = image::TemporaryImageFile::beside(path);
    if (!temporary) return temporary.error();
    image::ImageHeader spec;
    spec.width = raster.width;
    spec.height = raster.height;
    spec.channels = 1;
    spec.sample = image::ImageSample::UInt8;
    spec.channelNames = {"Y"};
    char size[64];
    std::snprintf(size, sizeof size, "%.17g", pixelSize);
    spec.set("stylos:content", std::string("labels"));
    spec.set("stylos:pixel_size_m", std::string(size));
    spec.set("Software", std::string("Stylos"));
    if (lowerExtension(path) == ".png") {
        spec.set("png:compressionLevel", 6);
        spec.set("XResolution", float(0.0254 / pixelSize));
        spec.set("YResolution", float(0.0254 / pixelSize));
        spec.set("ResolutionUnit", std::string("inch"));
    } else {
        spec.set("compression", std::string("zip"));
        spec.set("XResolution", float(0.01 / pixelSize));
        spec.set("YResolution", float(0.01 / pixelSize));
        spec.set("ResolutionUnit", std::string("cm"));
        spec.set("ImageDescription", std::string("stylos:content=labels\nstylos:pixel_size_m=") + size);
    }
    if (auto written = image::writeWholeImage(temporary->path().string(), spec, raster.ids.data(), name); !written)
        return written.error();
    return temporary->commit();
}

Status checkLabelRaster(const LabelRaster& raster, const std::string& rasterName, const unroll::UnrollMap& map,
                        const std::string& mapName, const Legend& legend, AnnotationLayer layer)
{
    if (raster.width != map.width() || raster.height != map.height())
        return Error::at(ErrorCode::InvalidArgument, rasterName, {},
                         std::to_string(raster.width) + " x " + std::to_string(raster.height) + " pixels, but the map " +
                             mapName + " is " + std::to_string(map.width()) + " x " + std::to_string(map.height()));
    std::array<bool, 256> known{};
    known[0] = true;
    for (const LegendClass& c : legend.classes(layer)) known[c.id] = true;
    for (std::size_t i = 0; i < raster.ids.size(); ++i)
        if (!known[raster.ids[i]])
            return Error::at(ErrorCode::InvalidArgument, rasterName, pixelText(i, raster.width),
                             "class id " + std::to_string(raster.ids[i]) + " is not in the " + layerName(layer) +
                                 " legend");
    return {};
}

Result<std::vector<std::int64_t>> leafPixels(const octree::PackedOctree& octree, const unroll::UnrollMap& map,
                                             ProgressSink* progress, double visibleDepth)
{
    return posedLeafPixels(octree, Eigen::Isometry3d::Identity(), map, progress, visibleDepth);
}

double paintDepth(double pixelSize) { return std::max(10.0 * pixelSize, 0.010); }

std::uint64_t applyLabelRaster(const LabelRaster& raster, std::span<const std::int64_t> pixels, std::span<std::uint8_t> labels)
{
    assert(pixels.size() == labels.size() && "applyLabelRaster(): one pixel per label");
    std::uint64_t changed = 0;
    for (std::size_t i = 0; i < labels.size(); ++i) {
        if (pixels[i] < 0) continue;
        assert(std::size_t(pixels[i]) < raster.ids.size() && "applyLabelRaster(): pixel outside the raster");
        const std::uint8_t id = raster.ids[std::size_t(pixels[i])];
        if (id != 0 && labels[i] != id) {
            labels[i] = id;
            ++changed;
        }
    }
    return changed;
}

LabelRaster labelRasterFromLeaves(std::span<const std::uint8_t> labels, std::span<const std::int64_t> pixels, int width,
                                  int height)
{
    assert(pixels.size() == labels.size() && "labelRasterFromLeaves(): one pixel per label");
    LabelRaster raster(width, height);
    std::vector<std::uint64_t> keys; // pixel << 8 | label
    keys.reserve(labels.size());
    for (std::size_t i = 0; i < labels.size(); ++i)
        if (pixels[i] >= 0) keys.push_back(std::uint64_t(pixels[i]) << 8 | labels[i]);
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < keys.size();) {
        const std::uint64_t pixel = keys[i] >> 8;
        std::size_t bestCount = 0;
        std::uint8_t best = 0;
        while (i < keys.size() && keys[i] >> 8 == pixel) {
            std::size_t j = i;
            while (j < keys.size() && keys[j] == keys[i]) ++j;
            if (j - i > bestCount) { // ascending ids: a tie keeps the smaller
                bestCount = j - i;
                best = std::uint8_t(keys[i] & 0xFF);
            }
            i = j;
        }
        raster.ids[pixel] = best;
    }
    return raster;
}

} // namespace stylos::core::annotation
