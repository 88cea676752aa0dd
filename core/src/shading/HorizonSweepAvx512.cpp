// The AVX-512 horizon kernel: the 16 lanes of a group in one register, the same operations as
// walkGroupScalar (HorizonSweep.cpp), so the same bits. Compiled for AVX-512F by function attribute
// and chosen at run time (groupKernel), so the library still runs on any x86-64.
#if defined(__GNUC__) && !defined(__clang__)
// GCC 12 warns about the _mm512_undefined_* placeholders inside its own intrinsics.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "HorizonSweep.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))

#include <immintrin.h>

#include <cmath>
#include <limits>

#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

#define STYLOS_AVX512 __attribute__((target("avx512f,avx512bw,avx512vl")))

namespace stylos::core::shading::detail {
namespace {

/** Metres between pixels whose keys differ by @p delta (HorizonSweep.h). */
STYLOS_AVX512 inline __m512 distance(__m512i delta, __m512 along, __m512 across)
{
    const __m512 steps = _mm512_cvtepi32_ps(_mm512_and_si512(delta, _mm512_set1_epi32(0xFFFF)));
    const __m512 moves = _mm512_cvtepi32_ps(_mm512_srli_epi32(delta, 16));
    return _mm512_add_ps(_mm512_mul_ps(steps, along), _mm512_mul_ps(moves, across));
}

/** The top of the stacks: the vertex and what the pop loop and the cache need of it. */
struct Top {
    __m512 height, slope, num, den;
    __m512i key, below, count;
};

/**
 * The kernel. Each lane's hull lives on a linked list: the pixel pushed at step s stores the step of the
 * vertex under it (the tangent) at [s][lane] of stacks.links, written for all 16 lanes at once; its
 * height is already in walk.heights, and its slope is computed again from both when needed. The top K vertices of every stack
 * are cached in registers (level 0 in the Top, level i ≥ 1 in ch[i] / cs[i] / ck[i]), so the pop loop
 * tests and shifts registers instead of gathering (gathers cost ~30 cycles each on microcode-mitigated
 * Xeons). A lane whose cache runs dry is refilled from the list.
 *
 * Latency: the 16 lanes of a step depend on the previous step, so the loop runs at the speed of its
 * dependency chain. Two things keep the division and the key decoding off it: the freshly pushed top
 * is tested as (h − h_top) · den ≥ num · run (its slope num / den is divided out in the background,
 * for when it moves down a level), and the distance to level 1 is decoded one round ahead.
 */
/** Steps ahead for the prefetches of the source and of the sum (a step takes ~50 ns). */
constexpr int kAhead = 8;

template <int K>
STYLOS_AVX512 void walkCached(const GroupWalk& walk, HullStacks& stacks)
{
    static_assert(K >= 2);
    std::uint16_t* links = stacks.links.data();
    const int n = walk.steps;
    if (n <= 0) return;
    const __m512i one = _mm512_set1_epi32(1), levels = _mm512_set1_epi32(K), none = _mm512_setzero_si512();
    const __m512 along = _mm512_set1_ps(walk.along), across = _mm512_set1_ps(walk.across);
    const __m512 zero = _mm512_setzero_ps(), unit = _mm512_set1_ps(1.0f);
    const bool sine = walk.value == HorizonValue::Sine, reverse = walk.reverse, fromSource = walk.fromSource;
    const WalkOutput output = walk.output;
    float* const heights = walk.heights;
    const std::int32_t* keys = walk.keys;
    float* const valuesOut = walk.values;
    const std::int64_t* offsets = walk.offsets;
    const auto source = reinterpret_cast<std::uintptr_t>(walk.source);
    const auto states = reinterpret_cast<std::uintptr_t>(walk.states);
    const auto sum = reinterpret_cast<std::uintptr_t>(walk.sum);
    const int ahead = reverse ? -kAhead : kAhead; // prefetch distance, in steps of the walk

    // Every level starts as the sentinel: height −∞, slope NaN (never popped).
    const __m512 low = _mm512_set1_ps(-std::numeric_limits<float>::infinity());
    const __m512 nan = _mm512_set1_ps(std::numeric_limits<float>::quiet_NaN());
    const __m512i sentinel = _mm512_set1_epi32((reverse ? -keys[n - 1] : keys[0]) - 1);
    Top top{low, nan, nan, unit, sentinel, sentinel, one};
    // A vertex's key gives its step: (sign · key − keys[0]) & 0xFFFF (HorizonSweep.h); the sentinel's
    // gives 65535 (forward) or n (reverse), both ≥ n.
    const std::int32_t sign = reverse ? -1 : 1, firstKey = keys[0];
    const __m512i firstKeys = _mm512_set1_epi32(firstKey), stepBits = _mm512_set1_epi32(0xFFFF);
    __m512 ch[K], cs[K];
    __m512i ck[K];
    for (int i = 1; i < K; ++i) {
        ch[i] = low;
        cs[i] = nan;
        ck[i] = sentinel;
    }

    for (int t = 0; t < n; ++t) {
        const int s = reverse ? n - 1 - t : t;
        const std::size_t row = std::size_t(s) * kGroupLanes;
        float* values = valuesOut + row;
        // Lane j of step s is element offsets[s] + j of the source layout; the lanes outside the grid
        // are masked, so the addresses are formed as integers (they may lie outside the arrays).
        const std::uintptr_t offset = std::uintptr_t(offsets[s]);
        if (unsigned(s + ahead) < unsigned(n)) {
            const std::uintptr_t next = std::uintptr_t(offsets[s + ahead]);
            if (fromSource) {
                _mm_prefetch(reinterpret_cast<const char*>(source + next * 4), _MM_HINT_T0);
                _mm_prefetch(reinterpret_cast<const char*>(source + next * 4 + 60), _MM_HINT_T0);
                if (states) _mm_prefetch(reinterpret_cast<const char*>(states + next), _MM_HINT_T0);
            }
            if (output != WalkOutput::Values) {
                _mm_prefetch(reinterpret_cast<const char*>(sum + next * 4), _MM_HINT_T0);
                _mm_prefetch(reinterpret_cast<const char*>(sum + next * 4 + 60), _MM_HINT_T0);
            }
        }
        __m512 h;
        __mmask16 valid;
        if (fromSource) {
            __mmask16 present = __mmask16(walk.inside[s]);
            if (states) {
                const __m128i state = _mm_maskz_loadu_epi8(present, reinterpret_cast<const void*>(states + offset));
                present = _mm_mask_cmpneq_epi8_mask(present, state, _mm_setzero_si128());
            }
            h = _mm512_maskz_loadu_ps(present, reinterpret_cast<const void*>(source + offset * 4));
            valid = _mm512_mask_cmp_ps_mask(present, h, h, _CMP_ORD_Q);
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

        __m512 run = distance(_mm512_sub_epi32(key, top.key), along, across);
        __m512 next = distance(_mm512_sub_epi32(key, ck[1]), along, across);
        __mmask16 pop = _mm512_mask_cmp_ps_mask(valid, _mm512_mul_ps(_mm512_sub_ps(h, top.height), top.den),
                                                _mm512_mul_ps(top.num, run), _CMP_GE_OQ);
        for (int round = 0; round < 2 || pop != 0; ++round) { // two rounds are the common case
            // Level 1 comes up, in slope form; the others follow.
            top.height = _mm512_mask_mov_ps(top.height, pop, ch[1]);
            top.slope = _mm512_mask_mov_ps(top.slope, pop, cs[1]);
            top.num = _mm512_mask_mov_ps(top.num, pop, cs[1]);
            top.den = _mm512_mask_mov_ps(top.den, pop, unit);
            top.key = _mm512_mask_mov_epi32(top.key, pop, ck[1]);
            run = _mm512_mask_mov_ps(run, pop, next);
#pragma GCC unroll 16
            for (int i = 1; i + 1 < K; ++i) {
                ch[i] = _mm512_mask_mov_ps(ch[i], pop, ch[i + 1]);
                cs[i] = _mm512_mask_mov_ps(cs[i], pop, cs[i + 1]);
                ck[i] = _mm512_mask_mov_epi32(ck[i], pop, ck[i + 1]);
            }
            next = distance(_mm512_sub_epi32(key, ck[1]), along, across);
            top.count = _mm512_mask_sub_epi32(top.count, pop, top.count, one);
            const __mmask16 dry = _mm512_mask_cmpeq_epi32_mask(pop, top.count, none);
            if (dry != 0) {
                // Rare (~1 % of the pixels), scalar, and inline: a call would clobber every register.
                // The vertex under the cache comes up with its slope computed again as at its push.
                alignas(64) float hs[kGroupLanes], ss[kGroupLanes];
                alignas(64) std::int32_t bs[kGroupLanes];
                _mm512_store_si512(bs, top.below);
                const __m512i vertex = top.below;
                for (unsigned bits = dry; bits != 0; bits &= bits - 1) {
                    const int j = __builtin_ctz(bits);
                    const std::int32_t key = bs[j];
                    const std::size_t at = std::size_t((sign * key - firstKey) & 0xFFFF) * kGroupLanes + std::size_t(j);
                    const float height = heights[at];
                    const unsigned link = links[at];
                    hs[j] = height;
                    if (link >= unsigned(n)) { // the first vertex: its tangent is the sentinel
                        ss[j] = std::numeric_limits<float>::quiet_NaN();
                        bs[j] = (reverse ? -keys[n - 1] : keys[0]) - 1;
                        continue;
                    }
                    const std::int32_t under = sign * keys[link];
                    const float below = heights[std::size_t(link) * kGroupLanes + std::size_t(j)];
                    const std::int32_t delta = key - under;
                    const float run = float(delta & 0xFFFF) * walk.along + float(delta >> 16) * walk.across;
                    const float rise = below - height, num = height - below;
                    const float hyp = std::sqrt(rise * rise + run * run);
                    const float inverse = 1.0f / (hyp * run);
                    ss[j] = num * hyp * inverse;
                    bs[j] = under;
                }
                top.height = _mm512_mask_load_ps(top.height, dry, hs);
                top.slope = _mm512_mask_load_ps(top.slope, dry, ss);
                top.num = _mm512_mask_mov_ps(top.num, dry, top.slope);
                top.den = _mm512_mask_mov_ps(top.den, dry, unit);
                top.key = _mm512_mask_mov_epi32(top.key, dry, vertex);
                top.below = _mm512_load_si512(bs);
                top.count = _mm512_mask_mov_epi32(top.count, dry, one);
                run = distance(_mm512_sub_epi32(key, top.key), along, across);
            }
            pop = _mm512_mask_cmp_ps_mask(pop, _mm512_mul_ps(_mm512_sub_ps(h, top.height), top.den),
                                          _mm512_mul_ps(top.num, run), _CMP_GE_OQ);
        }

        // top is now every lane's tangent.
        const __m512 rise = _mm512_sub_ps(top.height, h);
        const __m512 up = _mm512_max_ps(rise, zero);
        // One square root and one division serve both the sine and the pushed vertex's slope.
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

        // Push: record the pixel on its list, shift the caches down (evicting level K − 1 when full).
        const __m512 num = _mm512_sub_ps(h, top.height);
        const __m512 slope = _mm512_mul_ps(_mm512_mul_ps(num, hyp), inverse);
        const __m512i signed_ = reverse ? _mm512_sub_epi32(_mm512_setzero_si512(), top.key) : top.key;
        const __m512i link = _mm512_and_si512(_mm512_sub_epi32(signed_, firstKeys), stepBits);
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(links + row), _mm512_cvtepi32_epi16(link));
        const __mmask16 evict = _mm512_mask_cmpeq_epi32_mask(valid, top.count, levels);
        top.below = _mm512_mask_mov_epi32(top.below, evict, ck[K - 1]);
#pragma GCC unroll 16
        for (int i = K - 1; i > 1; --i) {
            ch[i] = _mm512_mask_mov_ps(ch[i], valid, ch[i - 1]);
            cs[i] = _mm512_mask_mov_ps(cs[i], valid, cs[i - 1]);
            ck[i] = _mm512_mask_mov_epi32(ck[i], valid, ck[i - 1]);
        }
        ch[1] = _mm512_mask_mov_ps(ch[1], valid, top.height);
        cs[1] = _mm512_mask_mov_ps(cs[1], valid, top.slope);
        ck[1] = _mm512_mask_mov_epi32(ck[1], valid, top.key);
        top.height = _mm512_mask_mov_ps(top.height, valid, h);
        top.slope = _mm512_mask_mov_ps(top.slope, valid, slope);
        top.num = _mm512_mask_mov_ps(top.num, valid, num);
        top.den = _mm512_mask_mov_ps(top.den, valid, run);
        top.key = _mm512_mask_mov_epi32(top.key, valid, key);
        top.count = _mm512_mask_min_epi32(top.count, valid, _mm512_add_epi32(top.count, one), levels);
    }
}

} // namespace

STYLOS_AVX512 void walkGroupAvx512(const GroupWalk& walk, HullStacks& stacks) { walkCached<6>(walk, stacks); }

} // namespace stylos::core::shading::detail

#endif
