#pragma once
// Internal to the shadings: percentiles by nearest rank.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace stylos::core::shading::detail {

/** The element of 0-based rank floor(q (n − 1) + 0.5) of @p values (non-empty; reorders them). */
inline float nearestRank(std::vector<float>& values, double q)
{
    const auto rank = std::size_t(std::floor(q * double(values.size() - 1) + 0.5));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(rank), values.end());
    return values[rank];
}

/** True when 0 ≤ low ≤ high ≤ 1. */
inline bool validPercentiles(double low, double high) { return low >= 0.0 && low <= high && high <= 1.0; }

} // namespace stylos::core::shading::detail
