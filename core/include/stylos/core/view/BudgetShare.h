#pragma once
/** @file
 * @brief How the 3D view shares one point budget among its fragments: water-filling in proportion to what
 *        each needs, none above its cap, what a capped one cannot use shared among the others.
 *
 * Units: points (cells of a cut). Thread-safety: a pure function. Failure modes: none; a demand that is
 * zero, negative or not finite, or a zero cap, gets 0. @p demands and @p caps must have the same size
 * (programmer error otherwise, asserted).
 */
#include <cstdint>
#include <vector>

namespace stylos::core::view {

/**
 * @brief The share of @p budget of each fragment: in proportion to @p demands, none above its cap in @p caps,
 *        what a capped one cannot use shared among the others. Σ ≤ budget; every fragment with a demand gets at
 *        least 1 while the budget lasts, and what rounding leaves goes to the first ones below their caps.
 */
std::vector<std::uint64_t> shareBudget(const std::vector<double>& demands, const std::vector<std::uint64_t>& caps,
                                       std::uint64_t budget);

} // namespace stylos::core::view
