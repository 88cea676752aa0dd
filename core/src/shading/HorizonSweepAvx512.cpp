// The AVX-512 horizon kernel: the 16 lanes of a group in one register, the same operations as
// walkGroupScalar (HorizonSweep.cpp), so the same bits. Compiled for AVX-512F by function attribute
// and chosen at run time (groupKernel), so the library still runs on any x86-64.
#if defined(__GNUC__) && !defined(__clang__)
// GCC 12 warns about the _mm512_undefined_* placeholders inside its own intrinsics.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "HorizonKernelParts.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))

#include <immintrin.h>

#include <cmath>
#include <limits>

#define STYLOS_AVX512 __attribute__((target("avx512f")))
#define STYLOS_AVX512_INLINE __attribute__((target("avx512f"), always_inline)) inline

namespace stylos::core::shading::detail {
namespace {

/** Levels of each stack cached in registers (6: ~0.25 refills per step of 16 pixels, 3 levels each). */
constexpr int kLevels = 6;

/** Metres between pixels whose keys differ by @p delta (HorizonSweep.h). */
STYLOS_AVX512_INLINE __m512 distance(__m512i delta, __m512 along, __m512 across)
{
    const __m512 steps = _mm512_cvtepi32_ps(_mm512_and_si512(delta, _mm512_set1_epi32(0xFFFF)));
    const __m512 moves = _mm512_cvtepi32_ps(_mm512_srli_epi32(delta, 16));
    return _mm512_add_ps(_mm512_mul_ps(steps, along), _mm512_mul_ps(moves, across));
}

/**
 * The top kLevels vertices of the 16 stacks (level 0 = top): height, slope of the incoming edge and
 * key; per lane, how many levels hold vertices (count) and the key of the vertex under the deepest
 * one (below). Lives in registers: always used through inlined functions.
 */
struct Cache {
    __m512 height[kLevels], slope[kLevels];
    __m512i key[kLevels];
    __m512i below, count;
};

/**
 * Lanes @p dry have popped every cached vertex: up to kRefill vertices under the cache come up from the
 * list (refillLane). Inline: a call would make the compiler keep the whole cache in memory.
 */
STYLOS_AVX512_INLINE void refill(Cache& cache, __mmask16 dry, const HullList& list)
{
    alignas(64) float heights[kRefill][kGroupLanes], slopes[kRefill][kGroupLanes];
    alignas(64) std::int32_t keys[kRefill][kGroupLanes], below[kGroupLanes], counts[kGroupLanes];
    _mm512_store_si512(below, cache.below);
    for (unsigned bits = dry; bits != 0; bits &= bits - 1) {
        const int j = __builtin_ctz(bits);
        const LaneRefill taken = refillLane(list, std::size_t(j), below[j]);
        for (int l = 0; l < kRefill; ++l) {
            heights[l][j] = taken.heights[l];
            slopes[l][j] = taken.slopes[l];
            keys[l][j] = taken.keys[l];
        }
        below[j] = taken.below;
        counts[j] = taken.count;
    }
    for (int l = 0; l < kRefill; ++l) {
        cache.height[l] = _mm512_mask_load_ps(cache.height[l], dry, heights[l]);
        cache.slope[l] = _mm512_mask_load_ps(cache.slope[l], dry, slopes[l]);
        cache.key[l] = _mm512_mask_load_epi32(cache.key[l], dry, keys[l]);
    }
    cache.below = _mm512_load_si512(below);
    cache.count = _mm512_mask_load_epi32(cache.count, dry, counts);
}

/** Lanes @p pop drop their top vertex: every level moves up one. */
STYLOS_AVX512_INLINE void popTop(Cache& cache, __mmask16 pop)
{
#pragma GCC unroll 16
    for (int i = 0; i + 1 < kLevels; ++i) {
        cache.height[i] = _mm512_mask_mov_ps(cache.height[i], pop, cache.height[i + 1]);
        cache.slope[i] = _mm512_mask_mov_ps(cache.slope[i], pop, cache.slope[i + 1]);
        cache.key[i] = _mm512_mask_mov_epi32(cache.key[i], pop, cache.key[i + 1]);
    }
    cache.count = _mm512_mask_sub_epi32(cache.count, pop, cache.count, _mm512_set1_epi32(1));
}

/** Lanes @p valid push a vertex: every level moves down one, the deepest leaving when the cache is full. */
STYLOS_AVX512_INLINE void push(Cache& cache, __mmask16 valid, __m512 height, __m512 slope, __m512i key)
{
    const __m512i levels = _mm512_set1_epi32(kLevels);
    const __mmask16 evict = _mm512_mask_cmpeq_epi32_mask(valid, cache.count, levels);
    cache.below = _mm512_mask_mov_epi32(cache.below, evict, cache.key[kLevels - 1]);
#pragma GCC unroll 16
    for (int i = kLevels - 1; i > 0; --i) {
        cache.height[i] = _mm512_mask_mov_ps(cache.height[i], valid, cache.height[i - 1]);
        cache.slope[i] = _mm512_mask_mov_ps(cache.slope[i], valid, cache.slope[i - 1]);
        cache.key[i] = _mm512_mask_mov_epi32(cache.key[i], valid, cache.key[i - 1]);
    }
    cache.height[0] = _mm512_mask_mov_ps(cache.height[0], valid, height);
    cache.slope[0] = _mm512_mask_mov_ps(cache.slope[0], valid, slope);
    cache.key[0] = _mm512_mask_mov_epi32(cache.key[0], valid, key);
    const __m512i more = _mm512_add_epi32(cache.count, _mm512_set1_epi32(1));
    cache.count = _mm512_mask_min_epi32(cache.count, valid, more, levels);
}

/**
 * The kernel. Each lane's hull lives on a linked list: the pixel pushed at step s stores the step of
 * the vertex under it (its tangent) at stacks.links[s · 16 + lane], written for the 16 lanes at once;
 * its height is in walk.heights, and its slope is computed again from both when needed. The top
 * kLevels vertices of every stack are cached in registers, so the pop loop tests and shifts registers
 * instead of gathering (a gather costs ~30 cycles on microcode-mitigated Xeons, more than the shifts).
 * The loop runs max over the 16 lanes of (pops + 1) rounds per step, two or three in practice.
 */
STYLOS_AVX512 void walkCached(const GroupWalk& walk, HullStacks& stacks)
{
    const int n = walk.steps;
    if (n <= 0) return;
    std::uint16_t* const links = stacks.links.data();
    const bool sine = walk.value == HorizonValue::Sine, reverse = walk.reverse, fromSource = walk.fromSource;
    const WalkOutput output = walk.output;
    float* const heights = walk.heights;
    const std::int32_t* const keys = walk.keys;
    const std::int64_t* const offsets = walk.offsets;
    const auto source = reinterpret_cast<std::uintptr_t>(walk.source);
    const auto sum = reinterpret_cast<std::uintptr_t>(walk.sum);
    const __m512 along = _mm512_set1_ps(walk.along), across = _mm512_set1_ps(walk.across);
    const __m512 zero = _mm512_setzero_ps(), unit = _mm512_set1_ps(1.0f);
    const __m512 nan = _mm512_set1_ps(std::numeric_limits<float>::quiet_NaN());
    const HullList list(walk, stacks);
    const __m512i firstKeys = _mm512_set1_epi32(list.firstKey), stepBits = _mm512_set1_epi32(0xFFFF);

    // Every level starts as the sentinel: height −∞, slope NaN (never popped), one level held.
    Cache cache;
    for (int i = 0; i < kLevels; ++i) {
        cache.height[i] = _mm512_set1_ps(-std::numeric_limits<float>::infinity());
        cache.slope[i] = nan;
        cache.key[i] = _mm512_set1_epi32(list.sentinel);
    }
    cache.below = cache.key[0];
    cache.count = _mm512_set1_epi32(1);

    for (int t = 0; t < n; ++t) {
        const int s = reverse ? n - 1 - t : t;
        const std::size_t row = std::size_t(s) * kGroupLanes;
        float* values = walk.values + row;
        // Lane j of step s is element offsets[s] + j of the source layout; the lanes outside the grid
        // are masked, so the addresses are formed as integers (they may lie outside the arrays).
        const std::uintptr_t offset = std::uintptr_t(offsets[s]);
        prefetchAhead(walk, s);
        __m512 h;
        __mmask16 valid;
        if (fromSource) {
            const __mmask16 inside = __mmask16(walk.inside[s]);
            h = _mm512_maskz_loadu_ps(inside, reinterpret_cast<const void*>(source + offset * 4));
            valid = _mm512_mask_cmp_ps_mask(inside, h, h, _CMP_ORD_Q);
            h = _mm512_mask_mov_ps(nan, valid, h);
            _mm512_storeu_ps(heights + row, h);
        } else {
            h = _mm512_loadu_ps(heights + row);
            valid = _mm512_cmp_ps_mask(h, h, _CMP_ORD_Q);
        }
        if (valid == 0) {
            if (output == WalkOutput::Values) _mm512_storeu_ps(values, zero);
            continue;
        }
        const __m512i key = _mm512_set1_epi32(reverse ? -keys[s] : keys[s]);

        // Pop: test the top, bring the next level up, until no lane pops. The distance to level 1 is
        // decoded a round ahead.
        __m512 run = distance(_mm512_sub_epi32(key, cache.key[0]), along, across);
        __m512 next = distance(_mm512_sub_epi32(key, cache.key[1]), along, across);
        __mmask16 pop = _mm512_mask_cmp_ps_mask(valid, _mm512_sub_ps(h, cache.height[0]),
                                                _mm512_mul_ps(cache.slope[0], run), _CMP_GE_OQ);
        for (int round = 0; round < 2 || pop != 0; ++round) { // two rounds are the common case
            popTop(cache, pop);
            run = _mm512_mask_mov_ps(run, pop, next);
            next = distance(_mm512_sub_epi32(key, cache.key[1]), along, across);
            const __mmask16 dry = _mm512_mask_cmpeq_epi32_mask(pop, cache.count, _mm512_setzero_si512());
            if (dry != 0) {
                refill(cache, dry, list);
                run = distance(_mm512_sub_epi32(key, cache.key[0]), along, across);
                next = distance(_mm512_sub_epi32(key, cache.key[1]), along, across);
            }
            pop = _mm512_mask_cmp_ps_mask(pop, _mm512_sub_ps(h, cache.height[0]), _mm512_mul_ps(cache.slope[0], run),
                                          _CMP_GE_OQ);
        }

        // Level 0 is every lane's tangent. One square root and one division serve both the sine and
        // the slope of the vertex pushed.
        const __m512 rise = _mm512_sub_ps(cache.height[0], h);
        const __m512 up = _mm512_max_ps(rise, zero);
        const __m512 hyp = _mm512_sqrt_ps(_mm512_add_ps(_mm512_mul_ps(rise, rise), _mm512_mul_ps(run, run)));
        const __m512 inverse = _mm512_div_ps(unit, _mm512_mul_ps(hyp, run));
        const __m512 value = sine ? _mm512_mul_ps(_mm512_mul_ps(up, run), inverse) : _mm512_div_ps(up, run);
        if (output == WalkOutput::Values) {
            _mm512_storeu_ps(values, _mm512_maskz_mov_ps(valid, value));
        } else {
            float* cell = reinterpret_cast<float*>(sum + offset * 4);
            const __m512 total = output == WalkOutput::Sum ? value : _mm512_add_ps(_mm512_loadu_ps(values), value);
            _mm512_mask_storeu_ps(cell, valid, _mm512_add_ps(_mm512_maskz_loadu_ps(valid, cell), total));
        }

        // Push: the pixel's link is its tangent's step.
        const __m512i tangent = reverse ? _mm512_sub_epi32(_mm512_setzero_si512(), cache.key[0]) : cache.key[0];
        const __m512i link = _mm512_and_si512(_mm512_sub_epi32(tangent, firstKeys), stepBits);
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(links + row), _mm512_cvtepi32_epi16(link));
        const __m512 slope = _mm512_mul_ps(_mm512_mul_ps(_mm512_sub_ps(h, cache.height[0]), hyp), inverse);
        push(cache, valid, h, slope, key);
    }
}

} // namespace

STYLOS_AVX512 void walkGroupAvx512(const GroupWalk& walk, HullStacks& stacks) { walkCached(walk, stacks); }

} // namespace stylos::core::shading::detail

#endif
