#pragma once
/** @file
 * @brief For comparison with the skydome: the sky-view factor of the Relief Visualization Toolbox
 *        (RVT; Zakšek, Oštir, Kokalj 2011), a radius-limited ray march.
 *
 * For each of D azimuths a_k = 2πk / D (same convention and same directions as SkydomeShading.h),
 * RVT samples the ray at radii r = r_min, r_min + 1/3, …, r_max pixels, rounds each sample to a pixel
 * offset (round half to even, as numpy) and keeps the distinct offsets; the horizon angle is the
 * largest atan((h_q − h_p) / |offset| · s) over them, clamped at 0, |offset| the Euclidean length of
 * the rounded offset and s the pixel size. The value is 1 − (1/D) Σ_k sin θ_k, RVT's SVF, normalised
 * like the skydome (1 on a flat field).
 *
 * Differences from RVT, deliberate: samples outside the image or on Empty pixels are skipped (RVT
 * pads by reflection and treats NaN as open), so that the border is handled as in the skydome; RVT's
 * optional noise removal and vertical exaggeration are left out.
 *
 * Cost: pixels × D × (distinct offsets, ~3 r_max) slope evaluations, vectorised along rows; memory 4
 * bytes per pixel (a copy of the heights with NaN for Empty) plus the image. Rows are shared among
 * threads; the result does not depend on the thread count. Cancel is checked every 16 rows.
 *
 * Thread-safety: reentrant; starts and joins its own threads. Failure modes: InvalidArgument
 * (directions outside [1, 4096], minRadius < 1, radius < minRadius or > 4096), Cancelled.
 */
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/shading/ShadedImage.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

namespace stylos::core::shading {

/** @brief Parameters of the RVT-like sky-view factor (RVT's defaults). */
struct SkyViewOptions {
    int directions = 16;  ///< D, in [1, 4096]
    int radius = 10;      ///< r_max, pixels
    int minRadius = 1;    ///< r_min, pixels (≥ 1)
    unsigned threads = 0; ///< worker threads, the caller's included; 0 = hardware threads
};

/** @brief RVT's sky-view factor in [0, 1] (see the file comment); coverage 0 on Empty pixels. */
Result<ShadedImage> shadeSkyViewFactor(const HeightField& field, const SkyViewOptions& options = {},
                                       ProgressSink* progress = nullptr);

} // namespace stylos::core::shading
