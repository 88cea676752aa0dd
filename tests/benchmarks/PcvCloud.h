#pragma once
// CloudCompare's PCV beside the 3D skydome (stylos_ao_quality, stylos_ao_truth): its output cloud with the
// "Illuminance (PCV)" scalar field, the nearest of its points to a query, and the factor F(n) between
// PCV's definition and ours.
//
// PCV's value is (rays that see the point) / (all rays), over the whole sphere (or, with -180, its upper
// half), without normals; Stylos's is over the directions in front of the normal. A value in ours times
// F(n) = (directions of the set with n·d > 0) / (all directions) is in PCV's; PCV's divided by F(n) in ours.
#include "stylos/core/ao/Directions.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace stylos::bench {

/** @brief CloudCompare's output: positions and the PCV scalar field, in file order. */
struct PcvCloud {
    std::vector<std::array<double, 3>> positions;
    std::vector<double> values;
    std::string field; ///< the scalar's name in the file, e.g. "scalar_Illuminance_(PCV)"
};

/**
 * @brief Reads any point file Stylos reads, keeping x y z and the first scalar whose name holds "PCV"
 *        or "Illuminance" (CloudCompare 2.11 writes "scalar_Illuminance_(PCV)" to PLY).
 *        Fails with the reader's error, or Malformed "FILE: no PCV / Illuminance scalar field".
 */
stylos::core::Result<PcvCloud> readPcvCloud(const std::filesystem::path& path);

/** @brief Share of @p directions in front of @p n (n·d > 0 in float, as the methods weigh them); 0 if none. */
double frontFraction(const std::vector<stylos::core::ao::Direction>& directions, const std::array<float, 3>& n);

/**
 * @brief The nearest of a set of points to a query, through a hash grid of bins of edge @p radius: a
 *        point is found when it lies within @p radius of the query (exactly the nearest one then; the
 *        lower index on a tie), otherwise SIZE_MAX. Keeps a reference to @p points.
 */
class PointGrid {
public:
    PointGrid(const std::vector<std::array<double, 3>>& points, double radius);
    std::size_t nearest(const Eigen::Vector3d& query) const;

private:
    std::array<std::int64_t, 3> binOf(const std::array<double, 3>& p) const;
    static std::uint64_t key(const std::array<std::int64_t, 3>& b);
    const std::vector<std::array<double, 3>>& m_points;
    double m_radius;
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> m_bins;
};

} // namespace stylos::bench
