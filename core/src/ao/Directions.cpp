#include "stylos/core/ao/Directions.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stylos::core::ao {

std::vector<Direction> fibonacciDirections(int count, bool upperHemisphere)
{
    const int n = std::clamp(count, 1, 65536);
    const double goldenAngle = std::numbers::pi * (3.0 - std::sqrt(5.0));
    std::vector<Direction> directions;
    directions.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double z = upperHemisphere ? 1.0 - (i + 0.5) / n : 1.0 - (2.0 * i + 1.0) / n;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = goldenAngle * i;
        directions.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    return directions;
}

} // namespace stylos::core::ao
