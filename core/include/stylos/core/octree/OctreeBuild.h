#pragma once
/** @file
 * @brief Building a packed octree from a point source: the paper's two construction algorithms
 *        (Duguet et al., VAST 2004, section 3) and the `.poct` file they end in.
 *
 *  - **Optimal**: pass 0 scans the bounds; then, level by level, one marking pass over the input sets
 *    the child bits of the cells of the current level, and exact-size child tables are allocated for
 *    the next level; a last pass averages the points into the leaves. The input is re-read for each
 *    pass, so memory holds only cells (7 bytes each, 10 with colour).
 *  - **Streaming**: after the bounds scan, one pass inserts each point (Populate), growing child tables
 *    by re-allocation; freed tables go to free lists per size and are reused.
 *  - Then **pull**: every inner cell's normal is the renormalised count-weighted average of its
 *    children's normals.
 *
 * Both builders give the same octree for the same input (same points in the same order): a leaf's normal
 * is the running count-weighted average of the normals falling in it, re-encoded after each point, in
 * input order; its colour likewise. So their `.poct` files are byte-identical.
 *
 * Points without a normal (a source without normals) are refused by buildOctree(); buildOctreeFile()
 * estimates normals first (normals::estimateNormalsForFile into a temporary file).
 *
 * Memory: the construction structure counts against `memoryLimit` (cells, chunk tables and free lists);
 * the leaves' spacing layer (4 bytes a leaf, computed once the structure is complete and written beside it) counts
 * too, checked before it is allocated. `stylos-cli build --memory-limit` passes the process's limit minus what the
 * process holds at start and 64 MiB of buffers, so that the whole process's peak stays within what the user gave
 * (measured: peak ≤ baseline + 64 MiB + 7 B × cells + 4 B × leaves);
 * read buffers (a few batches of 16 Ki points) and the normal tables (< 2 MiB) are outside it. A build
 * that would exceed the limit stops with ErrorCode::OutOfBudget and a message giving the bytes it needed
 * and the limit ("the octree needs 812 MiB at level 12 but the memory limit (--memory-limit) is 512 MiB";
 * Optimal knows the exact size of each level before allocating it, Streaming stops when the next chunk
 * would not fit); nothing is written.
 *
 * Progress: a fraction of all passes (the bounds scan included) and the pull, then the writing; cancel is
 * checked after every batch of 16 Ki points (Cancelled, nothing written).
 * Thread-safety: reentrant; a build uses `threads` worker threads plus one thread reading the input.
 *
 * Implementation (core/src/octree): ConstructionOctree (CellArena cells), OptimalBuilder, StreamingBuilder,
 * PointPass (the reader thread: reading, quantising, encoding the first-point normal codes), then
 * writePoct().
 */
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/octree/NormalCode.h"
#include "stylos/core/octree/RootBox.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stylos::core::octree {

class ConstructionOctree;

enum class BuildMethod { Optimal, Streaming };

/** @brief "optimal" or "streaming". */
const char* buildMethodName(BuildMethod method);

/** @brief Opens the input afresh, positioned at its first point; called once per pass. */
using PointSourceFactory = std::function<Result<std::unique_ptr<io::PointReader>>()>;

struct BuildOptions {
    int depth = 12;                                            ///< leaf level, MinOctreeDepth..MaxOctreeDepth
    BuildMethod method = BuildMethod::Optimal;
    NormalCodeKind normalCode = NormalCodeKind::Octahedral16;
    std::uint64_t memoryLimit = 0;                             ///< bytes for the construction structure; 0: none
    std::optional<RootBox> box;                                ///< skip the bounds scan; points outside are clamped
    unsigned threads = 2;                                      ///< ≥ 1
};

/** @brief What a build did; the keys of `stylos-cli build --json`. */
struct BuildReport {
    std::uint64_t points = 0;               ///< points inserted
    std::uint64_t skippedPoints = 0;        ///< non-finite points the reader dropped
    std::uint64_t cells = 0;                ///< all levels
    std::uint64_t leaves = 0;               ///< cells at the leaf level
    int depth = 0;
    BuildMethod method = BuildMethod::Optimal;
    std::vector<std::uint64_t> cellsPerLevel;
    std::uint64_t constructionBytes = 0;    ///< peak bytes of the construction structure
    std::uint64_t fileBytes = 0;            ///< size of the written .poct (0 when not written)
    std::uint64_t passes = 0;               ///< passes over the input, the bounds scan included
    bool normalsEstimated = false;          ///< buildOctreeFile estimated the normals first
    std::uint32_t normalScans = 0;          ///< ... scan by scan, over this many scans (0: the cloud whole)
    std::string normalScanColumn;           ///< ... the input's scan column (NormalFileReport::scanColumn)
    double seconds = 0;                     ///< wall time of the whole build, writing included
};

/**
 * @brief Builds the construction structure of the points @p open yields, pulled and ready for writing
 *        (what buildOctree() writes; tests and in-memory pipelines use it directly). Fills @p report
 *        (when given) except fileBytes; seconds is the build time.
 * @return the octree, or the errors of buildOctree() except WriteFailed; Malformed if the source yields
 *         different points from one pass to the next.
 */
Result<std::unique_ptr<ConstructionOctree>> buildConstructionOctree(const PointSourceFactory& open,
                                                                    const BuildOptions& options,
                                                                    ProgressSink* progress = nullptr,
                                                                    BuildReport* report = nullptr);

/**
 * @brief Builds the octree of the points @p open yields and writes it to @p output (`.poct`, written
 *        to a temporary name and renamed: on any error or cancel nothing is left).
 * @return the report, or: the reader's errors; InvalidArgument (depth out of range, threads 0, a
 *         source without normals, a source with no points); OutOfBudget; WriteFailed; Cancelled.
 */
Result<BuildReport> buildOctree(const PointSourceFactory& open, const std::filesystem::path& output,
                                const BuildOptions& options, ProgressSink* progress = nullptr);

/**
 * @brief buildOctree() for a point file in any supported format. A file without normals first gets
 *        them estimated (k-nearest PCA, normals::estimateNormalsForFile, into a temporary folder next to
 *        the output, removed afterwards); the report says so.
 */
Result<BuildReport> buildOctreeFile(const std::filesystem::path& input, const std::filesystem::path& output,
                                    const BuildOptions& options, ProgressSink* progress = nullptr,
                                    const io::ReadOptions& read = {});

} // namespace stylos::core::octree
