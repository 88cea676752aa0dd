#pragma once
/** @file
 * @brief Writing the 3D skydome's per-leaf values: as the "ambient" attribute layer of a `.poct`
 *        (Float32 × 1, one value per leaf in breadth-first leaf order), or as a binary PLY of the leaf
 *        centres, `x y z` (double, metres, the octree's frame) + `float ambient`.
 *
 * Both outputs are written atomically (a temporary name beside the target, renamed at the end): on any
 * error or cancel nothing is left and an existing file of that name is untouched.
 * Thread-safety: reentrant (the octree is only read). Failure modes: InvalidArgument (a value count
 * other than the octree's leaf count), WriteFailed (the message names the file and the system error),
 * Cancelled; for writeAmbientPoct in place also the errors of PackedOctree::open.
 */
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/octree/PoctWriter.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <filesystem>
#include <span>

namespace stylos::core::ao {

/** @brief The name of the skydome's attribute layer in a `.poct`. */
inline constexpr const char* AmbientLayerName = "ambient";

/** @brief The layer "ambient", Float32 × 1, holding @p perLeaf (little-endian). */
octree::AttributeLayer ambientLayer(std::span<const float> perLeaf);

/**
 * @brief Stores @p perLeaf (one value per leaf of @p octree) as the "ambient" layer. When @p output is
 *        the octree's own file, the file is rewritten in place (setPoctAttributeLayer: the cells and the
 *        other layers are copied unchanged, an existing "ambient" layer is replaced); otherwise a new
 *        `.poct` is written with the octree's cells, its other layers in file order and "ambient" (in
 *        place of the old one, or last). @p progress (optional) gets the fraction of cells written
 *        (new file only) and can cancel.
 * @return the size of the written file in bytes, or the errors in the file comment.
 */
Result<std::uint64_t> writeAmbientPoct(const octree::PackedOctree& octree, std::span<const float> perLeaf,
                                       const std::filesystem::path& output, ProgressSink* progress = nullptr);

/**
 * @brief Writes one PLY vertex per leaf of @p octree, in leaf order: its centre and @p perLeaf's value.
 *        Progress: the fraction of leaves written; cancel is checked every 64 Ki leaves.
 * @return the number of vertices written (the leaf count), or the errors in the file comment.
 */
Result<std::uint64_t> writeAmbientPly(const octree::PackedOctree& octree, std::span<const float> perLeaf,
                                      const std::filesystem::path& output, ProgressSink* progress = nullptr);

} // namespace stylos::core::ao
