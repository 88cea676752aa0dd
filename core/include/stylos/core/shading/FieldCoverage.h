#pragma once
/** @file
 * @brief How much of an object's footprint on a height field has a height: the measure behind the
 *        développée's pixel-size rule ("a well-covered image").
 *
 * The footprint is the morphological closing of the non-empty pixels (Measured or Filled) by a square of
 * half-side @p radius pixels: gaps narrower than about 2·radius between pixels with a height count as
 * part of the object, wider ones (a broken region, the air beside a statue) do not. The coverage is the
 * share of the footprint's pixels that have a height. A pixel far smaller than the sampling spacing
 * leaves most pixels of the footprint empty (low coverage); a well-chosen one covers nearly all of it.
 *
 * Cost: four sliding-window passes over the pixels, 2 bytes a pixel of scratch. Units: pixels.
 * Thread-safety: reentrant. Failure modes: none (an empty field has coverage 0).
 */
#include "stylos/core/shading/HeightField.h"

#include <cstdint>
#include <vector>

namespace stylos::core::shading {

struct FieldCoverage {
    std::uint64_t withHeight = 0; ///< Measured + Filled pixels
    std::uint64_t footprint = 0;  ///< pixels of the closed footprint (≥ withHeight)
    /** withHeight / footprint, in [0, 1]; 0 for an empty field. */
    double fraction() const { return footprint > 0 ? double(withHeight) / double(footprint) : 0.0; }
};

/** @brief The coverage of @p field's footprint closed by a square of half-side @p radius (≥ 0) pixels. */
FieldCoverage measureCoverage(const HeightField& field, int radius);

/** @brief The footprint itself: 1 for the pixels of the closing of those with a height (and those with one), row-major. */
std::vector<std::uint8_t> footprintMask(const HeightField& field, int radius);

} // namespace stylos::core::shading
