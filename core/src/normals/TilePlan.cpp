#include "TilePlan.h"

#include "NeighbourIndex.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stylos::core::normals::detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double quantile(std::vector<double>& values, double q)
{
    if (values.empty()) return 0.0;
    const auto at = static_cast<std::size_t>(q * double(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(at), values.end());
    return values[at];
}

} // namespace

double estimateHaloMargin(std::span<const double> sample, std::uint64_t totalPoints, std::size_t k)
{
    const std::size_t s = sample.size() / 3;
    if (s < 2 * k || k < 3) return kInfinity;
    std::array<double, 3> lo{kInfinity, kInfinity, kInfinity}, hi{-kInfinity, -kInfinity, -kInfinity};
    for (std::size_t i = 0; i < s; ++i)
        for (int d = 0; d < 3; ++d) {
            lo[d] = std::min(lo[d], sample[3 * i + d]);
            hi[d] = std::max(hi[d], sample[3 * i + d]);
        }
    const std::array<double, 3> origin{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
    const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);

    const NeighbourIndex index(sample, origin, 16, 1);
    const std::size_t small = std::max<std::size_t>(1, (k - 1) / 5); // neighbours besides the point itself
    std::vector<double> far, near;
    far.reserve(s);
    near.reserve(s);
    KnnScratch scratch;
    std::vector<std::uint32_t> queries;
    for (const auto& leaf : index.leaves()) {
        queries.clear();
        for (std::uint32_t p = leaf.begin; p < leaf.end; ++p) queries.push_back(p);
        index.search(queries, k, scratch);
        for (std::size_t q = 0; q < queries.size(); ++q) {
            far.push_back(std::sqrt(double(scratch.squaredDistance(q, k - 1))));
            near.push_back(std::sqrt(double(scratch.squaredDistance(q, small))));
        }
    }
    const double farMedian = quantile(far, 0.5), nearMedian = quantile(near, 0.5);
    double dimension = 2.0; // a surface, unless the sample says otherwise
    if (nearMedian > 0 && farMedian > nearMedian)
        dimension = std::clamp(std::log(double(k - 1) / double(small)) / std::log(farMedian / nearMedian), 1.0, 3.0);
    const double density = std::min(1.0, double(s) / double(std::max<std::uint64_t>(totalPoints, 1)));
    const double margin = 1.5 * quantile(far, 0.99) * std::pow(density, 1.0 / dimension);
    return std::max(margin, 1e-9 * diagonal);
}

TilePlan::TilePlan(std::span<const double> sample, const std::array<double, 6>& bounds, unsigned levels,
                   double margin)
    : m_margin(margin)
{
    std::vector<double> points(sample.begin(), sample.end());
    const TileBox everything{{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}};
    build(points, 0, points.size() / 3, everything, 0, levels, bounds);
}

std::uint32_t TilePlan::build(std::vector<double>& sample, std::size_t begin, std::size_t end, TileBox box,
                              unsigned depth, unsigned levels, const std::array<double, 6>& bounds)
{
    const auto node = static_cast<std::uint32_t>(m_nodes.size());
    m_nodes.push_back(Split{-1, 0, static_cast<std::uint32_t>(m_boxes.size()), 0});
    if (depth == levels) {
        m_boxes.push_back(box);
        return node;
    }
    // The longest side of the cell, its infinite sides clipped to the cloud's bounds.
    int axis = 0;
    double longest = -1;
    std::array<double, 3> lo{}, hi{};
    for (int d = 0; d < 3; ++d) {
        lo[d] = std::max(box.lo[d], bounds[d]);
        hi[d] = std::min(box.hi[d], bounds[3 + d]);
        if (hi[d] - lo[d] > longest) {
            longest = hi[d] - lo[d];
            axis = d;
        }
    }
    // Split at the sample median (points are 3 doubles; sort a copy of the coordinates of the range).
    const std::size_t count = end - begin;
    double value = 0.5 * (lo[axis] + hi[axis]);
    if (count >= 2) {
        std::vector<double> coordinates(count);
        for (std::size_t i = 0; i < count; ++i) coordinates[i] = sample[3 * (begin + i) + axis];
        const std::size_t middle = count / 2;
        std::nth_element(coordinates.begin(), coordinates.begin() + std::ptrdiff_t(middle), coordinates.end());
        if (coordinates[middle] > lo[axis] && coordinates[middle] < hi[axis]) value = coordinates[middle];
    }
    // Partition the sample range: low side first.
    std::size_t split = begin;
    for (std::size_t i = begin; i < end; ++i)
        if (sample[3 * i + axis] < value) {
            for (int d = 0; d < 3; ++d) std::swap(sample[3 * i + d], sample[3 * split + d]);
            ++split;
        }
    TileBox lowBox = box, highBox = box;
    lowBox.hi[axis] = value;
    highBox.lo[axis] = value;
    const std::uint32_t low = build(sample, begin, split, lowBox, depth + 1, levels, bounds);
    const std::uint32_t high = build(sample, split, end, highBox, depth + 1, levels, bounds);
    m_nodes[node] = Split{axis, value, low, high};
    return node;
}

std::uint32_t TilePlan::ownTile(const double* p) const
{
    std::uint32_t node = 0;
    while (m_nodes[node].axis >= 0)
        node = p[m_nodes[node].axis] < m_nodes[node].value ? m_nodes[node].low : m_nodes[node].high;
    return m_nodes[node].low;
}

void TilePlan::haloTiles(const double* p, std::vector<std::uint32_t>& out) const
{
    out.clear();
    collect(0, p, ownTile(p), out);
}

void TilePlan::collect(std::uint32_t node, const double* p, std::uint32_t own, std::vector<std::uint32_t>& out) const
{
    const Split& split = m_nodes[node];
    if (split.axis < 0) {
        if (split.low != own) out.push_back(split.low);
        return;
    }
    // A tile's halo is everything within the margin of its box, sides included.
    if (p[split.axis] - m_margin <= split.value) collect(split.low, p, own, out);
    if (p[split.axis] + m_margin >= split.value) collect(split.high, p, own, out);
}

} // namespace stylos::core::normals::detail
