#pragma once
/** @file
 * @brief Label rasters aligned with a développée: 8-bit images of class ids (0 = unlabelled) on exactly the
 *        grid of a développée's map (unroll::UnrollMap, the `.png.json` sidecar of `stylos-cli unroll`), and
 *        the transfer between such a raster and the per-leaf labels of the octree the développée was made of.
 *
 * Leaf → pixel: the leaf's centre (metres, the octree's frame = the frame of its développée's map) goes
 * through UnrollMap::pixelOf; the pixel is (floor(column), floor(row)) when inside the image, else none.
 * Nearest neighbour only: ids are never interpolated, blended or resampled, so no class is ever invented.
 * - applyLabelRaster: every leaf whose pixel holds c ≠ 0 gets c; the others keep their label.
 * - labelRasterFromLeaves: each pixel gets the most frequent label of the leaves landing in it (0 counts as a
 *   label; a tie goes to the smaller id); pixels no leaf lands in get 0.
 * Note: every leaf is mapped, whatever its height off the surface; on a drum the bed faces project onto the
 * top and bottom rows, so paint those rows only to label the faces too.
 *
 * Files: PNG or TIFF (by extension, case-insensitive), one 8-bit channel; reading also accepts grey + alpha
 * (the alpha is ignored) and refuses colour, palette-expanded, 16-bit or float images (a label raster holds
 * ids, not colours). Writing: grey 8-bit, PNG deflate / TIFF zip, atomically (temporary file beside the
 * target, renamed at the end), with "stylos:content" = "labels" and the pixel size as ImageWriter writes it.
 *
 * Cost: one pixelOf per leaf (~50 ns); labelRasterFromLeaves sorts 8 bytes per mapped leaf.
 * Thread-safety: reentrant. Failure modes: NotFound / Unreadable / UnknownFormat / Unsupported naming the
 * image; InvalidArgument naming the raster when its size differs from the map's or it holds an id outside the
 * legend (with the first such pixel), or naming the output for a bad extension; WriteFailed; Cancelled.
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/unroll/UnrollMap.h"
#include "stylos/core/util/Progress.h"

#include <cstdint>
#include <filesystem>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace stylos::core::annotation {

/** @brief Class ids, row 0 at the top, row-major. */
struct LabelRaster {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> ids; ///< width × height

    LabelRaster() = default;
    LabelRaster(int w, int h) : width(w), height(h), ids(std::size_t(w) * std::size_t(h), 0) {}
    std::uint8_t& at(int column, int row) { return ids[std::size_t(row) * std::size_t(width) + std::size_t(column)]; }
    std::uint8_t at(int column, int row) const { return ids[std::size_t(row) * std::size_t(width) + std::size_t(column)]; }
};

Result<LabelRaster> readLabelRaster(const std::filesystem::path& path);
/** @brief Writes @p raster (PNG or TIFF) atomically; @p pixelSize (metres, > 0) goes into the metadata. */
Status writeLabelRaster(const LabelRaster& raster, const std::filesystem::path& path, double pixelSize);

/**
 * @brief InvalidArgument naming @p rasterName when @p raster's size is not @p map's (naming @p mapName too) or
 *        a pixel holds an id ≠ 0 that @p legend lacks in @p layer; success otherwise.
 */
Status checkLabelRaster(const LabelRaster& raster, const std::string& rasterName, const unroll::UnrollMap& map,
                        const std::string& mapName, const Legend& legend, AnnotationLayer layer);

/**
 * @brief The pixel index (row · width + column) of every leaf, in leaf order; −1 where off the image.
 * @param visibleDepth metres, finite: only the surface the développée shows — a leaf seen edge-on (its normal
 *        within 17° of the surface's plane, |n · outward| < 0.3: a fracture or bed face) is left out (−1), and so
 *        is one lower (in the map's height) than the highest leaf of its pixel that is not, by more than this (a
 *        fragment's inner break face), or lower than the highest of the pixels within two of its own by more than
 *        twice this (a pixel of a sparse scan that no outer leaf lands in). Infinite (the default): every leaf,
 *        whatever its height and facing.
 */
Result<std::vector<std::int64_t>> leafPixels(const octree::PackedOctree& octree, const unroll::UnrollMap& map,
                                             ProgressSink* progress = nullptr,
                                             double visibleDepth = std::numeric_limits<double>::infinity());

/**
 * @brief The visibleDepth of painting on a développée of @p pixelSize metres (the workbench's brush and fills,
 *        `stylos-cli annotate`): ten pixels, at least 10 mm. A flute's wall within a pixel stays in (a semicircular
 *        flute of radius ρ drops √(2ρP) in its first pixel column: 8.5 mm for ρ = 36 mm, P = 1 mm); a fragment's
 *        inner break face, tens of millimetres down, does not, so its area is not counted with the outer surface's.
 */
double paintDepth(double pixelSize);

/** @brief Sets labels[i] = raster id at pixels[i] where that id ≠ 0; returns how many labels changed.
 *         Preconditions (asserted): labels and pixels of equal size, pixels inside the raster or −1. */
std::uint64_t applyLabelRaster(const LabelRaster& raster, std::span<const std::int64_t> pixels,
                               std::span<std::uint8_t> labels);

/** @brief The raster of @p width × @p height whose pixels hold the majority label of their leaves. */
LabelRaster labelRasterFromLeaves(std::span<const std::uint8_t> labels, std::span<const std::int64_t> pixels,
                                  int width, int height);

} // namespace stylos::core::annotation
