#pragma once
/** @file
 * @brief Well-spread direction sets for the 3D skydome: a Fibonacci (golden-angle) spiral over the whole
 *        sphere or over the upper hemisphere (z > 0, the world's up as CloudCompare's PCV takes it).
 *        Each direction stands for an equal solid angle (4π / D, or 2π / D for the hemisphere).
 *
 * Points i = 0..D−1: z_i = 1 − (2i + 1) / D (sphere) or 1 − (i + ½) / D (hemisphere), r_i = √(1 − z_i²),
 * φ_i = i · π (3 − √5); d_i = (r_i cos φ_i, r_i sin φ_i, z_i). Deterministic; unit length to 1e-15.
 * Thread-safety: reentrant. Failure modes: none (a count outside [1, 65536] is clamped).
 */
#include <array>
#include <vector>

namespace stylos::core::ao {

using Direction = std::array<double, 3>;

/** @brief The D = @p count directions of the spiral, over the sphere or only its z > 0 half. */
std::vector<Direction> fibonacciDirections(int count, bool upperHemisphere);

} // namespace stylos::core::ao
