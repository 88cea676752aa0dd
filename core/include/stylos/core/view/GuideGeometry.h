#pragma once
/** @file
 * @brief What the 3D view needs of a fragment's guides, in the scene frame: the docking drum's axis and flute
 *        pitch (its first Axis guide through its pose; 2π / the number of its Groove guides), each guide as a
 *        segment over the fragment's extent (the axis over the drum's height, each flute line along it), and
 *        that extent: the bounds of the octree's occupied cells at a coarse level.
 *        Units: metres, radians. Thread-safety: pure functions (the octree is only read).
 *        Failure modes: none; a fragment without an Axis guide has no drum axis.
 */
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/scene/Fragment.h"
#include "stylos/core/view/GizmoHandles.h"

#include <Eigen/Geometry>

#include <optional>
#include <vector>

namespace stylos::core::view {

/** @brief The drum axis of @p drum in the scene frame (its first Axis guide through @p world, its fragment
 *         frame → scene frame pose: Scene::worldPose(); its own pose when null, right at the top level) and
 *         its flute pitch (2π / its Groove guides; 0 without any); nullopt when it has no Axis guide. */
std::optional<DrumAxis> drumAxisOf(const scene::Fragment& drum, const scene::Pose* world = nullptr);

/** @brief A guide drawn as a segment, scene frame. */
struct GuideSegment {
    Eigen::Vector3d a = Eigen::Vector3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    scene::GuideKind kind = scene::GuideKind::Axis;
};

/** @brief Each guide of @p fragment over @p localBounds (its own frame): the part of the guide's line between the
 *         projections of the box's corners on it, through @p world (as for drumAxisOf()). None for an empty box. */
std::vector<GuideSegment> guideSegments(const scene::Fragment& fragment, const Eigen::AlignedBox3d& localBounds,
                                        const scene::Pose* world = nullptr);

/** @brief The occupied cells of one level of an octree, its own frame: their centres and their edge. */
struct OccupiedCells {
    std::vector<Eigen::Vector3d> centres;
    double size = 0.0;
};
/** @brief @p octree's cells at @p level (clamped to its depth). */
OccupiedCells occupiedCells(const octree::PackedOctree& octree, int level);
/** @brief Each guide of @p fragment over the extent of @p cells along it: the part of its line between the lowest and
 *         highest projections of the cells' corners — over the fragment's height whatever its pose in its file (the
 *         box of the file's axes made the lines of a tilted drum 2–3 times its height). None without cells. */
std::vector<GuideSegment> guideSegments(const scene::Fragment& fragment, const OccupiedCells& cells,
                                        const scene::Pose* world = nullptr);

/** @brief The bounds of @p octree's cells at @p level (clamped to its depth; whole cells), in its own frame: found
 *         by a branch-and-bound descent per face (a few cells per level), so the leaf level costs little even on a
 *         30 M-leaf octree. Empty for an octree without cells. */
Eigen::AlignedBox3d occupiedBounds(const octree::PackedOctree& octree, int level = 5);

} // namespace stylos::core::view
