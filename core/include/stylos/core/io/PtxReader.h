#pragma once
/** @file
 * @brief Streaming reader for Leica PTX text files: one or more scans, each a header — columns, rows,
 *        the scanner's position (1 line), its axes (3 lines), a 4 × 4 transform (4 lines) — then
 *        rows × columns lines "x y z intensity [r g b]".
 *
 *        Each point is transformed as Leica writes the matrix, row-vector convention:
 *        [x' y' z' 1] = [x y z 1] · M (the translation is M's last row). Points at (0, 0, 0) before the
 *        transform are the scanner's "no return" and are skipped and counted in pointsMissing().
 *        Attributes: the scalar "intensity" (as written, usually 0–1) and, when the first point line has
 *        seven values, colour (0–255). ReadOptions::scan keeps one scan (the others are skipped unparsed);
 *        without it the points also carry kScanIndexColumn, their scan's number in the file (a PTX file's
 *        scans are known only as it is read, so even a file of one scan has the column, all 0).
 *        declaredPoints (Σ rows × columns) and scans() are complete once the file is read.
 *
 *        Failures: Malformed "FILE: line N: ..." for a header line that is not the expected numbers, a
 *        value that is not a number, a point line with another count of values than the first;
 *        Truncated "FILE: line N: the file ends inside scan S after K of R × C points"; Empty for a
 *        file without any scan; InvalidArgument at the end for a scan number beyond the file's.
 *        Memory stays flat (one 1 MiB buffer). Not thread-safe.
 */
#include "stylos/core/io/BufferedFile.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointReader.h"

#include <array>
#include <memory>
#include <optional>

namespace stylos::core::io {

class PtxReader final : public PointReader {
public:
    static Result<std::unique_ptr<PointReader>> open(const std::filesystem::path& path, const ReadOptions& options = {});
    Result<std::size_t> read(PointBatch& batch, std::size_t maxPoints) override;
    std::uint64_t bytesConsumed() const override { return m_file.offset(); }

private:
    PtxReader(std::filesystem::path path, BufferedFile file, std::optional<std::size_t> scan);
    /** Reads the next scan header; false (no error) at the end of the file. */
    Result<bool> readScanHeader();
    /** The next line, counted; false at the end of the file. */
    bool nextLine(std::string_view& line);
    Error lineError(ErrorCode code, const std::string& problem) const;

    BufferedFile m_file;
    std::optional<std::size_t> m_wanted;
    std::uint64_t m_line = 0;            ///< 1-based number of the last line read
    std::uint64_t m_pointsLeft = 0;      ///< in the current scan
    std::uint64_t m_declared = 0;
    std::size_t m_values = 0;            ///< values per point line: 4 or 7 (0 until the first)
    std::array<double, 16> m_matrix{};   ///< the current scan's M, row-major
    bool m_keepScan = true;
    bool m_done = false;
};

} // namespace stylos::core::io
