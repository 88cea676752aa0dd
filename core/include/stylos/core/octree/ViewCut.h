#pragma once
/** @file
 * @brief The view-dependent level-of-detail cut of a packed octree: starting at the root, cells are
 *        refined (replaced by their children) while they project larger than a pixel threshold,
 *        largest projection first (among cells of one size: nearest the eye first), until the point
 *        budget is reached; cells outside the view frustum are dropped. The result is a list of cells (centre, size, normal, leaf index when a leaf) ready to be
 *        drawn as splats; nothing else of the tree is materialised.
 *
 * Projected size of a cell = size · pixelsPerRadian / distance from the eye to the cell's centre (a
 * perspective camera; for an orthographic one, size · pixelsPerMetre). The cut never holds more than
 * `pointBudget` cells: a refinement that would exceed it is not made, so the budget goes to the cells
 * that look largest. Units: metres, pixels. Thread-safety: reentrant, reads the octree only.
 */
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/Progress.h"

#include <array>
#include <cstdint>
#include <vector>

namespace stylos::core::octree {

/** @brief A camera as the cut needs it. */
struct CutCamera {
    std::array<double, 3> eye{0, 0, 0};
    /**
     * Column-major 4×4 view-projection matrix (OpenGL convention, clip = M · (x, y, z, 1)); used for
     * frustum culling when `cullToFrustum` is set.
     */
    std::array<double, 16> viewProjection{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    bool cullToFrustum = true;
    bool orthographic = false;
    double pixelsPerRadian = 1000;   ///< perspective: viewport height / vertical field of view
    double pixelsPerMetre = 1000;    ///< orthographic: viewport height / view height
};

struct CutOptions {
    double pixelThreshold = 1.0;          ///< refine while the projected size exceeds this, pixels
    std::uint64_t pointBudget = 1'000'000; ///< most cells in the cut (≥ 1)
    int maxLevel = -1;                    ///< deepest level to refine to; -1: the octree's depth
};

/** @brief One drawable cell of a cut. */
struct CutCell {
    std::array<float, 3> centre{};     ///< metres, relative to the root box origin (float for GL)
    float size = 0;                    ///< edge, metres
    std::array<float, 3> normal{};
    std::int32_t level = 0;
    std::uint64_t index = 0;           ///< breadth-first index within its level
};

struct CutResult {
    std::vector<CutCell> cells;
    std::uint64_t refinements = 0;     ///< cells replaced by their children
    bool budgetReached = false;        ///< stopped by the budget before the threshold was met everywhere
    int deepestLevel = 0;
};

/** @brief Computes the cut for @p camera. */
CutResult computeViewCut(const PackedOctree& octree, const CutCamera& camera, const CutOptions& options);

} // namespace stylos::core::octree
