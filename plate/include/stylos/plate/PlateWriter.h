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
 * the file). Thread-safety: call from one thread (QPainter, fonts).
 */
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

core::Status writePlate(const PlateContent& plate, const std::filesystem::path& output);

/**
 * @brief Writes one panel's picture alone (Export view image): PNG or TIFF (ZIP) by extension, 8 or 16 bits,
 *        grey or RGB as the picture is, with "stylos:pixel_size_m" (metres on the object per pixel) in the file;
 *        atomically. InvalidArgument for another extension, WriteFailed naming the file.
 */
core::Status writePanelImage(const core::plate::PanelImage& image, const std::filesystem::path& output, int bits);

} // namespace stylos::plate
