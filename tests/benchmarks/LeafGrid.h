#pragma once
// Benchmarks of the 3D skydome: the leaf nearest to a point, through a hash grid of the leaves' centres
// (stylos_ao_truth, stylos_ao_pointref).
#include "stylos/core/ao/AoCells.h"

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace stylos::bench {

class LeafGrid {
public:
    LeafGrid(const stylos::core::ao::AoCells& leaves, double bin) : m_leaves(leaves), m_bin(bin)
    {
        for (std::size_t i = 0; i < leaves.size(); ++i) m_map[key(binOf(leaves.centre(i)))].push_back(i);
    }
    std::size_t nearest(const Eigen::Vector3d& q) const
    {
        const auto b = binOf({q.x(), q.y(), q.z()});
        std::size_t best = SIZE_MAX;
        double bestD = 1e300;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const auto it = m_map.find(key({b[0] + dx, b[1] + dy, b[2] + dz}));
                    if (it == m_map.end()) continue;
                    for (const std::size_t i : it->second) {
                        const auto c = m_leaves.centre(i);
                        const double d2 = (Eigen::Vector3d(c[0], c[1], c[2]) - q).squaredNorm();
                        if (d2 < bestD) bestD = d2, best = i;
                    }
                }
        return best;
    }

private:
    std::array<std::int64_t, 3> binOf(const std::array<double, 3>& p) const
    {
        return {std::int64_t(std::floor(p[0] / m_bin)), std::int64_t(std::floor(p[1] / m_bin)),
                std::int64_t(std::floor(p[2] / m_bin))};
    }
    static std::uint64_t key(const std::array<std::int64_t, 3>& b)
    {
        return (std::uint64_t(b[0] & 0x1fffff) << 42) | (std::uint64_t(b[1] & 0x1fffff) << 21) |
               std::uint64_t(b[2] & 0x1fffff);
    }
    const stylos::core::ao::AoCells& m_leaves;
    double m_bin;
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> m_map;
};

} // namespace stylos::bench
