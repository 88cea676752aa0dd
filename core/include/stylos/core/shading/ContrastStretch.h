#pragma once
/** @file
 * @brief Display contrast for a shading: the covered values mapped linearly so that a robust range
 *        [low, high] (percentiles of the covered values) spans [0, 1], clamped. A skydome of a drum
 *        varies within a few tenths below 1 (a flute sees less sky than a fillet, a broken cavity far
 *        less): stretched, it reads like an engraving; unstretched, it is the exact fraction of the sky.
 *
 * Percentile q of the n covered values: the element of 0-based rank floor(q (n − 1) + 0.5) (nearest
 * rank, as HeightShading.h). value = clamp((v − low) / (high − low), 0, 1); when high == low every
 * covered value becomes 0.5. Uncovered pixels stay 0.
 *
 * Cost O(n); memory 4 bytes per covered pixel. Thread-safety: modifies the image in place; reentrant.
 * Failure modes: InvalidArgument for percentiles outside 0 ≤ low ≤ high ≤ 1 (image unchanged).
 */
#include "stylos/core/shading/ShadedImage.h"
#include "stylos/core/util/Result.h"

namespace stylos::core::shading {

/** @brief The values that were mapped to 0 and 1. */
struct ValueRange {
    float low = 0.0f;
    float high = 0.0f;
};

/** @brief Stretches @p image in place (see the file comment); returns the range ({0, 0} when nothing is covered). */
Result<ValueRange> stretchContrast(ShadedImage& image, double lowPercentile = 0.01, double highPercentile = 0.99);

} // namespace stylos::core::shading
