#pragma once
/** @file
 * @brief The streaming reader interface: a reader is opened on one file, describes it in its header,
 *        then yields batches until the end. It never holds the whole file: memory stays flat whatever
 *        the file size. Points with a NaN or infinite coordinate are skipped and counted, never passed on.
 *        Not thread-safe: one reader per thread.
 */
#include "stylos/core/io/PointBatch.h"
#include "stylos/core/util/Result.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace stylos::core::io {

/** @brief What a reader knows about its file once the header is parsed. */
struct PointFileHeader {
    std::string format;                       ///< e.g. "ply-binary-le", "las-1.2", "xyz", "pts", "obj"
    std::optional<std::uint64_t> declaredPoints; ///< count the file announces (none for plain text)
    PointSchema schema;
    /** Bounds stated in the header (LAS), already in world units; absent otherwise. */
    std::optional<std::array<double, 6>> declaredBounds;
};

class PointReader {
public:
    virtual ~PointReader() = default;

    const PointFileHeader& header() const { return m_header; }
    const std::filesystem::path& path() const { return m_path; }

    /**
     * @brief Reads the next points (at most @p maxPoints) into @p batch, replacing its content.
     * @return the number of points put in the batch; 0 once the whole file has been read (the
     *         reader then has checked that the data agree with the header's count). An Error when the
     *         data are malformed or truncated; the message names the file and the line or byte offset.
     */
    virtual Result<std::size_t> read(PointBatch& batch, std::size_t maxPoints) = 0;

    /** Points delivered so far. */
    std::uint64_t pointsRead() const { return m_pointsRead; }
    /** Points skipped so far because a coordinate was NaN or infinite. */
    std::uint64_t pointsSkipped() const { return m_pointsSkipped; }
    /** Bytes consumed so far, for progress (compare with the file size). */
    virtual std::uint64_t bytesConsumed() const = 0;
    std::uint64_t fileBytes() const { return m_fileBytes; }

protected:
    PointReader(std::filesystem::path path, std::uint64_t fileBytes)
        : m_path(std::move(path)), m_fileBytes(fileBytes) {}

    /** Error "file: position: problem" for this reader's file. */
    Error fail(ErrorCode code, const std::string& position, const std::string& problem) const
    {
        return Error::at(code, m_path.string(), position, problem);
    }

    PointFileHeader m_header;
    std::filesystem::path m_path;
    std::uint64_t m_fileBytes = 0;
    std::uint64_t m_pointsRead = 0;
    std::uint64_t m_pointsSkipped = 0;
};

} // namespace stylos::core::io
