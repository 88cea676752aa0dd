#pragma once
/** @file
 * @brief Black-and-white hatches of annotation classes as vector strokes, traced from the class ids of a
 *        panel's pixels (never from colours): for each class, the parallel lines of its hatch (45°, −45°,
 *        horizontal, vertical, or two of them crossed) clipped to its pixels, or dots on a grid. Vectors, so
 *        the PDF and SVG keep them sharp at any zoom and no clip path is needed (Qt 6.4's SVG writer drops clip
 *        paths: plates-annotation.md, B3).
 *
 * Lines of one family are @p spacingPx apart, anchored at the image's top-left corner so neighbouring classes'
 * lines line up. Each line is walked in steps of half a pixel; a run of steps in the class becomes a segment
 * from its first to its last step. "solid" gives horizontal lines at a third of the spacing.
 * Units: pixels of the panel image (x right, y down). Thread-safety: pure. Cost: (width + height) / spacing
 * lines of at most 2 · (width + height) steps per family.
 */
#include "stylos/core/annotation/Legend.h"

#include <cstdint>
#include <span>
#include <vector>

namespace stylos::core::plate {

struct HatchSegment {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;   ///< equal ends: a dot
};

std::vector<HatchSegment> hatchSegments(std::span<const std::uint8_t> classes, int width, int height, std::uint8_t id,
                                        annotation::Hatch hatch, double spacingPx);

} // namespace stylos::core::plate
