#pragma once
/** @file
 * @brief Questions the 3D view asks of its fragments without drawing: their bounds in the scene frame
 *        (from the cells of a coarse level, so tighter than the root boxes) and the surface point under
 *        a pixel (core::octree::pickRay against each visible fragment's leaves, in its own frame).
 *
 * Units: metres (scene frame), pixels (the camera's viewport, y downwards). Thread-safety: reentrant;
 * reads the shared octrees only. Failure modes: none; fragments without an octree or hidden are skipped,
 * and "nothing" is an empty box or an empty optional.
 */
#include "stylos/core/view/Camera.h"
#include "stylos/core/view/ViewFragment.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <vector>

namespace stylos::core::view {

/** @brief A surface point under a pixel. */
struct ScenePick {
    Eigen::Vector3d point = Eigen::Vector3d::Zero(); ///< scene frame, metres (the centre of the leaf cell hit)
    std::uint64_t fragmentId = 0;
    double cellSize = 0;                             ///< edge of that leaf cell, metres
    double along = 0;                                ///< distance along the ray, metres
};

/** @brief Bounds of the visible fragments (only the selected ones with @p selectedOnly); empty if none. */
Eigen::AlignedBox3d sceneBounds(const std::vector<ViewFragment>& fragments, bool selectedOnly = false);

/**
 * @brief The corners of the cells the visible fragments occupy at a coarse level (level 5, or the octree's
 *        depth when less: at most 32 Ki cells each), posed into the scene frame; only the selected ones with
 *        @p selectedOnly. What Camera::fit(points) frames: tighter than a box round a rotated fragment.
 */
std::vector<Eigen::Vector3d> sceneCorners(const std::vector<ViewFragment>& fragments, bool selectedOnly = false);

/**
 * @brief The nearest leaf along the ray through the pixel (@p x, @p y) of @p camera among the visible
 *        fragments, within @p radiusPixels of the ray (the pixel footprint at each depth).
 */
std::optional<ScenePick> pickScene(const std::vector<ViewFragment>& fragments, const Camera& camera, double x,
                                   double y, double radiusPixels = 3.0);

} // namespace stylos::core::view
