#include "stylos/core/view/BudgetShare.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace stylos::core::view {

std::vector<std::uint64_t> shareBudget(const std::vector<double>& demands, const std::vector<std::uint64_t>& caps,
                                       std::uint64_t budget)
{
    assert(demands.size() == caps.size() && "shareBudget(): one cap per demand");
    const std::size_t n = std::min(demands.size(), caps.size());
    std::vector<std::uint64_t> out(n, 0);
    std::vector<char> active(n, 0);
    for (std::size_t i = 0; i < n; ++i) active[i] = demands[i] > 0 && std::isfinite(demands[i]) && caps[i] > 0;
    std::uint64_t remaining = budget;
    for (;;) {
        double total = 0;
        for (std::size_t i = 0; i < n; ++i) total += active[i] ? demands[i] : 0.0;
        if (total <= 0 || remaining == 0) break;
        bool capped = false;
        const double pool = double(remaining);
        for (std::size_t i = 0; i < n; ++i) {
            if (!active[i] || pool * demands[i] / total < double(caps[i])) continue;
            out[i] = caps[i]; // Σ caps taken here ≤ Σ shares ≤ remaining
            remaining -= caps[i];
            active[i] = 0;
            capped = true;
        }
        if (capped) continue;
        std::uint64_t given = 0;
        for (std::size_t i = 0; i < n; ++i)
            if (active[i]) given += out[i] = std::uint64_t(pool * demands[i] / total);
        // Rounding leaves fewer than n points: one each to those that got none, then to the first ones.
        std::uint64_t left = remaining - std::min(given, remaining);
        for (std::size_t i = 0; i < n && left > 0; ++i)
            if (active[i] && out[i] == 0) { ++out[i]; --left; }
        for (std::size_t i = 0; i < n && left > 0; ++i)
            if (active[i] && out[i] < caps[i]) { ++out[i]; --left; }
        break;
    }
    return out;
}

} // namespace stylos::core::view
