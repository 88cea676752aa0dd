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
#include <vector>

namespace stylos::core::io {

/**
 * @brief The scalar column that a multi-scan reader adds when it may read several scans (E57: two or
 *        more read; PTX: no ReadOptions::scan): each point's scan, numbered from 0 in file order as scans() lists them, so
 *        that what follows the reader can keep the scans apart (normals::estimateNormalsForFile takes
 *        each point's neighbours from its own scan, as for a PLY's scan column).
 */
inline constexpr const char* kScanIndexColumn = "scan_index";

/**
 * @brief One scan of a file that holds several (an E57 `data3D` child, a PTX scan): its name and the pose
 *        the reader applies to its points (p' = R p + t, in the file's frame and units).
 */
struct ScanInfo {
    std::string name;                 ///< E57: the scan's name (may be empty); PTX: "scan N"
    std::string guid;                 ///< E57 only
    std::uint64_t points = 0;         ///< records the file declares for the scan, missing ones included
    /** Row-major 3×4 [R | t]. */
    std::array<double, 12> pose{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    /** E57: the rotation as the file states it (w, x, y, z); absent for PTX (a general 4×4). */
    std::optional<std::array<double, 4>> quaternion;
};

/** @brief What a reader knows about its file once the header is parsed. */
struct PointFileHeader {
    std::string format;                       ///< e.g. "ply-binary-le", "las-1.2", "e57-1.0", "ptx", "xyz", "pts", "obj"
    /** Count the file announces (none for plain text); a PTX reader knows it only at the end of the file. */
    std::optional<std::uint64_t> declaredPoints;
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
    /**
     * Points the file itself marks as missing, skipped and counted: E57 points whose
     * cartesianInvalidState / sphericalInvalidState is 1 (direction only) or 2 (invalid), PTX (0, 0, 0) points.
     */
    std::uint64_t pointsMissing() const { return m_pointsMissing; }
    /**
     * The scans of a multi-scan format, in file order (empty for single-cloud formats). An E57 reader
     * knows them all once open; a PTX reader adds each as it reaches its header (all of them at the end).
     */
    const std::vector<ScanInfo>& scans() const { return m_scans; }
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
    std::uint64_t m_pointsMissing = 0;
    std::vector<ScanInfo> m_scans;
};

} // namespace stylos::core::io
