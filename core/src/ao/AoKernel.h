#pragma once
// Internal to core/ao: what a method does for one direction, and the per-thread sums it adds to.
#include "stylos/core/ao/AmbientOcclusion.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace stylos::core::ao::detail {

/**
 * The cells as the kernels read them, structure of arrays: centres in cell edges relative to the grid
 * corner (x = coords.x + 0.5, exact in float up to level 23), unit normals, opacity. Built once.
 */
struct PreparedCells {
    std::vector<float> x, y, z;
    std::vector<float> nx, ny, nz;
    std::vector<float> opacity;
    std::array<std::uint32_t, 3> extent{};   ///< 1 + the largest coordinate on each axis
    std::size_t size() const { return x.size(); }
};

PreparedCells prepareCells(const AoCells& cells);
/** Receivers in the same layout (positions as x, y, z; opacity and extent unused). */
PreparedCells prepareReceivers(const AoReceivers& receivers);

/** Sums over the directions one worker ran: seen[i] = Σ w·v, total[i] = Σ w; two-sided, the same for the
 *  directions behind the tangent plane (measured with −n) in seenBack, totalBack (empty otherwise). */
struct Accumulator {
    std::vector<float> seen, total;
    std::vector<float> seenBack, totalBack;
    explicit Accumulator(std::size_t cells, bool twoSided = false)
        : seen(cells, 0.0f), total(cells, 0.0f), seenBack(twoSided ? cells : 0, 0.0f),
          totalBack(twoSided ? cells : 0, 0.0f)
    {
    }
};

/** w for n·d: 0 behind the tangent plane; 1, or n·d when cosine-weighted. */
inline float directionWeight(float nDotD, bool cosineWeighted)
{
    return nDotD > 0.0f ? (cosineWeighted ? nDotD : 1.0f) : 0.0f;
}

/**
 * One worker's method: run() adds, for every cell, w and w · visibility toward unit direction d (the sky
 * side) to @p sums. A kernel keeps its scratch (masks, depth maps) between directions; one per thread.
 */
class DirectionKernel {
public:
    virtual ~DirectionKernel() = default;
    virtual void run(const std::array<float, 3>& d, Accumulator& sums) = 0;
};

struct DepthMapPasses; // DepthMapPasses.h

/**
 * The DepthMap passes to run: the best instruction set this processor runs (AVX-512, AVX2, plain x86-64), or
 * the one that the environment variable STYLOS_AO_PASSES names ("avx512", "avx2", "portable": to measure
 * another on the same machine; all give the same bits). Read once per skydome, before its kernels are made.
 * InvalidArgument naming the variable when it names none that this processor runs.
 */
Result<const DepthMapPasses*> chosenDepthMapPasses();

/** With @p receivers, pass 2 measures them (AoReceivers, off the cells' lattice) instead of the cells. */
std::unique_ptr<DirectionKernel> makeDepthMapKernel(const PreparedCells& cells, const AoOptions& options,
                                                    const DepthMapPasses& passes,
                                                    const PreparedCells* receivers = nullptr);
std::unique_ptr<DirectionKernel> makeSliceKernel(const PreparedCells& cells, const AoOptions& options);

} // namespace stylos::core::ao::detail
