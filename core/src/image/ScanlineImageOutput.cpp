#include "ScanlineImageOutput.h"

#include "TemporaryImageFile.h"

#include "stylos/core/image/ImageLibrary.h"

#include <cassert>
#include <cstddef>
#include <memory>
#include <vector>

namespace stylos::core::image {

namespace {

/** Above this many bytes of raw pixels a TIFF is written as BigTIFF (classic TIFF stops at 4 GiB). */
constexpr double kBigTiffRawBytes = 3.5 * 1024.0 * 1024.0 * 1024.0;

ImageSample typeOf(SampleFormat sample)
{
    switch (sample) {
    case SampleFormat::UInt8: return ImageSample::UInt8;
    case SampleFormat::UInt16: return ImageSample::UInt16;
    case SampleFormat::Float32: return ImageSample::Float32;
    }
    return ImageSample::UInt8;
}

Error failure(const std::filesystem::path& target, const std::string& problem)
{
    return Error::at(ErrorCode::WriteFailed, target.string(), "", problem);
}

ImageHeader makeHeader(const ScanlineImageJob& job)
{
    ImageHeader header;
    header.width = job.width;
    header.height = job.height;
    header.channels = 2;
    header.sample = typeOf(job.sample);
    header.channelNames = {"Y", "A"};
    header.alphaChannel = 1;
    header.set("oiio:UnassociatedAlpha", 1);
    // Deflate at its fastest level (PNG and TIFF): on a 4096² noisy shading, 4-8x less time than the
    // default level 6 for 5-10% more bytes (up to 2x more on perfectly smooth images; 3x less CPU on
    // float TIFF heights for 3% more bytes).
    if (job.file == ImageFileFormat::Png) {
        header.set("png:compressionLevel", 1);
        header.set("png:filter", 16); // PNG_FILTER_SUB: the fastest filter that still helps deflate
    }
    // OpenEXR: zip one scanline per block: ~30% less CPU than 16-line "zip" for 2% more bytes.
    if (job.file == ImageFileFormat::Exr) header.set("compression", std::string("zips"));
    if (job.file == ImageFileFormat::Tiff) {
        header.set("compression", std::string("zip"));
        header.set("tiff:zipquality", 1);
        const double rawBytes = double(job.width) * double(job.height) * 2.0 * double(sampleBytes(header.sample));
        if (rawBytes > kBigTiffRawBytes) header.set("tiff:bigtiff", 1);
    }
    addImageMetadata(header, job.file, job.pixelSize, job.content, job.options->metadata);
    return header;
}

} // namespace

Status writeScanlineImage(const std::filesystem::path& target, const ScanlineImageJob& job,
                          const ScanlineFiller& fill)
{
    assert(job.options && job.width > 0 && job.height > 0 && "writeScanlineImage(): incomplete job");
    auto temporary = TemporaryImageFile::beside(target);
    if (!temporary) return temporary.error();
    const std::string temporaryName = temporary->path().string();
    const ImageHeader header = makeHeader(job);
    auto opened = openImageWriter(temporaryName, header, target.string());
    if (!opened) return opened.error();
    // Declared after `temporary`: destroyed (closed, its errors dropped) before the temporary file is removed.
    std::unique_ptr<ImageFileWriter> out = std::move(opened.value());

    std::vector<std::byte> row(std::size_t(job.width) * 2 * sampleBytes(header.sample));
    ProgressSink* progress = job.options->progress;
    for (int y = 0; y < job.height; ++y) {
        if (progress && progress->isCancelRequested())
            return Error::at(ErrorCode::Cancelled, target.string(), "", "cancelled while writing row " + std::to_string(y));
        fill(y, row.data());
        if (!out->writeScanline(y, header.sample, row.data()))
            return failure(target, "writing row " + std::to_string(y) + ": " + out->takeError());
        if (progress && (y % 64 == 63 || y + 1 == job.height)) progress->update(double(y + 1) / double(job.height));
    }
    if (!out->close()) return failure(target, "finishing the file: " + out->takeError());
    out.reset();
    return temporary->commit();
}

} // namespace stylos::core::image
