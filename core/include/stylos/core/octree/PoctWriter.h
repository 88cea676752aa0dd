#pragma once
/** @file
 * @brief Writing a `.poct` file (layout in docs/file-format.md): header, section table, then the cells
 *        of every level in breadth-first order with implicit children — child masks for the inner
 *        levels, normal codes for all levels — and per-leaf attribute layers, each section with its
 *        own checksum (XXH64). Weights and child indices of the construction structure are dropped.
 *
 * Files are written to a temporary name in the same folder and renamed at the end: on any error
 * nothing is left behind and an existing file of that name is untouched. Deterministic: the same
 * octree gives the same bytes (no time stamps, no build details in the file).
 * Thread-safety: reentrant.
 */
#include "stylos/core/octree/OctreeLevels.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace stylos::core::octree {

/** @brief The `.poct` format version this code writes, and the newest it reads. */
inline constexpr std::uint32_t PoctFormatVersion = 1;

/** @brief Element type of an attribute layer. */
enum class AttributeType : std::uint8_t { UInt8 = 1, UInt16 = 2, Float32 = 3 };

/**
 * @brief A per-leaf attribute layer: `components` values of `type` per leaf, in leaf order
 *        (breadth-first order of the leaf level). `bytes` holds leaves × components × size(type) bytes,
 *        little-endian. Names are ASCII, 1..15 characters, unique in a file; "colour" (UInt8 × 3) is the
 *        average RGB the builders write; "ambient" (Float32) holds ambient occlusion and
 *        "material" / "toolmark" (UInt8) the annotation class ids (core/annotation/LeafLabels.h).
 */
struct AttributeLayer {
    std::string name;
    AttributeType type = AttributeType::UInt8;
    std::uint8_t components = 1;
    std::vector<std::uint8_t> bytes;
};

/**
 * @brief A layer still being computed (on another thread) when the writing starts: its name, type and
 *        components, and `finish`, which the writer calls once the cells are written and which returns the
 *        layer (the same name, type and components; waiting for it if need be).
 */
struct PendingLayer {
    std::string name;
    AttributeType type = AttributeType::UInt8;
    std::uint8_t components = 1;
    std::function<AttributeLayer()> finish;
};

/**
 * @brief Writes @p levels (and the colour layer when it has colour, plus @p extraLayers) to @p path,
 *        in one pass over the levels (block by block: memory stays at a few MiB of buffers).
 *        @p progress (optional) gets the fraction of cells written after each block and can cancel.
 * @return the file size in bytes, or WriteFailed (message names the file and the system error),
 *         InvalidArgument (a layer with a bad name, duplicate name or wrong size; a description that
 *         contradicts the cells, masks whose children do not add up, a cell without children), or
 *         Cancelled. On any error nothing is left at @p path's folder and an existing file is kept.
 */
Result<std::uint64_t> writePoct(const OctreeLevels& levels, const std::filesystem::path& path,
                                std::span<const AttributeLayer> extraLayers = {}, ProgressSink* progress = nullptr);
/** @brief writePoct() with, after @p extraLayers, the @p pendingLayers, whose bytes are fetched once the cells
 *         are written: a layer computed from the same octree on another thread meanwhile. */
Result<std::uint64_t> writePoct(const OctreeLevels& levels, const std::filesystem::path& path,
                                std::span<const AttributeLayer> extraLayers, std::span<const PendingLayer> pendingLayers,
                                ProgressSink* progress = nullptr);

/**
 * @brief Rewrites the `.poct` at @p path with @p layer added, or replacing the layer of the same name
 *        (atomic, like writePoct). The cells are copied unchanged. Used to store ambient occlusion and
 *        annotation classes.
 * @return the new file size, or the errors of PackedOctree::open and writePoct.
 */
Result<std::uint64_t> setPoctAttributeLayer(const std::filesystem::path& path, const AttributeLayer& layer);

} // namespace stylos::core::octree
