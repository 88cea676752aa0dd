#pragma once
/** @file
 * @brief Streaming reader for ASTM E57 files (E2807, version 1.x): every `/data3D` scan, or the one
 *        ReadOptions::scan names, each with its pose (rotation quaternion + translation) applied, merged
 *        in the file's frame.
 *
 *        Positions: cartesianX/Y/Z, or sphericalRange/Azimuth/Elevation (x = r cos e cos a,
 *        y = r cos e sin a, z = r sin e), in the file's units (metres by the standard). Points whose
 *        cartesianInvalidState (sphericalInvalidState for spherical scans) is 1 (direction only) or
 *        2 (invalid) are skipped and counted in pointsMissing(); NaN or infinite ones in pointsSkipped().
 *        Attributes, kept when every scan read has them: colour (colorRed/Green/Blue mapped from the
 *        scan's colorLimits, else the fields' ranges, to 0–255) and the scalar "intensity" (mapped from
 *        intensityLimits, else the field's range, to 0–1). Other fields are not decoded. When two scans or
 *        more are read, the points also carry kScanIndexColumn, their scan's number in the file.
 *        Only the bitpack codec exists in E57 1.0; String prototype fields are refused.
 *
 *        Failures at open: E57FileHeader::parse(), parseE57Xml(), a page whose CRC-32C fails (every page
 *        is checked as it is read: "FILE: page P (byte B): checksum mismatch"), Empty for a file with no
 *        scan, InvalidArgument for a scan number beyond the file's, Unsupported for a scan without
 *        cartesian or spherical coordinates, Malformed for an invalid compressed-vector section header
 *        (every scan read is checked at open). In read(): the packet errors of E57VectorReader.
 *        Memory: one 256 KiB page window, one packet and the batch. Not thread-safe.
 */
#include "stylos/core/io/E57PagedFile.h"
#include "stylos/core/io/E57Structure.h"
#include "stylos/core/io/E57VectorReader.h"
#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointReader.h"

#include <memory>
#include <optional>
#include <vector>

namespace stylos::core::io {

class E57Reader final : public PointReader {
public:
    static Result<std::unique_ptr<PointReader>> open(const std::filesystem::path& path, const ReadOptions& options = {});
    Result<std::size_t> read(PointBatch& batch, std::size_t maxPoints) override;
    std::uint64_t bytesConsumed() const override { return m_bytesConsumed; }

    const E57FileHeader& fileHeader() const { return m_fileHeader; }

private:
    /** How one scan's fields become points: columns of the vector reader, and normalisation. */
    struct ScanPlan {
        std::size_t scan = 0;          ///< index in m_scanList
        bool spherical = false;
        int invalidState = -1;         ///< column of the invalid-state field, or -1
        int intensity = -1;            ///< column, or -1
        int color = -1;                ///< column of red (green, blue follow), or -1
        double intensityMin = 0, intensityRange = 1;
        std::array<double, 3> colorMin{}, colorRange{1, 1, 1};
        std::vector<int> fields;       ///< prototype fields to decode: coordinates, then the rest
    };

    E57Reader(std::filesystem::path path, E57PagedFile file, E57FileHeader header, std::vector<E57Scan> scans,
              std::vector<ScanPlan> plans, bool scanColumn);
    std::string label(std::size_t scan) const;
    /** Converts @p n decoded records of the current scan, appending the kept points to @p batch. */
    void convert(const ScanPlan& plan, std::size_t n, PointBatch& batch);

    E57PagedFile m_file;
    E57FileHeader m_fileHeader;
    std::vector<E57Scan> m_scanList;
    std::vector<ScanPlan> m_plans;     ///< the scans to read, in file order
    int m_intensityColumn = -1;        ///< scalar column of "intensity", or -1
    int m_scanColumn = -1;             ///< scalar column of kScanIndexColumn, or -1 (one scan read)
    std::size_t m_current = 0;         ///< index in m_plans
    std::optional<E57VectorReader> m_vector;
    std::vector<std::vector<double>> m_columns;
    std::uint64_t m_bytesConsumed = 0;
};

} // namespace stylos::core::io
