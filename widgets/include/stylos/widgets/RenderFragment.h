#pragma once
/** @file
 * @brief What the 3D view needs of one fragment of the scene: its packed octree, its pose and how to
 *        show it. The scene document builds these (ViewportWidget::setFragments); the view never reads
 *        the document itself.
 */
#include "stylos/core/octree/PackedOctree.h"

#include <QColor>

#include <Eigen/Core>

#include <cstdint>
#include <memory>

namespace stylos::widgets {

/** @brief One fragment as the view draws it. Plain value; the octree is shared and immutable. */
struct RenderFragment {
    std::uint64_t id = 0;                                          ///< stable identity (picking, buffers)
    std::shared_ptr<const core::octree::PackedOctree> octree;      ///< null: nothing to draw
    Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();            ///< rigid: octree frame → scene frame, metres
    QColor colour = QColor(200, 190, 170);                         ///< base colour (headlight shading)
    bool visible = true;
    bool selected = false;
};

} // namespace stylos::widgets
