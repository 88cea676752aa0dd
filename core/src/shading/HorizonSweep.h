#pragma once
// Internal to the skydome: the linear-time horizon of every pixel of 16 rasterised lines walked together.
#include "stylos/core/shading/SkydomeKernel.h"

#include <cstdint>
#include <vector>

namespace stylos::core::shading::detail {

/** Lines walked together by one kernel call (one AVX-512 register of floats, two AVX2 ones). */
constexpr int kGroupLanes = 16;

/**
 * What the kernel computes per pixel p with horizon slope s = rise / run ≥ 0 (0 with no occluder). With
 * hyp = √(rise² + run²) and inverse = 1 / (hyp · run), one division serves the sine and the slope of
 * the vertex pushed (num · hyp · inverse): a few float ulps from the exact quotients.
 */
enum class HorizonValue {
    Sine,  ///< sin θ = s / √(1 + s²), computed as rise · run · inverse
    Slope, ///< tan θ = s, computed as rise / run (horizonAngles: speed matters less)
};

/** Where a walk puts its values. */
enum class WalkOutput {
    Values,          ///< write them to values (0 where there is no pixel)
    SumWithValues,   ///< sum[pixel] += values[step][lane] + value (the two walks of opposite azimuths)
    Sum,             ///< sum[pixel] += value
};

/**
 * One walk of a group of 16 neighbouring lines of a raster, step by step (a step: one major index).
 *
 * Pixels. Lane j of step s is the element offsets[s] + j of the source layout (of source and sum),
 * where bit j of inside[s] is set; a walk fromSource reads them there (NaN = Empty) and writes the
 * group's heights (NaN = no pixel) to heights, which any other walk reads instead.
 *
 * Positions: a step's key is u · 65536 + s, s the step index and u the number of minor-axis moves
 * since the first step (both counted along the first step → last step order, so both grow). The
 * distance between two pixels of a line (metres) is Δs · along + Δu · across, Δs and Δu read from the
 * difference of their keys: exact integers, so the distance is correct to a few float ulps whatever
 * the size of the field. Walking in reverse negates the keys, which keeps both differences ≥ 0.
 */
struct GroupWalk {
    const float* source = nullptr;         ///< heights, metres (NaN = Empty), in the source layout
    const std::int64_t* offsets = nullptr; ///< per step: element of lane 0 (lanes outside may not exist)
    const std::uint16_t* inside = nullptr; ///< per step: the lanes inside the grid
    float* heights = nullptr;              ///< steps × 16 (lane fastest)
    float* values = nullptr;               ///< steps × 16
    float* sum = nullptr;                  ///< source layout, for WalkOutput::Sum*
    const std::int32_t* keys = nullptr;    ///< one per step (see above)
    int steps = 0;
    bool reverse = false;    ///< walk from the last step to the first (the opposite azimuth)
    bool fromSource = false; ///< read the pixels from the source (and fill heights) rather than heights
    WalkOutput output = WalkOutput::Values;
    HorizonValue value = HorizonValue::Sine;
    float along = 1.0f;  ///< metres per step
    float across = 0.0f; ///< metres per minor-axis move
};

/**
 * Scratch of one worker. The portable kernel keeps the 16 hull stacks level by level (level k of lane j
 * at k · 16 + j: heights, slopes, keys); the vector kernel keeps the top of each stack in registers and
 * the rest as a linked list: links[s · 16 + j] is the step of the vertex under the one pushed at step s
 * (≥ steps for the sentinel).
 */
struct HullStacks {
    std::vector<float> heights, slopes;
    std::vector<std::int32_t> keys;
    std::vector<std::uint16_t> links;
    /** Room for the sentinel and every step of a walk of up to @p steps. */
    explicit HullStacks(int steps)
        : heights(std::size_t(steps + 2) * kGroupLanes), slopes(heights.size()), keys(heights.size()),
          links(heights.size())
    {
    }
};

/**
 * @brief For every lane of every step that holds a pixel p, the HorizonValue of the largest slope
 *        (h_q − h_p) / dist(p, q) over the pixels q of the lane that the walk visited before p (0 when
 *        none is higher than p), delivered as walk.output says.
 *
 * Per lane, a stack keeps the upper convex hull of the points visited (distance along the walk,
 * height). The highest slope from p to the hull is at the tangent vertex; the vertices above it on the
 * stack (nearer p) lie under the segment from p to the tangent and leave the hull when p joins it, so
 * one pop loop both finds the tangent and restores convexity: amortised O(1) per pixel. A vertex v
 * leaves when p is on or above the line of its incoming edge, h_p − h_v ≥ slope_v · dist(p, v): one
 * vertex read per test. The sentinel at the bottom (height −∞, slope NaN) and the first real vertex
 * (slope +∞ or NaN) are never popped.
 *
 * Arithmetic: float, with differences of heights and exact integer step counts, so rounding is
 * relative to the local rise and run (~1e-7), never to the size of the heights or of the field. No
 * fused multiply-add: every kernel performs the same operations in the same order and returns the same
 * bits.
 */
using GroupKernel = void (*)(const GroupWalk& walk, HullStacks& stacks);

/** Portable kernel: the lanes one after the other at each step. */
void walkGroupScalar(const GroupWalk& walk, HullStacks& stacks);

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define STYLOS_HORIZON_X86_KERNELS 1
/** AVX2 kernel (HorizonSweepAvx2.cpp): only on a CPU with AVX2. */
void walkGroupAvx2(const GroupWalk& walk, HullStacks& stacks);
/** AVX-512 kernel (HorizonSweepAvx512.cpp): only on a CPU with AVX-512F. */
void walkGroupAvx512(const GroupWalk& walk, HullStacks& stacks);
#endif

/** The kernel for @p kernel, resolved first (resolveSkydomeKernel: not Auto, and available). */
GroupKernel groupKernel(SkydomeKernel kernel);

} // namespace stylos::core::shading::detail
