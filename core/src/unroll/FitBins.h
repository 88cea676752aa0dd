#pragma once
// Internal to the surface fit: axial coordinates of a sample, robust radii by axial bins, and a robust
// straight profile through them (the starting profile of the cylinder, cone and meridian fits).
#include "FitSample.h"
#include "FitSeed.h"

#include <cstddef>
#include <vector>

namespace stylos::core::unroll::detail {

/** @brief t = (p − point)·direction and r = the distance from @p axis for every point of @p sample. */
void axialCoordinates(const FitPoints& sample, const Eigen::Vector3d& centre, const FitLine& axis,
                      std::vector<double>& t, std::vector<double>& r);

/** @brief The median radius of one slice of the axis. */
struct FitBin {
    double t = 0.0;        ///< middle of the slice, metres
    double r = 0.0;        ///< median radius of its points, metres
    std::size_t count = 0; ///< its points
};

/**
 * @brief Cuts [0.1 %, 99.9 %] quantiles of @p t into @p bins equal slices and gives the median
 *        radius of each slice that holds at least 5 points and a tenth of the median slice's (the
 *        others — sparse clutter beyond the object's ends — are left out).
 */
std::vector<FitBin> medianRadiusByT(const std::vector<double>& t, const std::vector<double>& r, int bins);

/** @brief r = intercept + slope · t. */
struct FitProfileLine {
    double intercept = 0.0;
    double slope = 0.0;
};

/** @brief Theil–Sen line through the bins (median of pairwise slopes, then median intercept): robust
 *         to bins dominated by bed faces or breaks. @p withSlope false: slope 0, median radius. */
FitProfileLine robustProfileLine(const std::vector<FitBin>& bins, bool withSlope);

/**
 * @brief The offset from @p line of the densest band of residuals r − line(t) within ±@p range: the
 *        peak of their histogram (200 bins, smoothed twice by (1, 2, 1) / 4); 0 when none is in range.
 */
double densestOffset(const std::vector<double>& t, const std::vector<double>& r, const FitProfileLine& line,
                     double range);

/** Median of @p values (reorders them); 0 when empty. */
double medianOf(std::vector<double>& values);

} // namespace stylos::core::unroll::detail
