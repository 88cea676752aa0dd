#pragma once
/** @file
 * @brief The skydome shading of the paper: for every pixel, the solid angle of the sky it sees above
 *        the exact horizon of the whole height field, written normalised to [0, 1] (1 = 2π sr).
 *
 * Horizon. For each of D azimuths a_k = 2πk / D (k = 0 … D−1, clockwise from up; HeightField.h), the
 * grid is cut into the parallel rasterised lines of DirectionRaster.h (every pixel on exactly one
 * line). The horizon angle of pixel p toward a_k is
 *     θ_k(p) = max(0, max over q of atan((h_q − h_p) / dist(p, q))),
 * q ranging over ALL the non-empty pixels of p's line that lie ahead of p toward a_k (no radius limit),
 * dist the metric distance along the direction (pixel size × difference of the projections on the
 * direction). Empty pixels do not occlude (they are skipped, not treated as height 0), and nothing
 * occludes beyond the image border. Heights in metres, so the pixel size matters.
 *
 * Sky. The sky seen in an azimuth sector of width 2π/D above elevation θ is (2π/D)(1 − sin θ)
 * steradians, so the visible solid angle is Ω(p) = (2π/D) Σ_k (1 − sin θ_k(p)): 2π on a hilltop or
 * a flat field, → 0 at the bottom of a deep narrow hole. The value written is Ω / 2π
 * = 1 − (1/D) Σ_k sin θ_k, exactly 1 on a flat field.
 *
 * Method. Per direction, each line is walked once against the direction, keeping on a stack the upper
 * convex hull of the profile behind the current pixel; the horizon is the tangent to that hull, and
 * the pops that find it also restore convexity: amortised O(1) per pixel·direction, exact (equal to a
 * brute-force scan of the line up to float rounding, ~1e-7 relative). A direction and its opposite
 * share their lines (DirectionRaster.h), so with D even each line is read once and walked both ways.
 * 16 neighbouring lines are walked together, one step at a time, in the lanes of one AVX-512 register
 * where the CPU has AVX-512, or as two halves of 8 in AVX2 registers where it has AVX2 only (chosen at
 * run time, SkydomeKernel.h; a portable kernel otherwise, same bits), with the top of each lane's hull
 * held in registers. The lines read a copy of the field in which each step is
 * contiguous: row-major for the row-major rasters, transposed for the column-major ones. Bands of 16
 * lines are shared among SkydomeOptions::threads threads; directions run one after the other, so
 * every pixel's sum is taken in the same order: the image is bitwise identical whatever the thread
 * count (and whichever kernel runs).
 *
 * Cost: pixels × D × ~5 ns of one core with AVX-512 on a Xeon, ~7.5 ns with AVX2 on an AMD EPYC,
 * ~18 ns with the portable kernel (docs/benchmarks.md). Memory: 8 bytes per pixel at most besides the result (a copy of the field and
 * a transposed sum, each 4 bytes per pixel, on huge pages where Linux grants them) plus ~1.5 MiB per
 * thread for a 4096-pixel side. Cancel is checked every 64 lines; progress advances per direction
 * (per pair of opposite directions when D is even).
 *
 * Thread-safety: reentrant; starts and joins its own std::threads; the ProgressSink is called from
 * the calling thread (update) and from the workers (cancel checks). Failure modes: InvalidArgument
 * (directions outside [1, 4096]; a kernel, or STYLOS_SKYDOME_KERNEL, that is unknown or does not run
 * on this CPU), Cancelled.
 */
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/shading/ShadedImage.h"
#include "stylos/core/shading/SkydomeKernel.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <vector>

namespace stylos::core::shading {

/** @brief Parameters of the skydome. */
struct SkydomeOptions {
    int directions = 40; ///< D, number of azimuths evenly spaced from 0 (up), in [1, 4096]
    unsigned threads = 0; ///< worker threads, the caller's included; 0 = hardware threads
    SkydomeKernel kernel = SkydomeKernel::Auto; ///< which kernel walks the horizons (SkydomeKernel.h; same bits)
};

/** @brief Azimuth of direction @p k of @p directions, radians: 2πk / D. */
double skydomeAzimuth(int k, int directions);

/** @brief Ω / 2π per pixel (see the file comment); coverage 0 on Empty pixels. */
Result<ShadedImage> shadeSkydome(const HeightField& field, const SkydomeOptions& options = {},
                                 ProgressSink* progress = nullptr);

/**
 * @brief The horizon angle θ(p) ∈ [0, π/2) toward one @p azimuth of every pixel, radians, row-major
 *        (0 on Empty pixels); the quantity the skydome sums. InvalidArgument for a non-finite azimuth
 *        or a kernel that does not run here, Cancelled.
 */
Result<std::vector<float>> horizonAngles(const HeightField& field, double azimuth, unsigned threads = 0,
                                         ProgressSink* progress = nullptr, SkydomeKernel kernel = SkydomeKernel::Auto);

} // namespace stylos::core::shading
