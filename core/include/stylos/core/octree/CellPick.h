#pragma once
/** @file
 * @brief Picking on a packed octree without materialising it: the leaf nearest a 3D point, and the
 *        first leaf along a ray within a radius that grows with distance (a pixel's footprint). Both are
 *        branch-and-bound descents that visit only cells whose box can still beat the best found
 *        (the bound uses the box of the centres of the target level under a cell, i.e. the cell's box
 *        shrunk by half a target cell, with a tiny tolerance so that rounding never prunes the answer).
 *
 * Centres are those of RootBox::cellCentre (the same as CellView::centre). Ties are broken so the
 * answer is unique and deterministic: nearestCell keeps, among centres at exactly the same distance,
 * the one with the smallest breadth-first index; pickRay keeps the smallest t, then (equal t) the
 * smallest index.
 * Units: metres. Thread-safety: reentrant, reads the octree only. Failure modes: none (an empty answer
 * when nothing qualifies); a level outside −1..depth, a zero or non-finite direction or a negative radius
 * are programmer errors (asserted).
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
 *        @p maxDistance (metres, inclusive; infinity: any; negative or NaN: none). Empty for an empty
 *        result.
 */
std::optional<PickedCell> nearestCell(const PackedOctree& octree, const std::array<double, 3>& point,
                                      double maxDistance, int level = -1);

/**
 * @brief The cell of @p level (−1: the leaf level), nearest the ray origin along the ray, whose centre
 *        c has t = (c − origin) · d̂ ≥ 0 and lies within radius(t) = @p radiusAtOrigin + t ·
 *        @p radiusPerMetre (inclusive) of the ray's line (d̂ = @p direction normalised; it need not be
 *        unit). Both radii ≥ 0. Empty if none.
 */
std::optional<PickedCell> pickRay(const PackedOctree& octree, const std::array<double, 3>& origin,
                                  const std::array<double, 3>& direction, double radiusAtOrigin,
                                  double radiusPerMetre, int level = -1);

} // namespace stylos::core::octree
