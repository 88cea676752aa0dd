#pragma once
/** @file
 * @brief Normal estimation from any point file to a binary PLY with normals, in bounded memory.
 *
 * Passes over the input (read through io::openPointReader, so any supported format):
 *  1. count, bounds, centroid and a uniform random sample of 65,536 points (fixed seed). If the whole
 *     cloud fits the memory budget it is kept from this pass and estimated in one piece: the output is
 *     then exactly what estimateNormals() gives (scan by scan: what it gives each scan), in input order.
 *  2. otherwise the cloud is cut into 2^L tiles (median splits of the sample along the longest side of
 *     each cell, so the grid follows the cloud's longest axes; L is the smallest level at which every
 *     tile, with its halo, fits the budget by the sample's count). Each point is written to its tile's
 *     temporary file, and its position to the halo file of every other tile whose box grown by the margin
 *     contains it. The margin comes from the sample (TilePlan.h: 1.5 × the 99th percentile of the k-th
 *     neighbour distance, scaled to full density).
 *  3. one tile at a time: its points and halo are loaded, normals estimated for its own points with the
 *     in-memory kernel (same search frame, bounding-box centre, and same orientation centre, the global
 *     centroid, for all tiles, so orientation is consistent across tiles), and appended to the output.
 *
 * Scans: when the input has a scan column (a scalar named scan_id, scan_index or scan, any case; integers in
 * [0, 65535]) with two scans or more, each point's neighbours are taken from its own scan only (perScan, on by
 * default): where registered scans overlap, their sheets of points lie a registration error apart, and a
 * neighbourhood across them tilts the normal. The ids are checked in pass 1; a column with any other value is
 * not a scan column and the cloud is estimated whole. Halo records then carry the scan id, and the halo margin is
 * the largest of the scans' own (a scan is sparser than the merged cloud). Memory: the scan-by-scan copies are
 * charged per point once a second scan is met (a cloud near the budget may then be tiled, its output in tile
 * order, where `perScan = false` keeps it whole).
 *
 * Output: x y z (double), nx ny nz (float), the input's colours and scalar columns (as double), and
 * "surface_variation" (float) if asked. Normals the input already had are replaced. ORDER: tile by tile
 * (input order within a tile) when tiled; input order otherwise. Non-finite input points are skipped
 * by the reader (NormalFileReport::skippedPoints).
 *
 * Files: the temporary folder ".OUTNAME.normals-XXXXXXXX" is made next to the output (or in
 * std::filesystem::temp_directory_path() if that fails) and removed in every case; the output is written
 * through PlyWriter (temporary name, renamed at the end): an error or a cancel leaves nothing behind.
 * Disk: about (record + 24 × halo fraction) bytes per point of temporary space while tiled (32 × halo fraction
 * scan by scan).
 *
 * Units: metres. Thread-safety: reentrant; uses NormalOptions::threads worker threads.
 */
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/normals/NormalEstimation.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace stylos::core::normals {

/** @brief Parameters of the file-to-file estimation. */
struct NormalFileOptions {
    NormalOptions normals;                       ///< k, threads, orientation (centre default: global centroid)
    std::size_t memoryBudget = 256u << 20;       ///< bytes for points held at once (≥ 64 KiB)
    bool writeQuality = false;                   ///< also write the "surface_variation" column
    std::filesystem::path temporaryDirectory;    ///< where the tile folder goes; empty: next to the output
    io::ReadOptions read;                        ///< passed to the reader (text column layout)
    bool perScan = true;                         ///< neighbours from the point's own scan (see the file comment)
};

/** @brief What the file estimation did. */
struct NormalFileReport {
    NormalReport normals;              ///< points, degenerate, truncated (see NormalReport), centre
    std::uint64_t skippedPoints = 0;   ///< non-finite points the reader dropped
    std::uint64_t tiles = 0;           ///< 0 when the cloud fitted the budget in one piece
    std::uint64_t haloPoints = 0;      ///< halo copies loaded, summed over the tiles
    double margin = 0;                 ///< halo width in metres (0 when not tiled)
    std::size_t peakTilePoints = 0;    ///< largest number of points (own + halo) held at once
    std::string scanColumn;            ///< the scan column whose scans were kept apart; empty: estimated whole
    std::uint32_t scans = 0;           ///< how many scans were kept apart (0 when estimated whole)
};

/**
 * @brief Estimates normals for every point of @p input and writes them, with the input's attributes, to
 *        the binary PLY @p output.
 * @return the report, or the reader's error (NotFound, Unreadable, UnknownFormat, Unsupported,
 *         Malformed, Truncated, Empty), WriteFailed (output or temporary files), InvalidArgument
 *         (options), OutOfBudget (the budget cannot hold even one tile with its halo: the message gives
 *         the budget needed), or Cancelled. On any error nothing is left on disk.
 */
Result<NormalFileReport> estimateNormalsForFile(const std::filesystem::path& input,
                                                const std::filesystem::path& output,
                                                const NormalFileOptions& options = {},
                                                ProgressSink* progress = nullptr);

} // namespace stylos::core::normals
