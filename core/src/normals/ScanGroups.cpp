#include "ScanGroups.h"

#include "TilePlan.h"
#include "stylos/core/util/SubProgress.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <new>

namespace stylos::core::normals::detail {

std::optional<std::size_t> findScanColumn(const std::vector<std::string>& scalarNames)
{
    for (std::size_t i = 0; i < scalarNames.size(); ++i) {
        std::string name = scalarNames[i];
        std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (name == "scan_id" || name == "scan_index" || name == "scan") return i;
    }
    return std::nullopt;
}

bool ScanCensus::add(double id)
{
    if (!m_valid) return false;
    if (!(id >= 0.0 && id <= double(MaxScanId)) || id != std::floor(id)) {
        m_valid = false;
        return false;
    }
    const auto at = std::size_t(id);
    if (m_points[at]++ == 0) ++m_scans;
    return true;
}

Result<NormalReport> runNormalJobPerScan(const NormalJob& job, std::span<const double> scans,
                                         const ScanCensus& census, const NormalOptions& options,
                                         ProgressSink* progress)
{
    const std::size_t total = job.positions.size() / 3, queries = job.queryCount;
    if (total == 0) return runNormalJob(job, options, progress);
    if (std::all_of(scans.begin(), scans.end(), [&](double id) { return id == scans[0]; })) {
        NormalJob one = job;
        one.cloudPoints = census.points(std::size_t(scans[0]));
        return runNormalJob(one, options, progress);
    }
    try {
        // The points of each scan, queries first: one counting sort by id, over the ids up to the largest met
        // (a tile of one or two scans does not pay for 65,536 of them).
        const std::size_t top = std::size_t(*std::max_element(scans.begin(), scans.end()));
        std::vector<std::uint32_t> start(top + 2, 0), queryEnd(top + 1, 0);
        for (std::size_t i = 0; i < total; ++i) ++start[std::size_t(scans[i]) + 1];
        for (std::size_t s = 1; s < start.size(); ++s) start[s] += start[s - 1];
        std::vector<std::uint32_t> order(total), fill(start.begin(), start.end() - 1);
        for (std::size_t i = 0; i < queries; ++i) order[fill[std::size_t(scans[i])]++] = std::uint32_t(i);
        for (std::size_t s = 0; s <= top; ++s) queryEnd[s] = fill[s];
        for (std::size_t i = queries; i < total; ++i) order[fill[std::size_t(scans[i])]++] = std::uint32_t(i);

        NormalReport report;
        std::vector<double> positions;
        std::vector<float> normals, quality;
        std::size_t done = 0;
        for (std::size_t s = 0; s <= top; ++s) {
            const std::size_t first = start[s], own = queryEnd[s] - first, count = start[s + 1] - first;
            if (own == 0) continue;
            positions.resize(3 * count);
            for (std::size_t j = 0; j < count; ++j)
                std::copy_n(&job.positions[3 * std::size_t(order[first + j])], 3, &positions[3 * j]);
            normals.assign(3 * own, 0.0f);
            quality.assign(job.quality.empty() ? 0 : own, 0.0f);
            NormalJob part = job;
            part.positions = positions;
            part.queryCount = own;
            part.normals = normals;
            part.quality = quality;
            part.cloudPoints = census.points(s);
            SubProgress partProgress(progress, double(done) / double(queries), double(done + own) / double(queries));
            auto estimated = runNormalJob(part, options, &partProgress);
            if (!estimated) return estimated.error();
            report.points += estimated->points;
            report.degenerate += estimated->degenerate;
            report.truncated += estimated->truncated;
            report.centre = estimated->centre;
            for (std::size_t j = 0; j < own; ++j) {
                const std::size_t i = order[first + j];
                std::copy_n(&normals[3 * j], 3, &job.normals[3 * i]);
                if (!quality.empty()) job.quality[i] = quality[j];
            }
            done += own;
        }
        return report;
    } catch (const std::bad_alloc&) {
        return Error{ErrorCode::OutOfBudget,
                     "normal estimation: out of memory separating the scans of " + std::to_string(total) + " points"};
    }
}

double perScanHaloMargin(std::span<const double> sample, std::span<const std::uint16_t> sampleScans,
                         const ScanCensus& census, std::uint64_t totalPoints, std::size_t k)
{
    double margin = estimateHaloMargin(sample, totalPoints, k);
    std::vector<std::vector<double>> parts(std::size_t(MaxScanId) + 1);
    for (std::size_t i = 0; i < sampleScans.size(); ++i)
        parts[sampleScans[i]].insert(parts[sampleScans[i]].end(), &sample[3 * i], &sample[3 * i] + 3);
    for (std::size_t s = 0; s < parts.size(); ++s) {
        if (parts[s].size() / 3 < 2 * k) continue;
        const double own = estimateHaloMargin(parts[s], census.points(s), k);
        if (std::isfinite(own)) margin = std::max(margin, own);
    }
    return margin;
}

} // namespace stylos::core::normals::detail
