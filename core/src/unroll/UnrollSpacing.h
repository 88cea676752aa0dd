#pragma once
// Internal to the unroller: the default pixel size, the sampling spacing estimated from the density of
// the points in the (u, v) plane.
#include "UnrollSample.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace stylos::core::unroll::detail {

/**
 * @brief Estimates the sampling spacing d of a scan from its density on the développée.
 *
 * Method: a pseudo-random sample of the kept points (UnrollSample, rate = min(1, kSamplePoints / kept):
 * deterministic, no aliasing with the scan order) is counted in a grid of square cells of side c over u ∈ [0, circumference) ×
 * v ∈ [vMin, vMax], c chosen so that a cell holds about kPerCell sampled points when the points cover
 * the whole rectangle (more where they cover less of it). A scan sampled on a grid of spacing d puts
 * rate · c² / d² sampled points in a covered cell, so d = c · √(rate / m) with m the MEDIAN count of
 * the occupied cells: the median ignores the partly covered cells along the edges and holes and the
 * denser cells where scans overlap (as long as those are fewer than half the cells), so d is the
 * spacing of one scan — about one point per pixel where a single scan covers the surface.
 */
class UnrollSpacing {
public:
    static constexpr double kSamplePoints = 2.0 * 1024 * 1024;
    static constexpr double kPerCell = 64.0;
    static constexpr std::uint64_t kMinPoints = 16; ///< fewer kept points: no estimate

    /** Plans the grid for @p keptPoints points spread over [0, circumference) × [vMin, vMax], metres. */
    UnrollSpacing(double circumference, double vMin, double vMax, std::uint64_t keptPoints);

    /** False when there are too few points (kMinPoints) to estimate anything. */
    bool possible() const { return m_cells > 0; }
    /** Whether point index @p i belongs to the sample (deterministic). */
    bool sampled(std::uint64_t i) const { return m_sample.taken(i); }
    /** Grid cell of a kept point's (u, v), or the cell count when outside the grid. */
    std::size_t cellOf(double u, double v) const;
    std::size_t cellCount() const { return m_cells; }

    /** The spacing from merged cell counts (size cellCount()); nullopt when no cell is occupied. */
    std::optional<double> estimate(const std::vector<std::uint32_t>& counts) const;

private:
    double m_vMin = 0.0;
    UnrollSample m_sample;
    double m_cell = 1.0;
    std::size_t m_columns = 0;
    std::size_t m_rows = 0;
    std::size_t m_cells = 0;
};

} // namespace stylos::core::unroll::detail
