#pragma once
/** @file
 * @brief The extent of each fragment in its own frame (core::view::occupiedBounds of its opened octree, at a
 *        coarse level by default), cached per octree so that a pose change costs nothing. For the gizmo's centre,
 *        the guides' lengths and the Properties' size (at the leaves). GUI thread only.
 */
#include "stylos/core/view/GuideGeometry.h"
#include "stylos/widgets/document/SceneDocument.h"

#include <Eigen/Geometry>

#include <map>

namespace stylos::widgets {

class FragmentBounds {
public:
    /** @brief Bounds of the cells of @p level (clamped to each octree's depth: a large value gives the leaves). */
    explicit FragmentBounds(int level = 5) : m_level(level) {}

    /** @brief The bounds of @p id's octree in its own frame; empty while it has none. */
    Eigen::AlignedBox3d of(const SceneDocument& document, SceneDocument::FragmentId id);
    /** @brief The occupied cells of @p id's octree at the level (its own frame); none while it has no octree. */
    const core::view::OccupiedCells& cells(const SceneDocument& document, SceneDocument::FragmentId id);
    /** @brief Drops what is kept for @p id (its octree too: a removed fragment's file is not held open). */
    void forget(SceneDocument::FragmentId id)
    {
        m_cache.erase(id);
        m_cells.erase(id);
    }
    void clear()
    {
        m_cache.clear();
        m_cells.clear();
    }

private:
    struct Entry {
        SceneDocument::OctreePtr octree; ///< kept, so that its address is not reused
        Eigen::AlignedBox3d bounds;
    };
    struct CellsEntry {
        SceneDocument::OctreePtr octree;
        core::view::OccupiedCells cells;
    };
    int m_level;
    std::map<SceneDocument::FragmentId, Entry> m_cache;
    std::map<SceneDocument::FragmentId, CellsEntry> m_cells;
};

} // namespace stylos::widgets
