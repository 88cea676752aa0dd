#pragma once
/** @file
 * @brief Which cells of which fragments the 3D view draws for a camera: the multi-fragment level-of-detail
 *        cut under one shared point budget, and its splats. The pure computation behind the widgets'
 *        LodScheduler, which decides when to run it (in the background) and delivers the result.
 *
 * Two modes. **Budget** (the default): per fragment the view-dependent cut (core::octree::computeViewCut:
 * refine while a cell projects larger than the pixel threshold), the budget shared among the visible
 * fragments (shareBudget) in proportion to the cells each needs at the threshold — the cell count of the
 * level whose cells project to about the threshold, 0 when its root box is outside the view — capped by
 * its leaf count; then one more round gives what fragments satisfied below their share left unused (when
 * more than 5 % of the budget) to those that reached theirs. **GlobalLevel**: the paper's level slider,
 * every cell of one level of every fragment (clamped to each depth; no culling; the budget still caps it).
 *
 * Units: metres, pixels (the camera's viewport), points (cells). Thread-safety: computeSceneCut and
 * cutCameraFor are pure functions of their arguments, reentrant; they read the shared octrees only.
 * Failure modes: none; a fragment without an octree, hidden or out of view gets an empty cut (its
 * FragmentCut is still there, with its id); a budget of 0 gives empty cuts.
 */
#include "stylos/core/octree/ViewCut.h"
#include "stylos/core/view/Camera.h"
#include "stylos/core/view/SplatBuffer.h"
#include "stylos/core/view/ViewFragment.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace stylos::core::view {

enum class CutMode { Budget, GlobalLevel };

/** @brief What a cut depends on besides the fragments, the camera and the budget. */
struct CutSettings {
    CutMode mode = CutMode::Budget;
    double pixelThreshold = 1.0;   ///< refine while a cell projects larger than this, pixels
    int globalLevel = 8;           ///< GlobalLevel mode: the level drawn (clamped to each depth)
};

/** @brief One fragment's cut, as splats. */
struct FragmentCut {
    std::uint64_t id = 0;
    SplatBuffer splats;
};

/** @brief The cuts of one computation, one per fragment given, in the same order. */
struct SceneCut {
    std::vector<FragmentCut> fragments;
    std::uint64_t budget = 0;      ///< the budget it was computed for
    std::uint64_t cells = 0;       ///< cells in all cuts
    bool motion = false;           ///< a cut made while the camera moved (set by the scheduler)
    bool budgetReached = false;    ///< some cut stopped at its share of the budget
    bool final = false;            ///< the last refinement stage for this view (set by the scheduler)
    double seconds = 0;            ///< time the computation took (steady clock)
};

/** @brief The core cut camera for @p camera, in the frame of an octree placed by @p pose (octree → scene). */
octree::CutCamera cutCameraFor(const Camera& camera, const Eigen::Matrix4d& pose);

/**
 * @brief The cuts of @p fragments for @p camera under @p budget points in all, as the file comment says;
 *        each fragment's splats are shuffled with the seed id + 1.
 */
SceneCut computeSceneCut(const std::vector<ViewFragment>& fragments, const Camera& camera,
                         const CutSettings& settings, std::uint64_t budget);

} // namespace stylos::core::view
