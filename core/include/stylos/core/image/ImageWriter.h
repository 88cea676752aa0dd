#pragma once
/** @file
 * @brief Writes développées (shadings and raw heights) as image files through OpenImageIO, grey +
 *        alpha, with the pixel size in the metadata. Atomic: nothing is left on failure.
 *
 * **Formats** (by the path's extension, case-insensitive; anything else is InvalidArgument):
 * | extension     | shading (writeShadedImage)        | heights (writeHeightImage) |
 * |---------------|-----------------------------------|----------------------------|
 * | .png          | UInt8 (default), UInt16           | refused                    |
 * | .tif / .tiff  | UInt8, UInt16 (default), Float32  | Float32 (default, only)    |
 * | .exr          | Float32 (default, only)           | Float32 (default, only)    |
 * Other combinations (float PNG, 8/16-bit EXR, integer heights) are refused with InvalidArgument.
 *
 * **Pixels**: two channels "Y" (grey) and "A" (alpha), row 0 at the top, unassociated alpha (the
 * grey is not multiplied by alpha; it makes no difference here since alpha is 0 or 1 and the grey
 * is 0 where alpha is 0). Shading: grey = the value clamped to [0, 1] (NaN → 0), rounded to nearest
 * (UInt8: round(v · 255), UInt16: round(v · 65535), Float32: the clamped value); alpha = coverage
 * (full scale or 0); uncovered pixels get grey 0 whatever their value. Heights: grey = the height
 * in metres, exactly as stored; alpha = 1 on Measured and Filled pixels, 0 on Empty ones, whose grey
 * is written 0.
 *
 * **Metadata** (the pixel size p in metres):
 * - the resolution, so that viewers show the true scale: PNG: a pHYs chunk of round(1 / p) pixels
 *   per metre (OIIO reads it back as XResolution in dots per inch, ResolutionUnit "inch"); TIFF:
 *   XResolution = YResolution = 0.01 / p pixels per cm, ResolutionUnit cm; EXR: the standard
 *   xDensity attribute = 0.0254 / p pixels per inch (read back as XResolution, ResolutionUnit
 *   "in"). Not written on PNG when round(1 / p) is 0 (pixels larger than 2 m).
 * - text attributes "stylos:pixel_size_m" (p as the shortest fixed-point decimal that reads back
 *   to the same double, e.g. "0.0005"), "stylos:content" ("shading" or "height_m"), every entry of ImageWriteOptions::metadata
 *   and "Software" = "Stylos". PNG stores them as text chunks and EXR as string header attributes;
 *   TIFF cannot hold custom tags, so:
 * - "ImageDescription" (all formats) repeats every stylos/metadata attribute as lines
 *   "key=value", in key order (the only place TIFF keeps them).
 *
 * **Atomic writes**: the image goes to a temporary file ".NAME.tmp-XXXXXXXXXXXXXXXX.EXT" in the
 * target's folder, renamed over the target only when complete. On any failure or cancel the
 * temporary is removed and an existing target is left untouched.
 *
 * **Memory and speed**: pixels are converted and written one scanline at a time (one row buffer;
 * no full-size copy). Lossless compression tuned for speed: PNG deflate level 1 with the SUB filter,
 * TIFF zip level 1 (BigTIFF when the raw pixels exceed 3.5 GiB), EXR "zips".
 *
 * Units: pixel size in metres, heights in metres. Thread-safety: reentrant (concurrent calls on
 * different paths are safe). Failure modes: InvalidArgument naming the path (unsupported extension
 * or sample format, 0-pixel image, pixel size not positive and finite, a metadata key or value that
 * cannot be stored); WriteFailed naming the path and OpenImageIO's or the system's error (missing
 * or unwritable folder, disk full, the target is a folder); Cancelled when the progress sink asks.
 */
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/shading/ShadedImage.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace stylos::core::image {

enum class SampleFormat { UInt8, UInt16, Float32 };

struct ImageWriteOptions {
    /** Absent: the extension's default (see the table in the file comment). */
    std::optional<SampleFormat> format;
    /**
     * Extra text metadata (e.g. "stylos:shading" → "skydome"). A key is "namespace:name" (at most
     * 79 characters of letters, digits, '_', '.', '-', ':'); the namespace must not be "oiio" nor
     * an OpenImageIO format name ("png", "tiff", "openexr"…, which would steer the writer), and the
     * keys "stylos:pixel_size_m" and "stylos:content" are the writer's own. Values are UTF-8
     * without line breaks or NUL. Anything else: InvalidArgument.
     */
    std::map<std::string, std::string> metadata;
    /** Optional: updated once per scanline group, polled for cancel (→ Cancelled, nothing left). */
    ProgressSink* progress = nullptr;
};

/** @brief A shading value as the 8-bit sample writeShadedImage() stores: clamped to [0, 1] (NaN → 0),
 *         round(v · 255). The workbench's images use it too, so both show the same levels. */
std::uint8_t shadeToByte(float v);

/** @brief Writes the shading (values in [0, 1], coverage as alpha); see the file comment. */
Status writeShadedImage(const shading::ShadedImage& image, const std::filesystem::path& path,
                        const ImageWriteOptions& options = {});
/** @brief Writes the heights (metres) as float grey + alpha (0 on Empty pixels); TIFF or EXR only. */
Status writeHeightImage(const shading::HeightField& field, const std::filesystem::path& path,
                        const ImageWriteOptions& options = {});

} // namespace stylos::core::image
