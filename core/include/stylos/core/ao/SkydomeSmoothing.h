#pragma once
/** @file
 * @brief The 3D skydome's values smoothed over neighbouring leaves on the same surface: each receiver takes
 *        the Gaussian-weighted mean of the values of the receivers within @p radius whose normal is within
 *        acos(minCos) of its own (either orientation: a leaf measured two-sided may have been turned), so the
 *        noise that each leaf's own position and normal carry (sampling, scanner noise: σ 0.33 mm at 2 mm
 *        spacing reads as per-leaf grain) averages out while a crease or an edge, where the normals part,
 *        keeps its two sides apart. Weight (1 − d²/radius²)²: 1 at the receiver, 0 at the radius.
 *
 * Measured against the analytic truth (docs/benchmarks.md, "3D skydome against the true geometry"): at 1.5
 * occluder cell edges (SkydomeLayer's default), r 0.891 → 0.910 on a generated 2 mm drum.
 *
 * Units: positions and radius in any one unit (SkydomeLayer passes the occluders' cell edges). Memory: 44
 * bytes a receiver (the sorted bins, the receivers in bin order; the results go straight to the values), plus
 * the bin table. Threads: @p threads
 * (0: all cores). Thread-safety: reentrant. Failure modes: Cancelled (values left as they were).
 */
#include "stylos/core/ao/AoCells.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <span>

namespace stylos::core::ao {

struct SkydomeSmoothing {
    double radius = 0.0;  ///< in the receivers' units; ≤ 0: nothing done
    float minCos = 0.8f;  ///< neighbours whose |n·n'| is below this are left out (0.8: about 37°)
    unsigned threads = 0; ///< 0: hardware concurrency
};

/** @brief Replaces @p values (one per receiver, in receiver order) by their smoothed values. */
Status smoothSkydome(const AoReceivers& receivers, std::span<float> values, const SkydomeSmoothing& options,
                     ProgressSink* progress = nullptr);

} // namespace stylos::core::ao
