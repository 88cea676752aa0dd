#pragma once
/** @file
 * @brief The pixel sets the développée's painting tools select, on a width × height grid (pixel (c, r) spans
 *        [c, c + 1) × [r, r + 1), row 0 at the top, index r · width + c). Plain geometry on the grid: what the
 *        pixels mean (leaves, labels) is the caller's. Every result is ascending and unique, and only the
 *        pixels it returns are visited (plus, for the fills, their 4-neighbours), so a small stroke on a huge
 *        image costs what it touches.
 *
 * - brushPixels: the pixels whose centre lies within @p radius of the segment a–b (a round brush dragged
 *   from a to b; a == b is one dab). Continuous pixel coordinates.
 * - polygonPixels: the pixels whose centre is inside the closed polygon (even–odd rule), a polygon or a lasso.
 * - floodFill ("magic wand"): from @p seed, the 4-connected pixels whose value v is valid and within
 *   @p tolerance of the seed's (|v − v_seed| ≤ tolerance: a fixed range, so the region does not creep).
 * - enclosedHoles: the holes of the region that holds @p seed (its 4-connected pixels of the seed's id, an id
 *   ≠ 0): the 4-connected groups of other pixels that the region surrounds, i.e. that cannot reach the image
 *   border without crossing it. Whatever they hold (unlabelled, another class, no data) they are holes.
 *
 * Thread-safety: reentrant. Preconditions (asserted): sizes consistent, width · height < 2³².
 */
#include <cstdint>
#include <span>
#include <vector>

namespace stylos::core::annotation {

struct GridPoint {
    double x = 0.0; ///< continuous column
    double y = 0.0; ///< continuous row
};

std::vector<std::uint32_t> brushPixels(GridPoint a, GridPoint b, double radius, int width, int height);

std::vector<std::uint32_t> polygonPixels(std::span<const GridPoint> polygon, int width, int height);

/** @param valid per pixel, nonzero where the value exists (an Empty pixel of the développée is 0); an invalid
 *         or out-of-grid seed gives nothing. */
std::vector<std::uint32_t> floodFill(std::span<const float> values, std::span<const std::uint8_t> valid, int width,
                                     int height, std::uint32_t seed, float tolerance);

/** @param ids per pixel (the labels shown); a seed on id 0 or out of the grid gives nothing. */
std::vector<std::uint32_t> enclosedHoles(std::span<const std::uint8_t> ids, int width, int height, std::uint32_t seed);

} // namespace stylos::core::annotation
