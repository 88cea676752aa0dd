#pragma once
/** @file
 * @brief Private to core/normals: normals estimated scan by scan. A cloud merged from several range scans
 *        (the Stanford scans' `scan_id`) holds, where the scans overlap, interleaved sheets of points a
 *        registration error apart; a neighbourhood that mixes them fits a plane across the sheets and tilts
 *        the normal (dark grain on the Happy Buddha's robe). Taking each point's neighbours from its own scan
 *        keeps every neighbourhood on one sheet.
 */
#include "NormalJob.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace stylos::core::normals::detail {

/** Largest scan id kept apart: ids are integers in [0, MaxScanId]. */
constexpr std::uint32_t MaxScanId = 65535;

/** The scalar column that names each point's scan: the first called scan_id, scan_index or scan (any case). */
std::optional<std::size_t> findScanColumn(const std::vector<std::string>& scalarNames);

/** @brief The scan ids met in a column, checked as they come. */
class ScanCensus {
public:
    /** Counts @p id; false (and the census is spoilt) when it is not an integer in [0, MaxScanId]. */
    bool add(double id);
    bool valid() const { return m_valid; }
    std::uint32_t scans() const { return m_scans; } ///< distinct ids
private:
    std::vector<bool> m_seen = std::vector<bool>(MaxScanId + 1, false);
    std::uint32_t m_scans = 0;
    bool m_valid = true;
};

/**
 * @brief Runs @p job with each query's neighbours among the points (queries and halo) of its own scan.
 * @param scans one id per point of job.positions (queries first, then halo), each in [0, MaxScanId].
 * Scans run one after another in increasing id; a job whose points are all of one scan runs as it is, so its
 * normals are exactly runNormalJob's. Errors: runNormalJob's; OutOfBudget when the copies cannot be made.
 */
Result<NormalReport> runNormalJobPerScan(const NormalJob& job, std::span<const double> scans,
                                         const NormalOptions& options, ProgressSink* progress);

/** Extra bytes per point that runNormalJobPerScan holds beyond runNormalJob (a scan's copy of the positions,
 *  its normals and quality, the index lists). */
constexpr std::size_t PerScanBytesPerPoint = 3 * sizeof(double) + 4 * sizeof(float) + 2 * sizeof(std::uint32_t);

} // namespace stylos::core::normals::detail
