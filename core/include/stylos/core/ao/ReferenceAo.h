#pragma once
/** @file
 * @brief The brute-force 3D skydome against which the fast methods are measured: for each sample cell
 *        and each direction of the set, a ray from the cell's centre walks the level's grid cell by
 *        cell (3D DDA, Amanatides & Woo) over a hash set of the occupied cells until it leaves their
 *        bounding box; it is blocked by the first occupied cell it enters (the start cell excluded)
 *        whose centre lies more than `bias` edges above the sample's tangent plane. The value is the
 *        definition of AmbientOcclusion.h with binary visibility. Cost: O(samples · D · grid span).
 * Thread-safety: reentrant; uses `options.threads` threads over the samples. Failure modes: InvalidArgument
 * (directions outside 1..65536, a negative bias, a sample index out of range), Cancelled.
 */
#include "stylos/core/ao/AmbientOcclusion.h"

#include <cstddef>
#include <span>
#include <vector>

namespace stylos::core::ao {

/** @brief Values in [0, 1] for @p samples (indices into @p cells), in that order. */
Result<std::vector<float>> referenceAmbientOcclusion(const AoCells& cells, std::span<const std::size_t> samples,
                                                     const AoOptions& options, ProgressSink* progress = nullptr);

} // namespace stylos::core::ao
