#pragma once
/** @file
 * @brief The 3D skydome (ambient occlusion) on the cells of one octree level (Duguet et al., VAST 2004,
 *        section 6, figures 12–13): for every cell, the fraction of the sky around its normal that is
 *        not hidden by other cells.
 *
 * The value, exactly: with directions d_k (Directions.h, each an equal solid angle), a cell with normal n
 * and weight w_k = [n·d_k > 0] (or n·d_k with cosineWeighted) gets Σ w_k · v_k / Σ w_k, where v_k ∈ [0, 1]
 * is its visibility from d_k; 0 when Σ w_k = 0 (no direction of the set in front of it). Visibility toward
 * d of the cell at c: nothing in the way along the ray c + t·d, t > 0 — where only cells more than
 * `bias` edges above the cell's tangent plane on that side count as occluders (a surface does not shadow
 * itself: an occluder at distance t along the ray lies t·(n·d) above the plane, so the tolerance along
 * the ray grows as bias / (n·d) toward grazing directions, the slope-scaled bias of shadow maps).
 *
 * Methods:
 *  - Slices (the paper's): per direction, the cells are swept slice by slice along the direction's main
 *    axis, from the sky inward, with a 2D occlusion mask (transmittance). The mask is kept in the light's
 *    frame — each mask cell is one ray through all slices —, so moving to the next slice costs nothing;
 *    a cell entering the mask at its slice's fractional offset splits its opacity by overlap area over
 *    the (at most 2×2 of the) 9 mask cells its square may cover, once, instead of resampling the whole
 *    mask every slice (which blurs a shadow like a binomial and costs the shadow's volume). Each cell
 *    reads T = 1 − o at its centre ray, then adds its opacity: T ← T · (1 − coverage · opacity).
 *    Self-shadowing: each mask cell remembers where its latest burst of writes began (one surface
 *    crossed) and T before it; a reader skips that burst when it began within (bias + ¾)·|d_m| / (n·d)
 *    slices. Sparse: 32×32 mask tiles allocated on first write, empty slices skipped: the cost grows
 *    with the occupied cells, not the cube (SliceKernel.h).
 *  - DepthMap: per direction, a shadow map of the cells projected across the direction (one pixel per
 *    cell edge), the cell nearest the sky per pixel; a cell is visible when none lies ahead of it beyond
 *    the slope-scaled bias. Binary visibility, two passes over the cells per direction.
 * Both are compared with a brute-force reference (ReferenceAo.h) in docs/benchmarks.md.
 *
 * Multithreaded over directions (each thread its own accumulators, directions dealt by a fixed stride):
 * the same thread count gives the same bits; another differs by float rounding at most (not at all for
 * DepthMap with uniform weights, whose sums are small integers). Progress: the fraction of directions done; cancel is checked between directions.
 * Thread-safety: reentrant. Failure modes: InvalidArgument (directions outside 1..65536, bias or receiverBias < 0),
 * Cancelled.
 */
#include "stylos/core/ao/AoCells.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <optional>
#include <string>
#include <vector>

namespace stylos::core::ao {

enum class AoMethod { Slices, DepthMap };

/** @brief "slices" or "depthmap". */
const char* aoMethodName(AoMethod method);
/** @brief The method of that name, or none. */
std::optional<AoMethod> aoMethodFromName(const std::string& name);

struct AoOptions {
    int directions = 256;
    AoMethod method = AoMethod::DepthMap;
    bool cosineWeighted = false;      ///< weight each direction by n·d (irradiance) instead of 1 (solid angle)
    bool upperHemisphere = false;     ///< only directions with z > 0 (the sky above the world's horizon), as PCV
    double bias = 1.0;                ///< cell edges above the tangent plane before a cell occludes
    /** With receivers off the cells (leaves): edges beyond the occluder cube's half-extent along the
     *  receiver's normal before a cell occludes it (measured best on generated drums: see the overload). */
    double receiverBias = 0.5;
    /** With receivers off the cells (leaves), DepthMap, all directions (not upperHemisphere): a probe
     *  of 32 directions spread over the sphere measures both sides of each receiver's tangent plane
     *  (d·n > 0 with n, d·n < 0 with −n), the receiver keeps the side that sees more and is measured on
     *  it over all directions — a normal estimated with the wrong sign (into the solid, whose inside sees
     *  almost nothing) reads as if it were right. Ignored otherwise. */
    bool twoSided = true;
    unsigned threads = 0;             ///< 0: hardware concurrency
};

/** @brief Whether receivers off the cells are measured on both sides (AoOptions::twoSided and its
 *         conditions: DepthMap, all directions). */
inline bool twoSidedApplies(const AoOptions& options)
{
    return options.twoSided && !options.upperHemisphere && options.method == AoMethod::DepthMap;
}

/** @brief Per-cell values in [0, 1], in the order of @p cells. */
Result<std::vector<float>> computeAmbientOcclusion(const AoCells& cells, const AoOptions& options,
                                                   ProgressSink* progress = nullptr);

/**
 * @brief Per-receiver values in [0, 1], in the order of @p receivers (e.g. leafReceivers: the leaves),
 *        with @p occluders' cells as the only occluders (DepthMap only). A receiver at any point of its
 *        cell, with its own normal n, is hidden toward d by the cell the depth map holds on its line when
 *        that cell lies ahead and its centre is more than ½(|nx| + |ny| + |nz|) + receiverBias edges above the
 *        receiver's tangent plane — the farthest a cube that the plane cuts can reach, plus bias: a
 *        receiver never shadows itself on an open face of any slope. Failure modes: as above, and
 *        InvalidArgument for the Slices method.
 */
Result<std::vector<float>> computeAmbientOcclusion(const AoCells& occluders, const AoReceivers& receivers,
                                                   const AoOptions& options, ProgressSink* progress = nullptr);

} // namespace stylos::core::ao
