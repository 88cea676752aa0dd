// The skydome against the points as discs (DiscSkydome.h): discs from a cloud, a uniform grid of them, and
// rays walked through the grid cell by cell.
#include "stylos/core/ao/DiscSkydome.h"

#include "stylos/core/normals/NormalEstimation.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

namespace stylos::core::ao {
namespace {

struct Points {
    std::span<const double> xyz;
    std::size_t kdtree_get_point_count() const { return xyz.size() / 3; }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return xyz[3 * i + d]; }
    template <class Box> bool kdtree_get_bbox(Box&) const { return false; }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Points, double, std::uint32_t>,
                                                 Points, 3, std::uint32_t>;

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

} // namespace

Result<DiscCloud> discsFromPoints(std::span<const double> positions, const DiscCloudOptions& options)
{
    const std::size_t n = positions.size() / 3;
    const std::size_t k = std::max<std::size_t>(1, options.neighbours);
    if (positions.size() % 3 != 0 || n < k + 1)
        return Error::at(ErrorCode::InvalidArgument, "<memory>", "",
                         "discs need at least " + std::to_string(k + 1) + " points, not " + std::to_string(n));
    DiscCloud discs;
    discs.centres.resize(n);
    for (std::size_t i = 0; i < n; ++i) discs.centres[i] = {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
    std::vector<float> normals(3 * n);
    normals::NormalOptions normalOptions;
    normalOptions.threads = options.threads;
    auto estimated = normals::estimateNormals(positions, normals, normalOptions);
    if (!estimated) return estimated.error();
    discs.normals.resize(n);
    for (std::size_t i = 0; i < n; ++i) discs.normals[i] = {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};

    // Radii: the mean distance to the k nearest other points (the point itself is the first found).
    // Projected: the centre moved along its normal onto the plane through its neighbours' centroid.
    discs.radii.resize(n);
    const Points points{positions};
    const Tree tree(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    const unsigned threads = std::max(1u, options.threads ? options.threads : std::thread::hardware_concurrency());
    const std::size_t searched = std::max(k, options.projectionNeighbours) + 1;
    std::vector<std::thread> workers;
    for (unsigned w = 0; w < threads; ++w)
        workers.emplace_back([&, w] {
            std::vector<std::uint32_t> index(searched);
            std::vector<double> distance2(searched);
            for (std::size_t i = w; i < n; i += threads) {
                const std::size_t found = tree.knnSearch(&positions[3 * i], searched, index.data(), distance2.data());
                double sum = 0.0;
                std::size_t count = 0;
                for (std::size_t j = 0; j < found && count < k; ++j)
                    if (index[j] != i) sum += std::sqrt(distance2[j]), ++count;
                discs.radii[i] = float(options.radiusScale * (count ? sum / double(count) : 0.0));
                if (options.projectionNeighbours == 0) continue;
                const std::size_t used = std::min(found, options.projectionNeighbours + 1); // the point included
                std::array<double, 3> mean{0, 0, 0};
                for (std::size_t j = 0; j < used; ++j)
                    for (int a = 0; a < 3; ++a) mean[a] += positions[3 * index[j] + std::size_t(a)] / double(used);
                const auto& nn = discs.normals[i];
                auto& c = discs.centres[i];
                const double h = (c[0] - mean[0]) * nn[0] + (c[1] - mean[1]) * nn[1] + (c[2] - mean[2]) * nn[2];
                for (int a = 0; a < 3; ++a) c[a] -= h * nn[a];
            }
        });
    for (auto& t : workers) t.join();
    return discs;
}

std::optional<double> rayHitsDisc(const std::array<double, 3>& o, const std::array<double, 3>& d,
                                  const std::array<double, 3>& c, const std::array<float, 3>& n, double r)
{
    const double nd = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
    if (std::abs(nd) < 1e-12) return std::nullopt; // parallel to the disc's plane
    const std::array<double, 3> oc{c[0] - o[0], c[1] - o[1], c[2] - o[2]};
    const double t = (n[0] * oc[0] + n[1] * oc[1] + n[2] * oc[2]) / nd;
    if (!(t > 0.0)) return std::nullopt;
    const double qx = t * d[0] - oc[0], qy = t * d[1] - oc[1], qz = t * d[2] - oc[2];
    if (qx * qx + qy * qy + qz * qz > r * r) return std::nullopt;
    return t;
}

DiscGrid::DiscGrid(const DiscCloud& discs, double cell) : m_discs(discs)
{
    std::array<double, 3> hi{};
    m_lo = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    hi = {-m_lo[0], -m_lo[1], -m_lo[2]};
    for (std::size_t i = 0; i < discs.size(); ++i)
        for (int a = 0; a < 3; ++a) {
            m_lo[a] = std::min(m_lo[a], discs.centres[i][a] - discs.radii[i]);
            hi[a] = std::max(hi[a], discs.centres[i][a] + discs.radii[i]);
        }
    if (discs.size() == 0) m_lo = hi = {0, 0, 0};
    if (!(cell > 0.0)) {
        std::vector<float> radii = discs.radii;
        const auto middle = radii.begin() + std::ptrdiff_t(radii.size() / 2);
        if (!radii.empty()) std::nth_element(radii.begin(), middle, radii.end());
        cell = radii.empty() ? 1.0 : 4.0 * double(*middle);
        if (!(cell > 0.0)) cell = 1.0;
    }
    constexpr double kMaxCells = double(1 << 25);
    auto cellsFor = [&](double edge) {
        double total = 1.0;
        for (int a = 0; a < 3; ++a) total *= std::floor((hi[a] - m_lo[a]) / edge) + 1.0;
        return total;
    };
    while (cellsFor(cell) > kMaxCells) cell *= 1.25;
    m_cell = cell;
    for (int a = 0; a < 3; ++a) m_dims[a] = int(std::floor((hi[a] - m_lo[a]) / cell)) + 1;

    // Counting sort of (cell, disc) listings into CSR.
    const std::size_t cells = std::size_t(m_dims[0]) * std::size_t(m_dims[1]) * std::size_t(m_dims[2]);
    m_begin.assign(cells + 1, 0);
    auto forEachCell = [&](std::size_t i, auto&& f) {
        int lo[3], up[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::clamp(int(std::floor((discs.centres[i][a] - discs.radii[i] - m_lo[a]) / cell)), 0, m_dims[a] - 1);
            up[a] = std::clamp(int(std::floor((discs.centres[i][a] + discs.radii[i] - m_lo[a]) / cell)), 0, m_dims[a] - 1);
        }
        for (int z = lo[2]; z <= up[2]; ++z)
            for (int y = lo[1]; y <= up[1]; ++y)
                for (int x = lo[0]; x <= up[0]; ++x)
                    f(std::size_t(x) + std::size_t(m_dims[0]) * (std::size_t(y) + std::size_t(m_dims[1]) * std::size_t(z)));
    };
    for (std::size_t i = 0; i < discs.size(); ++i) forEachCell(i, [&](std::size_t c) { ++m_begin[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) m_begin[c + 1] += m_begin[c];
    m_items.resize(m_begin[cells]);
    std::vector<std::uint32_t> fill(m_begin.begin(), m_begin.end() - 1);
    for (std::size_t i = 0; i < discs.size(); ++i)
        forEachCell(i, [&](std::size_t c) { m_items[fill[c]++] = std::uint32_t(i); });
}

bool DiscGrid::blocked(const std::array<double, 3>& o, const std::array<double, 3>& d, double skip) const
{
    // The ray's entry into the grid's box (the origin may lie outside it).
    double tEnter = 0.0, tLeave = std::numeric_limits<double>::max();
    for (int a = 0; a < 3; ++a) {
        const double lo = m_lo[a], hi = m_lo[a] + m_cell * m_dims[a];
        if (std::abs(d[a]) < 1e-300) {
            if (o[a] < lo || o[a] > hi) return false;
            continue;
        }
        double t0 = (lo - o[a]) / d[a], t1 = (hi - o[a]) / d[a];
        if (t0 > t1) std::swap(t0, t1);
        tEnter = std::max(tEnter, t0);
        tLeave = std::min(tLeave, t1);
    }
    if (tEnter > tLeave) return false;
    int cellAt[3], step[3];
    double tNext[3], tDelta[3];
    for (int a = 0; a < 3; ++a) {
        const double x = (o[a] + tEnter * d[a] - m_lo[a]) / m_cell;
        cellAt[a] = std::clamp(int(std::floor(x)), 0, m_dims[a] - 1);
        if (d[a] > 0) {
            step[a] = 1;
            tDelta[a] = m_cell / d[a];
            tNext[a] = (m_lo[a] + (cellAt[a] + 1) * m_cell - o[a]) / d[a];
        } else if (d[a] < 0) {
            step[a] = -1;
            tDelta[a] = -m_cell / d[a];
            tNext[a] = (m_lo[a] + cellAt[a] * m_cell - o[a]) / d[a];
        } else {
            step[a] = 0;
            tDelta[a] = tNext[a] = std::numeric_limits<double>::max();
        }
    }
    const double skip2 = skip * skip;
    for (;;) {
        const std::size_t c = std::size_t(cellAt[0]) +
                              std::size_t(m_dims[0]) * (std::size_t(cellAt[1]) + std::size_t(m_dims[1]) * std::size_t(cellAt[2]));
        for (std::uint32_t k = m_begin[c]; k < m_begin[c + 1]; ++k) {
            const std::uint32_t i = m_items[k];
            const auto& centre = m_discs.centres[i];
            const double dx = centre[0] - o[0], dy = centre[1] - o[1], dz = centre[2] - o[2];
            if (dx * dx + dy * dy + dz * dz <= skip2) continue;
            if (rayHitsDisc(o, d, centre, m_discs.normals[i], m_discs.radii[i])) return true;
        }
        const int a = tNext[0] < tNext[1] ? (tNext[0] < tNext[2] ? 0 : 2) : (tNext[1] < tNext[2] ? 1 : 2);
        cellAt[a] += step[a];
        if (cellAt[a] < 0 || cellAt[a] >= m_dims[a]) return false;
        tNext[a] += tDelta[a];
    }
}

double discSkydome(const DiscGrid& grid, const std::array<double, 3>& p, const std::array<double, 3>& n,
                   std::span<const std::array<double, 3>> directions, double skip, bool twoSided)
{
    std::size_t front = 0, frontSeen = 0, back = 0, backSeen = 0;
    for (const auto& d : directions) {
        const double nd = dot(n, d);
        if (nd > 0.0) {
            ++front;
            frontSeen += grid.blocked(p, d, skip) ? 0 : 1;
        } else if (nd < 0.0 && twoSided) {
            ++back;
            backSeen += grid.blocked(p, d, skip) ? 0 : 1;
        }
    }
    const double f = front ? double(frontSeen) / double(front) : 0.0;
    const double b = back ? double(backSeen) / double(back) : 0.0;
    return twoSided ? std::max(f, b) : f;
}

} // namespace stylos::core::ao
