#pragma once
/** @file
 * @brief Reads a whole point file once, streaming, and sums it up: format, point count, points
 *        skipped as non-finite, exact bounds of the points read, attributes. Memory stays flat.
 */
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/util/Progress.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stylos::core::io {

struct PointFileSummary {
    std::string format;
    std::uint64_t points = 0;                     ///< points read (finite)
    std::uint64_t skipped = 0;                    ///< points skipped for a NaN or infinite coordinate
    std::uint64_t missing = 0;                    ///< points the file marks missing (E57 invalid state, PTX 0 0 0)
    std::optional<std::uint64_t> declaredPoints;  ///< what the header announced, if anything
    std::optional<std::array<double, 3>> min, max;///< bounds of the points read; absent when there are none
    std::vector<std::string> attributes;          ///< "normal", "color", then scalar names
    std::uint64_t fileBytes = 0;
    std::vector<ScanInfo> scans;                  ///< E57 / PTX: every scan in the file, with its pose
};

/** @brief Streams @p path to the end. Errors from the reader; ErrorCode::Cancelled on request. */
Result<PointFileSummary> summarizePointFile(const std::filesystem::path& path, const ReadOptions& options = {},
                                            ProgressSink* progress = nullptr);

} // namespace stylos::core::io
