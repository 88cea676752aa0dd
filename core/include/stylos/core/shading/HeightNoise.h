#pragma once
/** @file
 * @brief Scanner noise in a height field, and the smoothing that removes it before the skydome.
 *
 * The exact horizon of the skydome (SkydomeShading.h) reads every bump as relief: at the sampling spacing a
 * scanner's noise (σ ≈ 0.3 mm) tilts the horizon of the nearest pixels by tens of degrees, and the image
 * turns to salt and pepper where the surface is flat and open. estimateHeightNoise() measures σ on the field
 * itself: the residual of each measured pixel against the mean of its four measured neighbours is
 * σ·√(5/4) for white noise, and smooth relief adds only its curvature × pixel² (micrometres for a flute at
 * half a millimetre), so 1.4826 × the median absolute residual / √1.25 is σ, robust to edges and breaks.
 *
 * noiseSmoothingSigma() turns σ into the standard deviation s of a Gaussian that leaves slopes between
 * neighbouring pixels with a noise of kSlopeNoise (white noise of σ under a 2D Gaussian of s pixels keeps
 * σ / (2√π s)): s = σ / (2√π · kSlopeNoise · pixel), none below half a pixel. smoothHeights() applies it as a
 * normalised convolution over the non-empty pixels (separable, ±3s), so empty pixels neither take nor give
 * height and the edges of a fragment are not pulled down; the states are kept.
 *
 * Units: metres. Thread-safety: reentrant. smoothHeights: threads as SkydomeOptions (0 = hardware).
 */
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/util/Result.h"

namespace stylos::core::shading {

/** @brief The slope noise (rise over run between neighbouring pixels) the automatic smoothing leaves. */
inline constexpr double kSlopeNoise = 0.05;

/** @brief Largest Gaussian σ smoothHeights() takes, pixels (a radius of 3σ = 48 pixels). */
inline constexpr double kMaxSmoothingPixels = 16.0;

/** @brief σ of the height noise, metres (see the file comment); 0 when fewer than 64 measured pixels have
 *         four measured neighbours. */
double estimateHeightNoise(const HeightField& field);

/** @brief The Gaussian σ (metres) that leaves kSlopeNoise from a noise of @p noise at @p pixelSize; 0 when that
 *         is under half a pixel; at most kMaxSmoothingPixels pixels. */
double noiseSmoothingSigma(double noise, double pixelSize);

/**
 * @brief @p field smoothed by a Gaussian of standard deviation @p sigma metres over its non-empty pixels
 *        (see the file comment). @p sigma 0 returns a copy. InvalidArgument when @p sigma is negative, not
 *        finite or over kMaxSmoothingPixels pixels.
 */
Result<HeightField> smoothHeights(const HeightField& field, double sigma, unsigned threads = 0);

} // namespace stylos::core::shading
