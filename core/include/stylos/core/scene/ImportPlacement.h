#pragma once
/** @file
 * @brief Where an imported scan goes in the scene. Scans made in the same site frame (coordinates at least
 *        SiteDistance from the origin) and near one another keep their true relative places: the new one
 *        takes the pose of the fragment it lies beside, so all of them share that fragment's one offset.
 *        The first scan in site coordinates is moved by one offset, its box centre rounded to whole metres,
 *        so that the scene works near the origin. Any other scan (an object in its own frame, near the
 *        origin, or a site scan far from the others) is set down beside the scene: to its +x side, a gap of
 *        a quarter of the larger of the two sizes between them, centred on the scene in y, on the scene's
 *        ground (the lowest z). The first scan of an empty scene near the origin stays where it is.
 *        Units: metres. Pure functions; thread-safe.
 */
#include "stylos/core/scene/Pose.h"

#include <Eigen/Geometry>

#include <vector>

namespace stylos::core::scene {

/** @brief Coordinates at least this far from the origin (metres) are a site's (a museum or site frame). */
inline constexpr double SiteDistance = 100.0;

/** @brief A fragment already in the scene: its extent in its own (file) frame and its pose in the scene. */
struct PlacedExtent {
    Eigen::AlignedBox3d local;
    Pose world;
};

/** @brief The pose (file frame → scene) for a scan whose extent in its file frame is @p incoming, in a
 *         scene of @p placed (fragments with an empty extent are ignored). An empty @p incoming: identity. */
Pose placeImport(const std::vector<PlacedExtent>& placed, const Eigen::AlignedBox3d& incoming);

/** @brief The bounds in the scene of @p extent (its local box's eight corners, posed). */
Eigen::AlignedBox3d worldBounds(const PlacedExtent& extent);

} // namespace stylos::core::scene
