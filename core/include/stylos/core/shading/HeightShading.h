#pragma once
/** @file
 * @brief Height as grey: each non-empty pixel's height mapped linearly from a robust range
 *        [low, high] to [0, 1] (clamped), low and high being percentiles of the non-empty heights so
 *        that a few outliers (dust, a spike of the scan) do not flatten the image.
 *
 * Percentile q ∈ [0, 1] of the n non-empty heights sorted ascending: the element of 0-based rank
 * floor(q · (n − 1) + 0.5) (nearest rank). grey = clamp((h − low) / (high − low), 0, 1); when
 * high == low (a flat field) every covered pixel is 0.5. Empty pixels get coverage 0, value 0.
 *
 * Units: heights in metres. Cost O(n) (selection, not a full sort); memory 4 bytes per pixel.
 * Thread-safety: reentrant; reads the field only. Failure modes: InvalidArgument (percentiles outside
 * [0, 1] or low > high; an explicit range that is not finite or has low > high).
 */
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/shading/ShadedImage.h"
#include "stylos/core/util/Result.h"

#include <optional>

namespace stylos::core::shading {

/** @brief A height interval, metres. */
struct HeightRange {
    double low = 0.0;
    double high = 0.0;
};

/** @brief Parameters of the height shading. */
struct HeightShadingOptions {
    double lowPercentile = 0.01;  ///< fraction in [0, 1]: maps to black
    double highPercentile = 0.99; ///< fraction in [0, 1], ≥ lowPercentile: maps to white
    /** A fixed range (metres) instead of the percentiles, e.g. to shade several fields alike. */
    std::optional<HeightRange> range;
};

/**
 * @brief The @p lowPercentile and @p highPercentile heights of the non-empty pixels (nearest rank).
 * @return the range ({0, 0} when no pixel has a height), or InvalidArgument for bad percentiles.
 */
Result<HeightRange> robustHeightRange(const HeightField& field, double lowPercentile, double highPercentile);

/** @brief Height as grey in [0, 1] (see the file comment); InvalidArgument for bad options. */
Result<ShadedImage> shadeHeight(const HeightField& field, const HeightShadingOptions& options = {});

} // namespace stylos::core::shading
