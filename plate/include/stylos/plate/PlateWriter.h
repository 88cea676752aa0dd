#pragma once
/** @file
 * @brief Writes a plate page: PDF (QPdfWriter: page size in mm — Qt rounds the MediaBox to whole points, so a
 *        page is within 0.18 mm —, text, bars, rulers and hatches as vectors, images lossless (never JPEG), the
 *        fonts embedded), SVG (QSvgGenerator, width and height in mm, 0.1 mm user units), TIFF (ZIP) or PNG at
 *        the plate's dpi with the resolution written in the file, 8 or 16 bits, grey when nothing is in colour.
 *
 * The same inputs give the same bytes: the PDF's creation date and document id (which Qt sets from the
 * clock and at random) are replaced by fixed values of the same length, so nothing else moves.
 * Every file is written to a temporary file beside the target and renamed at the end: a failure leaves no
 * file and no half-written plate. Failure modes: InvalidArgument (an unknown extension), WriteFailed (naming
 * the file), Cancelled. The document title (PDF, SVG) is the caption, cut at a word within 200 characters with an
 * ellipsis. Thread-safety: call from one thread (QPainter, fonts).
 */
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"
#include "stylos/plate/PlatePainter.h"

#include <filesystem>
#include <optional>

namespace stylos::plate {

enum class PlateFormat { Pdf, Svg, Tiff, Png };

/** @brief The format of @p path by its extension (.pdf, .svg, .tif / .tiff, .png; case-insensitive). */
std::optional<PlateFormat> plateFormatOf(const std::filesystem::path& path);

/** @brief The page's size in pixels at the plate's dpi (raster outputs). */
QSize rasterPageSize(const PlateContent& plate);

/**
 * @brief Writes @p plate to @p output (its format by the extension). With @p progress, a cancel requested before the
 *        finished file is renamed into place gives ErrorCode::Cancelled, the partial file removed and an existing
 *        @p output left as it was (the drawing itself is not interrupted).
 */
core::Status writePlate(const PlateContent& plate, const std::filesystem::path& output,
                        const core::ProgressSink* progress = nullptr);

/**
 * @brief Writes one panel's picture alone (Export view image): PNG or TIFF (ZIP) by extension, 8 or 16 bits,
 *        grey or RGB as the picture is, with "stylos:pixel_size_m" (metres on the object per pixel) in the file;
 *        atomically. InvalidArgument for another extension, WriteFailed naming the file; Cancelled (nothing written)
 *        when @p progress asks before the file is renamed into place.
 */
core::Status writePanelImage(const core::plate::PanelImage& image, const std::filesystem::path& output, int bits,
                             const core::ProgressSink* progress = nullptr);

} // namespace stylos::plate
