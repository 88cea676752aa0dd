#pragma once
/** @file
 * @brief A procedural point source of any size that is never stored: points of a fluted drum sampled
 *        uniformly by area with their true outward normals, generated batch by batch from a
 *        counter-based random generator, so that reading it again yields exactly the same points in the
 *        same order (what the Optimal octree builder needs, pass after pass) and memory stays flat for
 *        300 M points or more (a few KiB of tables, plus the caller's batch).
 *
 * The shape: a cylinder of radius R (to the fillets) and height H whose lateral surface carries N
 * concave circular-arc flutes separated by fillets (the flute outline of DrumShape: the same arcs for the
 * same radius, groove count, depth and fillet fraction, groove 0 centred on azimuth 0), and both bed
 * faces, flat (no anathyrosis), bounded by the fluted outline. No claw band, no broken region. With
 * 0 grooves, a plain cylinder with its two discs.
 *
 * Sampling: uniform by area (exact up to rounding). The lateral surface is parametrised by arc length
 * around the outline and height; a bed face as a fan from the axis, by swept area (closed form on the
 * fillet arcs, the inverse of the closed-form swept area of a flute arc by a table and one Newton step)
 * and the square root of a uniform variate for the radius.
 *
 * Point i depends only on (seed, i): it uses outputs 3i, 3i + 1 and 3i + 2 of SplitMix64 seeded with
 * `seed` (the surface in shuffled order; the two coordinates, from the high and low 32 bits — a
 * resolution below a nanometre —; the noise). Two orders:
 *  - shuffled (default): every point picks its surface at random (probability ∝ area) and a position
 *    uniformly on it: i.i.d. samples, no spatial coherence between consecutive points.
 *  - ordered (`shuffled = false`), scan-like: the counts per surface are fixed (bottom face, lateral
 *    surface, top face, in proportion to their areas, rounded) and the points come in that order. On each
 *    surface point j of its n_s lies in the thin column (j + U)/n_s along the angular coordinate (arc
 *    length, or swept area on a bed face) and in row (j mod r) of r rows across it (height, or r² on a
 *    bed face), r ≈ the square root of n_s scaled so that cells are about square: the points sweep the
 *    surface by azimuth, column after column, each column from bottom to top (from the axis outward).
 *    The marginals are exactly uniform; locally the density is uniform at the scale of one column.
 *
 * Noise (σ > 0) moves each point along its normal by a Gaussian variate (Box–Muller on the third
 * variate), so points leave the surface by a few σ; the normal stays the true one.
 *
 * Positions in metres in the drum's own frame (axis = z, lower bed at z = 0). Speed, one thread, no
 * noise: see docs/benchmarks.md (`stylos_octree_benchmark --stream N`); the maps are branch-free and use
 * no libm call per point (tables and short polynomials). Noise adds a log and a cos per point.
 * Thread-safety: one reader per thread; readers are independent and share nothing.
 */
#include "stylos/core/io/PointReader.h"

#include <cstdint>
#include <memory>

namespace stylos::core::synth {

struct SyntheticStreamOptions {
    std::uint64_t points = 1'000'000;  ///< total points of the stream (indices 0 .. points − 1)
    std::uint64_t offset = 0;          ///< first index the reader yields (≤ points): it yields points − offset
    std::uint64_t seed = 1;
    double radius = 0.55;              ///< to the fillets, metres
    double height = 0.5;               ///< metres
    int grooves = 48;                  ///< flutes around the drum; 0: a plain cylinder; else 3..1000
    double grooveDepth = 0.008;        ///< from the fillet circle to the bottom of a flute, metres
    double filletFraction = 0.1;       ///< share of the flute pitch taken by the fillet, [0, 1)
    double noise = 0.0;                ///< Gaussian noise along the normal, metres (σ ≥ 0)
    bool shuffled = true;              ///< false: scan-like order (see the file comment)
};

/** @brief Areas of the procedural drum (m²), as the sampler uses them. */
struct SyntheticDrumAreas {
    double lateral = 0;   ///< outline perimeter × height
    double bed = 0;       ///< one bed face (the disc of radius R less the flutes)
    double perimeter = 0; ///< length of the fluted outline, metres
};

/**
 * @brief A PointReader over the procedural drum: format "synthetic-drum", path "synthetic-drum",
 *        schema: normals (unit, outward), no colour; declaredPoints = points − offset; fileBytes and
 *        bytesConsumed count 36 bytes per point (the size of the same points in a binary PLY with double
 *        positions and float normals), for progress.
 *        InvalidArgument (message "synthetic-drum: problem") for zero points, an offset past the end,
 *        non-positive or non-finite sizes, a negative noise, or flutes that cannot be concave arcs (the
 *        rules of DrumParameters::problem()).
 */
Result<std::unique_ptr<io::PointReader>> openSyntheticStream(const SyntheticStreamOptions& options);

/** @brief The areas of the drum that @p options describe; the same InvalidArgument errors. */
Result<SyntheticDrumAreas> syntheticDrumAreas(const SyntheticStreamOptions& options);

} // namespace stylos::core::synth
