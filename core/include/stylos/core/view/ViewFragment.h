#pragma once
/** @file
 * @brief What the 3D view needs of one fragment of the scene: its packed octree, its pose and how to show
 *        it; and the comparison that tells a change of poses alone from any other change (poseChanges),
 *        so that moving a fragment updates its model matrix without recomputing the level-of-detail cut.
 *        The application builds these from the scene document (app/gui ViewportSync); the view never
 *        reads the document.
 *
 * Units: metres (the pose's translation). Thread-safety: value types and a pure function; the octree is
 * shared and immutable, safe to read from any thread. Failure modes: none.
 */
#include "stylos/core/octree/PackedOctree.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace stylos::core::view {

/** @brief One fragment as the view draws it. Plain value; the octree is shared and immutable. */
struct ViewFragment {
    std::uint64_t id = 0;                                     ///< stable identity (picking, buffers)
    std::shared_ptr<const octree::PackedOctree> octree;       ///< null: nothing to draw
    Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();       ///< rigid: octree frame → scene frame, metres
    std::array<std::uint8_t, 3> colour{200, 190, 170};        ///< base colour, sRGB, 8 bits (headlight shading)
    bool visible = true;
    bool selected = false;
};

/** @brief A new pose for the fragment @p id. */
struct PoseChange {
    std::uint64_t id = 0;
    Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
};

/**
 * @brief When @p next differs from @p current in poses only — the same ids in the same order, the same
 *        octrees (the same objects), colours, visibility and selection — the poses that changed (in
 *        @p next's order; empty when nothing changed at all); otherwise (anything else changed) nullopt.
 *        Poses compare exactly, element by element.
 */
std::optional<std::vector<PoseChange>> poseChanges(const std::vector<ViewFragment>& current,
                                                   const std::vector<ViewFragment>& next);

} // namespace stylos::core::view
