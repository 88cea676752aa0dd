#pragma once
/** @file
 * @brief Per-leaf class ids of an annotation layer, stored in the `.poct` itself as the UInt8 × 1 attribute
 *        layer "material" or "toolmark" (one byte per leaf, breadth-first leaf order; 0 = unlabelled).
 *        The cells' checksums in the same file tie the labels to their octree: a label layer can only
 *        be written with exactly one value per leaf.
 *
 * Writes are atomic (the whole `.poct` goes to a temporary name beside the target and is renamed): on any
 * error nothing is left and an existing file is untouched; rewriting the octree's own file is allowed.
 * Thread-safety: reentrant (the octree is only read). Failure modes: readLeafLabels — Malformed when the
 * file holds a layer of that name of another type or size (naming the file); writeLeafLabels —
 * InvalidArgument naming the output and the octree's file when the label count is not the leaf count,
 * WriteFailed, Cancelled, and the errors of PackedOctree::open when rewriting in place.
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/Progress.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace stylos::core::annotation {

/** @brief The leaf count of @p octree (cells at its deepest level). */
inline std::uint64_t leafCount(const octree::PackedOctree& octree) { return octree.cellCount(octree.depth()); }

/** @brief The labels of @p layer, one per leaf; all zeros when the file has no such layer. */
Result<std::vector<std::uint8_t>> readLeafLabels(const octree::PackedOctree& octree, AnnotationLayer layer);

/** @brief The attribute layer that stores @p labels (UInt8 × 1, named layerName(@p layer)). */
octree::AttributeLayer labelAttribute(AnnotationLayer layer, std::span<const std::uint8_t> labels);

/**
 * @brief Writes @p octree to @p output with @p attribute added or replacing the layer of the same name (the
 *        cells and the other layers unchanged, in file order). In place (setPoctAttributeLayer) when @p output
 *        is the octree's own file. @p progress gets the fraction of cells written (new file only).
 * @return the size of the written file, or WriteFailed, InvalidArgument (wrong size), Cancelled.
 */
Result<std::uint64_t> writeAttributePoct(const octree::PackedOctree& octree, octree::AttributeLayer attribute,
                                         const std::filesystem::path& output, ProgressSink* progress = nullptr);

/**
 * @brief Writes @p octree to @p output with every layer of @p attributes added or replacing the layer of the
 *        same name, in one pass (writePoct: atomic). @p output may be the octree's own file: the new file
 *        replaces it by rename, and the opened @p octree stays valid (it maps the old one).
 * @return the size of the written file, or InvalidArgument (a layer of the wrong size, or two of one name),
 *         WriteFailed, Cancelled.
 */
Result<std::uint64_t> writeAttributesPoct(const octree::PackedOctree& octree,
                                          std::vector<octree::AttributeLayer> attributes,
                                          const std::filesystem::path& output, ProgressSink* progress = nullptr);
/** @brief Stores @p labels (one per leaf) as @p layer of @p octree in @p output (see writeAttributePoct). */
Result<std::uint64_t> writeLeafLabels(const octree::PackedOctree& octree, AnnotationLayer layer,
                                      std::span<const std::uint8_t> labels, const std::filesystem::path& output,
                                      ProgressSink* progress = nullptr);

} // namespace stylos::core::annotation
