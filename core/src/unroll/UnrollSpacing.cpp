#include "UnrollSpacing.h"

#include <algorithm>
#include <cmath>

namespace stylos::core::unroll::detail {

namespace {

constexpr double kMaxCells = 4.0 * 1024 * 1024; ///< caps the grid (16 MiB of counts per worker)

} // namespace

UnrollSpacing::UnrollSpacing(double circumference, double vMin, double vMax, std::uint64_t keptPoints)
    : m_vMin(vMin), m_sample(kSamplePoints, keptPoints)
{
    if (keptPoints < kMinPoints || !(circumference > 0.0) || !std::isfinite(vMax - vMin)) return;
    const double sampled = m_sample.rate() * double(keptPoints);
    // Height of the rectangle: at least one cell's worth of the circumference, so a ring of points
    // (all at one v) still gets square cells.
    const double vRange = std::max(vMax - vMin, circumference / std::max(1.0, sampled / kPerCell));
    const double wanted = std::clamp(sampled / kPerCell, 1.0, kMaxCells);
    m_cell = std::sqrt(circumference * vRange / wanted);
    m_columns = std::max<std::size_t>(1, std::size_t(std::ceil(circumference / m_cell)));
    m_rows = std::max<std::size_t>(1, std::size_t(std::floor((vMax - vMin) / m_cell)) + 1);
    m_cells = m_columns * m_rows;
}

std::size_t UnrollSpacing::cellOf(double u, double v) const
{
    const double c = std::floor(u / m_cell), r = std::floor((v - m_vMin) / m_cell);
    if (!(c >= 0.0) || !(r >= 0.0)) return m_cells;
    const auto column = std::min(m_columns - 1, std::size_t(c));
    const auto row = std::size_t(r);
    return row < m_rows ? row * m_columns + column : m_cells;
}

std::optional<double> UnrollSpacing::estimate(const std::vector<std::uint32_t>& counts) const
{
    std::vector<std::uint32_t> occupied;
    for (std::uint32_t n : counts)
        if (n > 0) occupied.push_back(n);
    if (occupied.empty()) return std::nullopt;
    const auto middle = occupied.begin() + std::ptrdiff_t(occupied.size() / 2);
    std::nth_element(occupied.begin(), middle, occupied.end());
    const double spacing = m_cell * std::sqrt(m_sample.rate() / double(*middle));
    if (!std::isfinite(spacing) || !(spacing > 0.0)) return std::nullopt;
    return spacing;
}

} // namespace stylos::core::unroll::detail
