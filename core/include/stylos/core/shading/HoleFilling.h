#pragma once
/** @file
 * @brief Fills the small holes of a height field from their neighbours, as the paper does, and leaves
 *        large holes and regions open to the image border empty (transparent) rather than invent them.
 *
 * Method. A hole is a connected component of Empty pixels (8-connected by default, 4 as an option).
 * A hole is filled only when all of these hold:
 *   - it touches no image border (a region open to the border is outside the object, not a hole);
 *   - its area is at most HoleFillOptions::maxArea pixels;
 *   - its depth — the largest number of steps (in the same connectivity) from one of its pixels to
 *     the nearest non-empty pixel — is at most maxDepth (0: no depth limit). A thin crack of any
 *     length has depth 1; a round hole of radius R has depth about R.
 * A hole is filled from its border inward, in rounds: round k gives every pixel at depth k the
 * plain average of its non-empty neighbours (same connectivity) — Measured pixels and pixels filled
 * in rounds before k, never pixels of the same round — and marks it Filled. The average is taken in
 * double and stored as float. Holes never interact (the neighbours of a hole's pixels are its own
 * pixels or non-empty ones), so the result is independent of any processing order: deterministic.
 * Pixels already Filled by an earlier call count as non-empty.
 *
 * Cost: O(pixels + E log E) for E empty pixels in fillable holes; memory 1 byte per pixel (visited
 * flags), 4 bytes per pixel of the largest empty region, 16 per pixel of the largest hole filled and 8
 * per filled pixel. Cancel is checked every 64 rows of the scan; nothing is written before it ends.
 *
 * Units: heights in metres (only averaged). Thread-safety: reentrant; the field is modified in place
 * and must not be used by another thread meanwhile. Failure modes: InvalidArgument (maxArea 0,
 * negative maxDepth) and Cancelled, both leaving the field unchanged.
 */
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <cstddef>

namespace stylos::core::shading {

/** @brief Which pixels count as neighbours, for both the hole components and the averages. */
enum class Connectivity {
    Four = 4,  ///< left, right, up, down
    Eight = 8, ///< and the four diagonals (the default)
};

/** @brief Which holes are filled (see the file comment). */
struct HoleFillOptions {
    Connectivity connectivity = Connectivity::Eight;
    /** Largest hole filled, in pixels (≥ 1). 256 px is 8 mm × 8 mm at 0.5 mm pixels. */
    std::size_t maxArea = 256;
    /** Largest hole depth filled, in pixels (0: no limit on the depth, only on the area). */
    int maxDepth = 0;
};

/** @brief What a fill did. */
struct HoleFillReport {
    std::size_t holes = 0;            ///< components of Empty pixels found (border ones included)
    std::size_t filledHoles = 0;      ///< of which filled
    std::size_t filledPixels = 0;     ///< pixels turned from Empty to Filled
    std::size_t borderPixels = 0;     ///< Empty pixels left because their component touches the border
    std::size_t largeHolePixels = 0;  ///< Empty pixels left because their hole is too large or too deep
    int deepestFill = 0;              ///< largest depth filled (rounds), pixels
};

/**
 * @brief Fills the holes of @p field in place (see the file comment).
 * @return the report, or InvalidArgument / Cancelled (field unchanged).
 */
Result<HoleFillReport> fillHoles(HeightField& field, const HoleFillOptions& options = {},
                                 ProgressSink* progress = nullptr);

/**
 * @brief Fills the gaps between samples that fillHoles() leaves: the Empty pixels inside the object's footprint
 *        (footprintMask(): the closing of the pixels with a height by a square of half-side @p radius ≥ 1), whatever
 *        the size of the empty region they belong to or whether it reaches the border. A pixel near the sampling
 *        spacing leaves one-pixel gaps that join into networks larger than maxArea, which read as cracks; a gap
 *        narrower than about 2 · radius belongs to the object (the coverage's rule), a wider region (a broken face,
 *        the air beside the object) keeps its Empty pixels beyond the footprint. Filled as fillHoles() fills, from
 *        the rim inward in rounds, each pixel the average of its neighbours with a height; the pixels of a region
 *        that no round reaches stay Empty. Report: holes = empty regions met, filledHoles = those with a pixel filled,
 *        largeHolePixels = pixels left Empty. Deterministic; InvalidArgument (radius < 1) and Cancelled leave the
 *        field unchanged.
 */
Result<HoleFillReport> fillFootprintGaps(HeightField& field, int radius, Connectivity connectivity = Connectivity::Eight,
                                         ProgressSink* progress = nullptr);

} // namespace stylos::core::shading
