#pragma once
/** @file
 * @brief Reads a whole cloud into memory from any supported point file or from the cells of a packed
 *        octree (.poct), for whole-cloud algorithms (the surface fit, unrolling).
 *
 * Point files (io::pointFileExtensions()) are streamed through io::openPointReader; positions are
 * kept relative to the first point (rounded to the metre, so the origin is a round number) and the
 * file's normals are kept when it has them. A `.poct` (recognised by its signature, whatever its
 * extension) gives one point per cell of the chosen level — its centre and its averaged normal —
 * and its cell edge as the spacing. Non-finite points are skipped by the readers (counted there).
 *
 * Memory: 12 bytes per point, 24 with normals; a limit can be set, over which the load stops with
 * OutOfBudget naming the file rather than exhaust the machine. Units: metres (the file's own).
 * Thread-safety: reentrant. Failure modes: the reader's errors (NotFound, Unreadable, UnknownFormat,
 * Unsupported, Malformed, Truncated, Empty), Empty when no point is left, OutOfBudget, Cancelled.
 */
#include "stylos/core/cloud/PointCloud.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <filesystem>

namespace stylos::core::cloud {

struct CloudLoadOptions {
    io::ReadOptions read;       ///< text column layout, for text files
    int octreeLevel = -1;       ///< .poct: the level whose cells become points; −1 = the leaves
    bool keepNormals = true;    ///< false: drop normals to halve the memory
    std::uint64_t maxBytes = 0; ///< 0 = no limit; else OutOfBudget when the arrays would exceed it
};

/** @brief True when @p path starts with the .poct signature (false when unreadable). */
bool isPoctPath(const std::filesystem::path& path);

/** @brief Loads @p path (see the file comment). */
Result<PointCloud> loadPointCloud(const std::filesystem::path& path, const CloudLoadOptions& options = {},
                                  ProgressSink* progress = nullptr);

} // namespace stylos::core::cloud
