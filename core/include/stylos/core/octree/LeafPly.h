#pragma once
/** @file
 * @brief A binary PLY of an octree's leaves: one vertex per leaf centre (`x y z` double, metres, the octree's
 *        frame) with per-leaf columns as properties, streamed in batches of 64 Ki leaves and written
 *        atomically (PlyWriter: a temporary file renamed by finish(); nothing is left on error or cancel).
 *        The one writer behind `stylos-cli ao -o OUT.ply` (ambient) and `stylos-cli export` (annotation layers).
 *        Thread-safety: reentrant. Failure modes: WriteFailed naming the output, Cancelled.
 */
#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace stylos::core::octree {

/** @brief One property of the leaves: its name, its PLY type and its value at leaf index (PackedOctree's). */
struct LeafPlyColumn {
    std::string name;
    io::PlyScalarType type = io::PlyScalarType::Float32;
    std::function<double(std::uint64_t leaf)> value;
};

/** @brief Writes the leaves of @p octree with @p columns (in that order) to @p output, @p comment in the
 *         header; returns the number of points written. Progress rises to 1, cancel checked every batch. */
Result<std::uint64_t> writeLeafPly(const PackedOctree& octree, const std::vector<LeafPlyColumn>& columns,
                                   const std::string& comment, const std::filesystem::path& output,
                                   ProgressSink* progress = nullptr);

} // namespace stylos::core::octree
