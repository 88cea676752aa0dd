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

} // namespace stylos::widgets
