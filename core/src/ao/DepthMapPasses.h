#pragma once
// Internal to the DepthMap skydome kernel: its two passes over the cells for one direction, compiled
// for several instruction sets (the same arithmetic, no fused multiply-add: every variant gives the same
// bits), the best one the processor runs chosen once.
#include "AoKernel.h"
#include "DepthMapFrame.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace stylos::core::ao::detail {

/** Per-worker scratch of the passes: cells are processed in blocks of kBlock. */
struct DepthMapScratch {
    static constexpr std::size_t kBlock = 64;
    alignas(64) std::uint32_t index[kBlock];    ///< map index of the cell's (first) pixel
    alignas(64) std::int32_t row[2 * kBlock];   ///< pass 1: entries for pixels (iu, iv), (iu + 1, iv)
    alignas(64) std::int32_t below[2 * kBlock]; ///< pass 1: entries for row iv + 1
    alignas(64) std::int32_t ownKey[kBlock];    ///< pass 2
    alignas(64) std::int32_t entry[kBlock];     ///< pass 2: the map at the cell's pixel
    alignas(64) float toPixel[2][kBlock];       ///< pass 2: pixel centre − the cell's projection
    alignas(64) std::uint32_t seenMask[kBlock]; ///< pass 2, two-sided: all ones where the receiver sees d
    alignas(64) float nDotD[kBlock];            ///< pass 2, two-sided: n · d
};

/**
 * Pass 1 (splat) writes every cell into @p map (f.width × f.height entries, zeroed by the caller);
 * pass 2 (test) adds, for every cell, w and w · visibility to @p sums, skipping the blocks of kBlock
 * cells whose flag in @p facing is 0 (all their weights are 0). See DepthMapKernel.cpp.
 */
struct DepthMapPasses {
    void (*splat)(const DepthMapFrame& f, const PreparedCells& cells, std::int32_t* map, DepthMapScratch& scratch);
    void (*test)(const DepthMapFrame& f, const PreparedCells& cells, const std::int32_t* map,
                 const std::uint8_t* facing, float bias, bool cosine, Accumulator& sums, DepthMapScratch& scratch);
    /** Pass 2 for receivers anywhere in their cells (AoReceivers), not at the cells' centres: the
     *  occluder's centre rebuilt from the map, hidden beyond the cube's half-extent along n + bias. */
    void (*testOffLattice)(const DepthMapFrame& f, const PreparedCells& receivers, const std::int32_t* map,
                           const std::uint8_t* facing, float bias, bool cosine, Accumulator& sums,
                           DepthMapScratch& scratch);
    /** testOffLattice on both sides of each receiver's tangent plane (AoOptions::twoSided): a direction
     *  with n·d < 0 is measured with −n and added to the sums' back half; @p facing is not read. */
    void (*testTwoSided)(const DepthMapFrame& f, const PreparedCells& receivers, const std::int32_t* map,
                         const std::uint8_t* facing, float bias, bool cosine, Accumulator& sums,
                         DepthMapScratch& scratch);
    const char* isa; ///< "avx512", "avx2" or "portable"
};

/** The variants this processor can run, the fastest first (at least the portable one). */
std::vector<DepthMapPasses> depthMapPassVariants();

} // namespace stylos::core::ao::detail
