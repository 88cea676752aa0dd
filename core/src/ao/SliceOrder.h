#pragma once
// Internal to core/ao: the cells sorted into slices along each axis, for the Slices kernel.
#include "AoKernel.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace stylos::core::ao::detail {

/**
 * For each main axis m (0 x, 1 y, 2 z), the cell indices sorted by (c_m, c_b, c_a) with a = (m + 1) mod 3
 * and b = (m + 2) mod 3: slice by slice, and in a slice row (fixed b) after row, a increasing. Built by
 * three stable counting sorts per axis, O(cells + extent). Memory: 12 bytes per cell plus the offsets.
 * Read-only once built: shared by the kernels of all threads.
 */
struct SliceOrder {
    std::array<std::vector<std::uint32_t>, 3> cells;       ///< per axis: cell indices in slice order
    std::array<std::vector<std::uint32_t>, 3> sliceBegin;  ///< per axis: extent + 1 offsets into cells[m]
};

SliceOrder buildSliceOrder(const PreparedCells& cells);

/**
 * The order of @p cells, built once and shared while any kernel holds it: the kernels of one
 * computation (one per thread) are made from the same PreparedCells and get the same object; the
 * first builds it, the others wait. Keyed by the address of @p cells, which is unique while a holder
 * lives (a kernel must not outlive its cells). Thread-safe.
 */
std::shared_ptr<const SliceOrder> sharedSliceOrder(const PreparedCells& cells);

} // namespace stylos::core::ao::detail
