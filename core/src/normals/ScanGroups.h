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

/** @brief The scan ids met in a column, checked and counted as they come. */
class ScanCensus {
public:
    /** Counts @p id; false (and the census is spoilt) when it is not an integer in [0, MaxScanId]. */
    bool add(double id);
    bool valid() const { return m_valid; }
    std::uint32_t scans() const { return m_scans; } ///< distinct ids
    std::uint64_t points(std::size_t id) const { return m_points[id]; } ///< points of scan @p id
private:
    std::vector<std::uint64_t> m_points = std::vector<std::uint64_t>(MaxScanId + 1, 0);
    std::uint32_t m_scans = 0;
    bool m_valid = true;
};

/**
 * @brief Runs @p job with each query's neighbours among the points (queries and halo) of its own scan.
 * @param scans  one id per point of job.positions (queries first, then halo), each in [0, MaxScanId].
 * @param census the whole cloud's: each scan's job gets its scan's point count as NormalJob::cloudPoints.
 * Scans run one after another in increasing id; a job whose points are all of one scan runs as it is (with
 * that scan's count), so its normals are exactly runNormalJob's. Errors: runNormalJob's; OutOfBudget when
 * the copies cannot be made.
 */
Result<NormalReport> runNormalJobPerScan(const NormalJob& job, std::span<const double> scans,
                                         const ScanCensus& census, const NormalOptions& options,
                                         ProgressSink* progress);

/**
 * @brief The tiles' halo margin when neighbours are taken scan by scan: the largest of
 *        estimateHaloMargin() over each scan's part of the sample (a scan is sparser than the merged cloud,
 *        so its k-th neighbour lies farther), and of the merged sample's own margin. Scans with fewer than 2k
 *        sample points are left out (their points may be counted as truncated).
 * @param sampleScans one id per sample point.
 */
double perScanHaloMargin(std::span<const double> sample, std::span<const std::uint16_t> sampleScans,
                         const ScanCensus& census, std::uint64_t totalPoints, std::size_t k);

/** Extra bytes per point that runNormalJobPerScan holds beyond runNormalJob (a scan's copy of the positions,
 *  its normals and quality, the index lists). */
constexpr std::size_t PerScanBytesPerPoint = 3 * sizeof(double) + 4 * sizeof(float) + 2 * sizeof(std::uint32_t);

} // namespace stylos::core::normals::detail
