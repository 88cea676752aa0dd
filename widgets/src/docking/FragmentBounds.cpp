#include "docking/FragmentBounds.h"

#include "stylos/core/view/GuideGeometry.h"

namespace stylos::widgets {

Eigen::AlignedBox3d FragmentBounds::of(const SceneDocument& document, SceneDocument::FragmentId id)
{
    SceneDocument::OctreePtr octree = document.octree(id);
    if (!octree) {
        m_cache.erase(id);
        return {};
    }
    auto it = m_cache.find(id);
    if (it == m_cache.end() || it->second.octree != octree)
        it = m_cache.insert_or_assign(id, Entry{octree, core::view::occupiedBounds(*octree, m_level)}).first;
    return it->second.bounds;
}

const core::view::OccupiedCells& FragmentBounds::cells(const SceneDocument& document, SceneDocument::FragmentId id)
{
    static const core::view::OccupiedCells none;
    SceneDocument::OctreePtr octree = document.octree(id);
    if (!octree) {
        m_cells.erase(id);
        return none;
    }
    auto it = m_cells.find(id);
    if (it == m_cells.end() || it->second.octree != octree)
        it = m_cells.insert_or_assign(id, CellsEntry{octree, core::view::occupiedCells(*octree, m_level)}).first;
    return it->second.cells;
}

} // namespace stylos::widgets
