#pragma once
// Internal to the skydome: the scalar parts that every horizon kernel (HorizonSweep.h) shares, so that
// the portable, AVX2 and AVX-512 kernels perform the same operations and return the same bits: the
// distance of two keys, the prefetches ahead of a walk, and the refill of a vector kernel's register
// cache from the hull's linked list. Header-only and always inlined: the vector kernels are compiled
// for their instruction sets by function attribute and must not call out of their loops.
#include "HorizonSweep.h"

#include <cmath>
#include <cstdint>
#include <limits>

// Same bits in every kernel: no contraction of a · b + c into a fused multiply-add, in this header's
// functions and in the kernel file that includes it (every kernel file includes this header first).
#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

#if defined(__GNUC__) || defined(__clang__)
#define STYLOS_KERNEL_INLINE __attribute__((always_inline)) inline
#else
#define STYLOS_KERNEL_INLINE inline
#endif

namespace stylos::core::shading::detail {

/** Steps ahead for the prefetches of the source and of the sum (a step takes ~50 ns). */
constexpr int kPrefetchAhead = 8;
/** Vertices a vector kernel's dry cache takes from the list at once. */
constexpr int kRefill = 3;

/** Metres between two pixels of a lane whose keys differ by @p delta ≥ 0 (HorizonSweep.h). */
STYLOS_KERNEL_INLINE float keyDistance(std::int32_t delta, float along, float across)
{
    const float steps = float(delta & 0xFFFF), moves = float(delta >> 16);
    return steps * along + moves * across;
}

/**
 * Prefetches the source (a forward walk) and the sum (the Sum* outputs) of the step kPrefetchAhead
 * steps after step @p s in the walk's order: each step is a new row, which the hardware prefetchers do
 * not follow. Addresses are formed as integers, never dereferenced (lanes may lie outside the arrays).
 */
STYLOS_KERNEL_INLINE void prefetchAhead(const GroupWalk& walk, int s)
{
#if defined(__GNUC__) || defined(__clang__)
    const int ahead = walk.reverse ? s - kPrefetchAhead : s + kPrefetchAhead;
    if (unsigned(ahead) >= unsigned(walk.steps)) return;
    const std::uintptr_t next = std::uintptr_t(walk.offsets[ahead]) * sizeof(float); // lanes 0 … 15: 1–2 lines
    const auto fetch = [next](const float* base) {
        const std::uintptr_t address = reinterpret_cast<std::uintptr_t>(base) + next;
        __builtin_prefetch(reinterpret_cast<const void*>(address));
        __builtin_prefetch(reinterpret_cast<const void*>(address + 60));
    };
    if (walk.fromSource) fetch(walk.source);
    if (walk.output != WalkOutput::Values) fetch(walk.sum);
#else
    (void)walk;
    (void)s;
#endif
}

/**
 * What a vector kernel needs to read its hulls' linked lists (HullStacks::links): a vertex's key gives
 * its step, (sign · key − firstKey) & 0xFFFF; the sentinel's key gives 65535 (forward) or n (reverse),
 * never a step.
 */
struct HullList {
    const float* heights;
    const std::uint16_t* links;
    const std::int32_t* keys;
    int steps;
    std::int32_t sign, firstKey, sentinel;
    float along, across;

    HullList(const GroupWalk& walk, const HullStacks& stacks)
        : heights(walk.heights), links(stacks.links.data()), keys(walk.keys), steps(walk.steps),
          sign(walk.reverse ? -1 : 1), firstKey(walk.keys[0]),
          sentinel((walk.reverse ? -walk.keys[walk.steps - 1] : walk.keys[0]) - 1), along(walk.along),
          across(walk.across)
    {
    }
};

/**
 * The slope of the edge from @p lower (the tangent, @p run metres ahead) up to @p height, as the
 * kernels compute it when they push a vertex: one square root and one division shared with the value
 * (HorizonSweep.h), no fused multiply-add.
 */
STYLOS_KERNEL_INLINE float edgeSlope(float lower, float height, float run)
{
    const float rise = lower - height, num = height - lower;
    const float hyp = std::sqrt(rise * rise + run * run);
    const float inverse = 1.0f / (hyp * run);
    return num * hyp * inverse;
}

/** Up to kRefill vertices of one lane's hull from the list, top first (refillLane). */
struct LaneRefill {
    float heights[kRefill], slopes[kRefill];
    std::int32_t keys[kRefill];
    std::int32_t below; ///< the key of the vertex under the last one taken
    int count;          ///< the levels taken, 1 … kRefill (those past the sentinel are copies of it)
};

/**
 * A vector kernel's lane @p lane (of the group) has popped every vertex of its register cache: up to
 * kRefill vertices from @p vertex (the key under the cache) down come up from the hull's linked list,
 * each slope computed again exactly as at its push. ~1 lane in 4 steps: scalar.
 */
STYLOS_KERNEL_INLINE LaneRefill refillLane(const HullList& list, std::size_t lane, std::int32_t vertex)
{
    constexpr float lowest = -std::numeric_limits<float>::infinity();
    const float none = std::numeric_limits<float>::quiet_NaN();
    LaneRefill taken;
    int level = 0;
    for (; level < kRefill; ++level) {
        taken.keys[level] = vertex;
        if (vertex == list.sentinel) {
            taken.heights[level] = lowest;
            taken.slopes[level] = none;
            ++level;
            break;
        }
        const std::size_t row = std::size_t((list.sign * vertex - list.firstKey) & 0xFFFF) * kGroupLanes;
        const float height = list.heights[row + lane];
        const unsigned link = list.links[row + lane];
        taken.heights[level] = height;
        if (link >= unsigned(list.steps)) { // the first vertex: its tangent is the sentinel
            taken.slopes[level] = none;
            vertex = list.sentinel;
            continue;
        }
        const std::int32_t under = list.sign * list.keys[link];
        const float lower = list.heights[std::size_t(link) * kGroupLanes + lane];
        taken.slopes[level] = edgeSlope(lower, height, keyDistance(vertex - under, list.along, list.across));
        vertex = under;
    }
    taken.below = vertex;
    taken.count = level;
    for (int l = level; l < kRefill; ++l) { // levels past the sentinel: never read, but defined
        taken.heights[l] = lowest;
        taken.slopes[l] = none;
        taken.keys[l] = list.sentinel;
    }
    return taken;
}

} // namespace stylos::core::shading::detail
