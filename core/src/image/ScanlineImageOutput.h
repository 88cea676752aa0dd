#pragma once
// Internal: writes a grey + alpha image scanline by scanline through OpenImageIO into a temporary
// file beside the target, then renames it into place (ImageWriter.h describes the result).
#include "ImageMetadata.h"

#include "stylos/core/image/ImageWriter.h"

#include <filesystem>
#include <functional>
#include <string>

namespace stylos::core::image {

/** What to write: size, file and sample formats, and the metadata that goes with it. */
struct ScanlineImageJob {
    int width = 0;
    int height = 0;
    double pixelSize = 1.0;    ///< metres
    ImageFileFormat file = ImageFileFormat::Png;
    SampleFormat sample = SampleFormat::UInt8;
    std::string content;       ///< the "stylos:content" attribute
    const ImageWriteOptions* options = nullptr;
};

/** Fills row @p row: width × 2 interleaved samples (grey, alpha) of the job's sample type. */
using ScanlineFiller = std::function<void(int row, void* samples)>;

/**
 * @brief Writes the job's rows, top first, with one row buffer; atomic (TemporaryImageFile).
 * @return WriteFailed naming @p target with OpenImageIO's error, Cancelled when the job's progress
 *         sink asks (checked every row); nothing is left behind on either.
 */
Status writeScanlineImage(const std::filesystem::path& target, const ScanlineImageJob& job,
                          const ScanlineFiller& fill);

} // namespace stylos::core::image
