#pragma once
/** @file
 * @brief One directional light (Lambert): value = max(0, n · l), n the unit normal of the height field
 *        and l the unit vector toward the light.
 *
 * Frame (HeightField.h): x to the right (columns), y up (toward row 0), z the height. The light's
 * azimuth is measured clockwise from up (0: light from the top of the image, π/2: from the right;
 * the default 7π/4 is the cartographers' upper-left light), its elevation from the horizontal plane:
 * l = (sin a · cos e, cos a · cos e, sin e).
 *
 * Normal: n ∝ (−k ∂h/∂x, −k ∂h/∂y, 1), k the vertical exaggeration, the derivatives by central
 * differences in metres ((h[c+1] − h[c−1]) / 2s, s the pixel size); a one-sided difference where one
 * neighbour is Empty or outside, 0 where both are. A plane facing the light gives exactly 1 (up to
 * rounding), a plane whose normal makes angle α with l gives cos α, a flat field gives sin e.
 *
 * Units: metres and radians. Cost O(pixels). Thread-safety: reentrant; reads the field only.
 * Failure modes: InvalidArgument (elevation outside [0, π/2], azimuth or exaggeration not finite,
 * exaggeration ≤ 0).
 */
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/shading/ShadedImage.h"
#include "stylos/core/util/Result.h"

#include <numbers>

namespace stylos::core::shading {

/** @brief Parameters of the light shading. */
struct LightShadingOptions {
    double azimuth = 1.75 * std::numbers::pi; ///< radians, clockwise from up (upper-left by default)
    double elevation = 0.25 * std::numbers::pi; ///< radians above the horizontal, in [0, π/2]
    double verticalExaggeration = 1.0; ///< multiplies the heights (> 0)
};

/** @brief Lambert shading in [0, 1] (see the file comment); InvalidArgument for bad options. */
Result<ShadedImage> shadeLight(const HeightField& field, const LightShadingOptions& options = {});

} // namespace stylos::core::shading
