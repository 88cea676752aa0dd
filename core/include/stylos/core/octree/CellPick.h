#pragma once
/** @file
 * @brief Picking on a packed octree without materialising it: the leaf nearest a 3D point, and the
 *        first leaf along a ray within a radius that grows with distance (a pixel's footprint). Both are
 *        branch-and-bound descents that visit only cells whose box can still beat the best found.
 *        Units: metres. Thread-safety: reentrant, reads the octree only.
 */
#include "stylos/core/octree/PackedOctree.h"

#include <array>
#include <optional>

namespace stylos::core::octree {

struct PickedCell {
    CellView cell;            ///< a cell of the leaf level (or of `level` when given)
    double distance = 0;      ///< nearestCell: distance from the query point to the cell's centre;
                              ///< pickRay: distance along the ray to the centre's projection
};

/**
 * @brief The cell of @p level (−1: the leaf level) whose centre is nearest @p point, within
 *        @p maxDistance (metres; infinity: any). Empty for an empty result.
 */
std::optional<PickedCell> nearestCell(const PackedOctree& octree, const std::array<double, 3>& point,
                                      double maxDistance, int level = -1);

/**
 * @brief The cell of @p level (−1: the leaf level), nearest the ray origin along the ray, whose centre
 *        lies within radius(t) = @p radiusAtOrigin + t · @p radiusPerMetre of the ray (t: distance
 *        along the ray, ≥ 0). @p direction need not be unit. Empty if none.
 */
std::optional<PickedCell> pickRay(const PackedOctree& octree, const std::array<double, 3>& origin,
                                  const std::array<double, 3>& direction, double radiusAtOrigin,
                                  double radiusPerMetre, int level = -1);

} // namespace stylos::core::octree
