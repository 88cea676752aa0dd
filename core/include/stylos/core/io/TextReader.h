#pragma once
/** @file
 * @brief Streaming reader of text point files: XYZ, ASC, CSV, TXT and Leica PTS.
 *
 * One point per line; fields separated by spaces/tabs, ',' or ';' (detected from the first data
 * line). Blank lines and comments ('#' or "//" first) are skipped anywhere. An optional header line of
 * column names ("X,Y,Z,Intensity,R,G,B", or a comment such as "//X Y Z Rf Gf Bf") gives the layout;
 * otherwise it is detected from the column count and the first data lines (see detectLayout()), or
 * taken from ReadOptions::columns. Names may be quoted; a UTF-8 byte order mark is ignored; with ','
 * or ';' one trailing separator per line is tolerated. A line holding a single integer starts a Leica
 * PTS block of that many points; each block's count is checked against its points.
 *
 * Positions are read as double in the file's units. Colours are 0–255 integers or floats in [0, 1]
 * (decided per file from the first data lines, scaled to 0–255, rounded and clamped). Points whose
 * x, y or z is NaN or infinite are skipped and counted in pointsSkipped().
 *
 * Failures (one line naming the file and "line N"): Malformed for a data line with the wrong number
 * of columns, a field that is not a number, a line over 64 MiB, a header without x, y and z, or more
 * points than a PTS count announces; Truncated for fewer; Empty when there is no data line;
 * InvalidArgument for a bad ReadOptions::columns. Memory stays flat (one 1 MiB buffer).
 * Not thread-safe: one reader per thread.
 */
#include "stylos/core/io/BufferedFile.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointReader.h"
#include "stylos/core/io/TextColumns.h"

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace stylos::core::io {

class TextReader final : public PointReader {
public:
    /**
     * @brief Opens @p path, reads its first lines to settle the separator, layout and colour scale.
     *        header().format is "xyz", "asc", "csv", "pts" or "txt" by extension; declaredPoints is
     *        the first PTS count (it grows as later PTS blocks are met, and is final once read()
     *        returned 0), none without one.
     */
    static Result<std::unique_ptr<PointReader>> open(const std::filesystem::path& path, const ReadOptions& options);

    Result<std::size_t> read(PointBatch& batch, std::size_t maxPoints) override;
    std::uint64_t bytesConsumed() const override { return m_file.offset(); }

    /** The column layout in use (detected, from a header, or the override). */
    const ColumnLayout& layout() const { return m_layout; }

private:
    TextReader(std::filesystem::path path, BufferedFile file);

    /** What open() learns from the first lines. */
    struct Prescan;
    Result<Prescan> prescan();
    Status settleLayout(const Prescan& scan, const ReadOptions& options);
    /** Handles a line holding a lone integer: closes the current PTS block and opens another. */
    Status startBlock(std::uint64_t count);
    Status finish();
    Error lineError(ErrorCode code, std::uint64_t line, const std::string& problem) const;

    BufferedFile m_file;
    ColumnLayout m_layout;
    Separator m_separator = Separator::Whitespace;
    bool m_unitColors = false;
    std::array<std::size_t, 3> m_position{};
    std::array<std::size_t, 3> m_normal{};
    std::array<std::size_t, 3> m_color{};
    std::vector<std::size_t> m_scalarColumns;
    std::vector<double> m_values; ///< one line's numbers, reused
    std::uint64_t m_line = 0;           ///< number of the last line read (1-based)
    std::uint64_t m_headerLine = 0;     ///< the non-comment header line to skip; 0 when none
    std::uint64_t m_firstCountLine = 0; ///< the PTS count already in declaredPoints; 0 when none
    // The current PTS block.
    std::optional<std::uint64_t> m_blockCount;
    std::uint64_t m_blockLine = 0;
    std::uint64_t m_blockPoints = 0;
    bool m_finished = false;
};

} // namespace stylos::core::io
