#pragma once
/** @file
 * @brief Which leaves of a fragment a lasso drawn in the 3D view covers and the eye sees: the leaves whose
 *        centre projects inside the polygon and lies on the nearest surface there — not the back of a drum,
 *        not what another fragment hides. The 3D lasso of the annotation (widgets LassoTool) labels them.
 *
 * Method: every leaf of every visible fragment is projected with the camera; within the polygon's bounding
 * box a coarse depth buffer (cells of LassoOptions::cellPixels pixels) keeps the nearest depth, each leaf
 * rasterised as a disc in the plane of its normal (two-sided) of radius max(its spacing, half its edge)
 * (PackedOctree::leafSpacing), as the splats are drawn, so that the front surface has no holes through which
 * the back would show. A target leaf inside the polygon is visible when its depth is within
 * toleranceSpacings × that radius, plus slopeAllowance × the size of a buffer cell at its depth (a slanted
 * surface spans that much depth in one cell), of the buffer at its cell. All leaves are read, not the view's
 * level-of-detail cut, so what is labelled does not depend on how far the view has refined.
 *
 * Units: pixels (the camera's viewport, y downwards, as Camera::project), metres. Cost: one pass over the
 * leaves of the visible fragments (a few hundred ns a leaf). Thread-safety: reentrant; reads the shared
 * octrees only. Failure modes: none; a polygon of fewer than three vertices, or one outside the viewport,
 * selects nothing; hidden fragments and fragments without an octree neither occlude nor are selected.
 */
#include "stylos/core/view/Camera.h"
#include "stylos/core/view/ViewFragment.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace stylos::core::view {

struct LassoOptions {
    double cellPixels = 2.0;         ///< edge of a depth-buffer cell, pixels (≥ 1)
    double toleranceSpacings = 1.5;  ///< depth tolerance, in leaf radii (spacings)
    double slopeAllowance = 2.0;     ///< extra tolerance, in buffer cells at the leaf's depth (slanted surfaces)
};

/** @brief The leaves of one fragment a lasso selects (ascending leaf indices). */
struct LassoLeaves {
    std::uint64_t fragment = 0;
    std::vector<std::uint32_t> leaves;
};

/** @brief Whether the point (@p x, @p y) lies inside @p polygon (even-odd rule; the polygon is closed). */
bool insidePolygon(const std::vector<Eigen::Vector2d>& polygon, double x, double y);

/**
 * @brief The visible leaves inside @p polygon (pixels of @p camera) of each fragment of @p targets that is
 *        visible among @p fragments, one entry per such target (in @p targets' order, possibly with no
 *        leaves); every visible fragment occludes.
 */
std::vector<LassoLeaves> lassoVisibleLeaves(const std::vector<ViewFragment>& fragments, const Camera& camera,
                                            const std::vector<std::uint64_t>& targets,
                                            const std::vector<Eigen::Vector2d>& polygon,
                                            const LassoOptions& options = {});

} // namespace stylos::core::view
