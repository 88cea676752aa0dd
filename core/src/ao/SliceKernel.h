#pragma once
// Internal to core/ao: the paper's method (Duguet et al. 2004, section 6), made sparse. See SliceKernel.cpp.
#include "AoKernel.h"
#include "SliceMask.h"
#include "SliceOrder.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace stylos::core::ao::detail {

/** Choices of the Slices kernel (the defaults are the measured best; the others stay for measurements
 *  and tests). */
struct SliceTuning {
    /** Read the mask at the cell's centre ray (one mask cell) rather than area-weighted over its square. */
    bool pointRead = true;
    /** β: edges added to the bias when the direction drifts across the slices (0 along an axis), for the
     *  mask's own blur: a square split over whole mask cells reaches a reader up to 1½ edges from the
     *  square's centre line, against ½ for the square itself. */
    double maskTolerance = 0.75;
    /** Steps between two writes to a mask cell that still belong to one burst (one surface). */
    int burstGap = 2;
};

/** Counters over all run() calls of one kernel (for benchmarks). */
struct SliceStats {
    std::uint64_t directions = 0;
    std::uint64_t cellVisits = 0;   ///< cells × directions
    std::uint64_t reads = 0;        ///< cells read (n·d > 0)
    std::uint64_t maskWrites = 0;   ///< mask cells composed (one per covered mask cell and slice)
    std::uint64_t tiles = 0;        ///< mask tiles written, summed over directions
    std::uint64_t maskBox = 0;      ///< mask box area (width × height), summed over directions
};

/**
 * One thread's Slices kernel: per direction, the cells are swept slice by slice along the main axis of
 * the direction, from the sky inward, against a SliceMask kept in the light's frame. The per-axis slice
 * order is shared between the kernels of one computation (sharedSliceOrder).
 */
class SliceKernel final : public DirectionKernel {
public:
    SliceKernel(const PreparedCells& cells, const AoOptions& options, SliceTuning tuning = {});
    void run(const std::array<float, 3>& d, Accumulator& sums) override;
    const SliceStats& stats() const { return m_stats; }
    const SliceMask& mask() const { return m_mask; }

private:
    /** Where the squares of one step fall in the light's frame: cell a covers mask columns a + base
     *  (1 − frac) and a + base + 1 (frac); likewise rows. */
    struct Placement {
        int baseA = 0, baseB = 0;
        float fracA = 0.0f, fracB = 0.0f;
        int readA = 0, readB = 0;   ///< point read: the mask cell of the centre ray is (a + readA, b + readB)
    };
    /** (mask column, coverage) of one slice row, by column. */
    struct Coverage {
        int column;
        float value;
    };

    void readSlice(std::uint32_t begin, std::uint32_t end, std::size_t step, const Placement& at, Accumulator& sums);
    void depositSlice(std::uint32_t begin, std::uint32_t end, std::uint32_t step, const Placement& at);
    void rowCoverage(std::uint32_t begin, std::uint32_t end, const Placement& at, std::vector<Coverage>& out) const;
    void composeRow(int row, const std::vector<Coverage>& first, float firstScale, const std::vector<Coverage>* second,
                    float secondScale, std::uint32_t step);

    const PreparedCells& m_cells;
    AoOptions m_options;
    SliceTuning m_tuning;
    std::shared_ptr<const SliceOrder> m_order;
    SliceMask m_mask;
    std::vector<Coverage> m_previousRow, m_currentRow;
    // The current direction.
    int m_axisA = 0, m_axisB = 0;
    float m_direction[3] = {0.0f, 0.0f, 0.0f};
    double m_tolerance = 0.0, m_far = 0.0;
    SliceStats m_stats;
};

} // namespace stylos::core::ao::detail
