#pragma once
/** @file
 * @brief The extent of each fragment in its own frame (core::view::occupiedBounds of its opened octree at a
 *        coarse level), cached per octree so that a pose change costs nothing. For the gizmo's centre and the
 *        guides' lengths. GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"

#include <Eigen/Geometry>

#include <map>

namespace stylos::widgets {

class FragmentBounds {
public:
    /** @brief The bounds of @p id's octree in its own frame; empty while it has none. */
    Eigen::AlignedBox3d of(const SceneDocument& document, SceneDocument::FragmentId id);

private:
    struct Entry {
        SceneDocument::OctreePtr octree; ///< kept, so that its address is not reused
        Eigen::AlignedBox3d bounds;
    };
    std::map<SceneDocument::FragmentId, Entry> m_cache;
};

} // namespace stylos::widgets
