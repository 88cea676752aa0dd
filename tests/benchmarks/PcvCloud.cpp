#include "PcvCloud.h"

#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/io/PointReader.h"

#include <cassert>
#include <cmath>

namespace stylos::bench {

using stylos::core::Error;
using stylos::core::ErrorCode;

stylos::core::Result<PcvCloud> readPcvCloud(const std::filesystem::path& path)
{
    auto opened = stylos::core::io::openPointReader(path);
    if (!opened) return opened.error();
    auto& reader = *opened.value();
    int column = -1;
    const auto& names = reader.header().schema.scalarNames;
    for (std::size_t k = 0; k < names.size() && column < 0; ++k)
        if (names[k].find("PCV") != std::string::npos || names[k].find("Illuminance") != std::string::npos)
            column = int(k);
    if (column < 0) return Error::at(ErrorCode::Malformed, path.string(), "", "no PCV / Illuminance scalar field");
    PcvCloud cloud;
    cloud.field = names[std::size_t(column)];
    stylos::core::io::PointBatch batch;
    for (;;) {
        auto n = reader.read(batch, 65536);
        if (!n) return n.error();
        if (n.value() == 0) break;
        for (std::size_t i = 0; i < n.value(); ++i) {
            cloud.positions.push_back({batch.positions[3 * i], batch.positions[3 * i + 1], batch.positions[3 * i + 2]});
            cloud.values.push_back(batch.scalars[std::size_t(column)][i]);
        }
    }
    return cloud;
}

double frontFraction(const std::vector<stylos::core::ao::Direction>& directions, const std::array<float, 3>& n)
{
    if (directions.empty()) return 0.0;
    std::size_t front = 0;
    for (const auto& d : directions) front += n[0] * float(d[0]) + n[1] * float(d[1]) + n[2] * float(d[2]) > 0.0f;
    return double(front) / double(directions.size());
}

PointGrid::PointGrid(const std::vector<std::array<double, 3>>& points, double radius)
    : m_points(points), m_radius(radius)
{
    assert(radius > 0 && "PointGrid::PointGrid(): the radius must be positive");
    m_bins.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) m_bins[key(binOf(points[i]))].push_back(i);
}

std::size_t PointGrid::nearest(const Eigen::Vector3d& query) const
{
    const auto b = binOf({query.x(), query.y(), query.z()});
    std::size_t best = SIZE_MAX;
    double bestD = m_radius * m_radius;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const auto it = m_bins.find(key({b[0] + dx, b[1] + dy, b[2] + dz}));
                if (it == m_bins.end()) continue;
                for (const std::size_t i : it->second) {
                    const auto& p = m_points[i];
                    const double d2 = (Eigen::Vector3d(p[0], p[1], p[2]) - query).squaredNorm();
                    if (d2 < bestD || (d2 == bestD && i < best)) bestD = d2, best = i;
                }
            }
    return best;
}

std::array<std::int64_t, 3> PointGrid::binOf(const std::array<double, 3>& p) const
{
    return {std::int64_t(std::floor(p[0] / m_radius)), std::int64_t(std::floor(p[1] / m_radius)),
            std::int64_t(std::floor(p[2] / m_radius))};
}

std::uint64_t PointGrid::key(const std::array<std::int64_t, 3>& b)
{
    return (std::uint64_t(b[0] & 0x1fffff) << 42) | (std::uint64_t(b[1] & 0x1fffff) << 21) | std::uint64_t(b[2] & 0x1fffff);
}

} // namespace stylos::bench
