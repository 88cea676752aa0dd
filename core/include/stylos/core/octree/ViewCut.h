#pragma once
/** @file
 * @brief The view-dependent level-of-detail cut of a packed octree: starting at the root, cells are
 *        refined (replaced by their children) while they project larger than a pixel threshold,
 *        largest projection first (among cells of one size: nearest the eye first), until the point
 *        budget is reached; cells outside the view frustum are dropped. The result is a list of cells
 *        (centre, size, normal, level and index) ready to be drawn as splats; nothing else of the tree
 *        is materialised.
 *
 * Projected size of a cell = size · pixelsPerRadian / distance from the eye to the cell's centre (a
 * perspective camera; for an orthographic one, size · pixelsPerMetre); a cell whose closed box holds
 * the eye projects infinitely large. The cut never holds more than `pointBudget` cells: a refinement
 * that would exceed it is not made, so the budget goes to the cells that look largest.
 *
 * The algorithm, exactly (tests rely on it):
 *  1. A cell is *visible* unless its box lies entirely outside one of the six frustum planes
 *     (`cullToFrustum`; conservative: a cell that touches or crosses the frustum is never dropped).
 *     The root is the first cell looked at; if it is not visible the cut is empty.
 *  2. A visible cell is a *candidate* when its projected size is > `pixelThreshold` and its level is
 *     < maxLevel; any other visible cell goes to the cut as soon as it is looked at.
 *  3. Candidates wait in a priority queue ordered by projected size (largest first), then distance
 *     from the eye to the centre (nearest first), then level, then index (smallest first), so the
 *     order is a total order and the cut deterministic. The first candidate is taken out; with n its
 *     visible children and C the number of cells in the cut and in the queue (itself included), it
 *     is refined if C − 1 + n ≤ pointBudget (its visible children are then looked at, step 2);
 *     otherwise it goes to the cut (and `budgetReached` is set). Repeat until the queue is empty.
 *     A candidate refused for the budget does not stop the others: a later one with fewer visible
 *     children may still fit.
 *  So every leaf under a visible cell has exactly one ancestor-or-self in the cut unless a cell on its
 *  way was culled, and the cut is the whole visible leaf level when the budget and threshold allow.
 *
 * Distances and centres are computed relative to the root box origin, in double.
 *
 * Order of `cells`: unspecified but deterministic (the same octree, camera and options give the same
 * list). Cost: O(cells looked at · log(queue)) while the budget lasts; once no cell of the budget is
 * left, the remaining candidates are settled in one linear pass (the same result as step 3, see
 * ViewCut.cpp). Memory: the queue (at most min(pointBudget, inner cells) entries of 32 bytes) and
 * the result (40 bytes per cell). Measured (ViewCutBenchmark in tests/core/ViewCutTest.cpp): a 1 M-cell
 * cut of a 30 M-point drum octree (depth 13, 28 M leaves) in 0.21 s (best of 5) on the 2-core dev
 * machine; opening the file took 0.05 s (in the page cache).
 *
 * Units: metres, pixels. Thread-safety: reentrant, reads the octree only. Failure modes: none; a
 * pointBudget of 0, a non-positive pixelsPerRadian / pixelsPerMetre or a maxLevel below −1 are
 * programmer errors (asserted; in release builds a budget of 0 counts as 1 and a negative maxLevel
 * as −1).
 */
#include "stylos/core/octree/PackedOctree.h"

#include <array>
#include <cstdint>
#include <vector>

namespace stylos::core::octree {

/** @brief A camera as the cut needs it. */
struct CutCamera {
    std::array<double, 3> eye{0, 0, 0};   ///< metres, in the octree's (world) frame
    /**
     * Column-major 4×4 view-projection matrix (OpenGL convention, clip = M · (x, y, z, 1), x, y, z in
     * the world frame); used for frustum culling when `cullToFrustum` is set.
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
    int maxLevel = -1;                    ///< deepest level to refine to; −1 (or more than the depth): the depth
};

/** @brief One drawable cell of a cut. */
struct CutCell {
    std::array<float, 3> centre{};     ///< metres, relative to the root box origin (float for GL)
    float size = 0;                    ///< edge, metres
    std::array<float, 3> normal{};     ///< unit
    std::int32_t level = 0;
    std::uint64_t index = 0;           ///< breadth-first index within its level
};

struct CutResult {
    std::vector<CutCell> cells;
    std::uint64_t refinements = 0;     ///< cells replaced by their children
    bool budgetReached = false;        ///< some candidate was left unrefined because of the budget
    int deepestLevel = 0;              ///< deepest level in the cut (0 when the cut is empty)
};

/** @brief Computes the cut for @p camera (see the file comment for the exact rules). */
CutResult computeViewCut(const PackedOctree& octree, const CutCamera& camera, const CutOptions& options);

} // namespace stylos::core::octree
