#pragma once
/** @file
 * @brief A procedural point source of any size that is never stored: points of a fluted drum (the
 *        shape of DrumShape: radius, height, grooves, both bed faces) sampled uniformly at random with
 *        their true normals, generated batch by batch from a counter-based random generator, so that
 *        reading it again yields exactly the same points in the same order (what the Optimal octree
 *        builder needs, pass after pass) and memory stays flat for 300 M points or more.
 *
 * Point i depends only on (seed, i): the stream can also be opened at any offset. Positions in metres
 * in the drum's own frame (axis = z, base at z = 0). Thread-safety: one reader per thread; readers are
 * independent.
 */
#include "stylos/core/io/PointReader.h"

#include <cstdint>
#include <memory>

namespace stylos::core::synth {

struct SyntheticStreamOptions {
    std::uint64_t points = 1'000'000;  ///< total points the stream yields
    std::uint64_t seed = 1;
    double radius = 0.55;              ///< metres
    double height = 0.5;               ///< metres
    int grooves = 48;                  ///< flutes around the drum
    double grooveDepth = 0.008;        ///< metres
    double noise = 0.0;                ///< Gaussian noise along the normal, metres (σ)
    bool shuffled = true;              ///< false: points ordered by angle then height (scan-like order)
};

/**
 * @brief A PointReader over the procedural drum (format "synthetic-drum", schema: normals, no colour).
 *        InvalidArgument for zero points or non-positive sizes.
 */
Result<std::unique_ptr<io::PointReader>> openSyntheticStream(const SyntheticStreamOptions& options);

} // namespace stylos::core::synth
