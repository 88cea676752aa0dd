// The AVX2 horizon kernel: the 16 lanes of a group walked as two halves of 8, each in one AVX2
// register, with the same operations as walkGroupScalar (HorizonSweep.cpp), so the same bits.
// Compiled for AVX2 by function attribute, without FMA (the portable kernel has none), and chosen at
// run time (SkydomeKernel.cpp), so the library still runs on any x86-64.
#include "HorizonKernelParts.h"

#if STYLOS_HORIZON_X86_KERNELS

#include <immintrin.h>

#include <limits>

#define STYLOS_AVX2 __attribute__((target("avx2")))
#define STYLOS_AVX2_INLINE __attribute__((target("avx2"), always_inline)) inline

namespace stylos::core::shading::detail {
namespace {

/** Lanes per register, half a group. */
constexpr int kWidth = 8;
/**
 * Levels of each stack cached in registers. AVX2 has 16 registers, not AVX-512's 32: with 4 levels
 * (12 registers) the compiler keeps part of the cache on the stack (L1); 3 levels measured ~10 %
 * slower (more refills), 5 and 6 within the noise (docs/benchmarks.md).
 */
constexpr int kLevels = 4;

/** Masks are vectors of 0 / all-ones lanes (AVX2 has no mask registers). */
STYLOS_AVX2_INLINE __m256 select(__m256 no, __m256 yes, __m256 mask)
{
    return _mm256_blendv_ps(no, yes, mask);
}

STYLOS_AVX2_INLINE __m256i select(__m256i no, __m256i yes, __m256 mask)
{
    return _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(no), _mm256_castsi256_ps(yes), mask));
}

STYLOS_AVX2_INLINE __m256 asMask(__m256i lanes)
{
    return _mm256_castsi256_ps(lanes);
}

/** Metres between pixels whose keys differ by @p delta (HorizonSweep.h). */
STYLOS_AVX2_INLINE __m256 distance(__m256i delta, __m256 along, __m256 across)
{
    const __m256 steps = _mm256_cvtepi32_ps(_mm256_and_si256(delta, _mm256_set1_epi32(0xFFFF)));
    const __m256 moves = _mm256_cvtepi32_ps(_mm256_srli_epi32(delta, 16));
    return _mm256_add_ps(_mm256_mul_ps(steps, along), _mm256_mul_ps(moves, across));
}

/** The top kLevels vertices of 8 stacks, as in the AVX-512 kernel (HorizonSweepAvx512.cpp). */
struct Cache {
    __m256 height[kLevels], slope[kLevels];
    __m256i key[kLevels];
    __m256i below, count;
};

/**
 * Lanes @p dry take up to kRefill vertices from the list (refillLane), each value broadcast and blended
 * into its lane: no round trip through memory, whose narrow stores a wide load cannot forward.
 */
STYLOS_AVX2_INLINE void refill(Cache& cache, unsigned dry, const HullList& list, int first)
{
    alignas(32) std::int32_t below[kWidth];
    _mm256_store_si256(reinterpret_cast<__m256i*>(below), cache.below);
    const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (unsigned bits = dry; bits != 0; bits &= bits - 1) {
        const int j = __builtin_ctz(bits);
        const LaneRefill taken = refillLane(list, std::size_t(first + j), below[j]);
        const __m256 lane = asMask(_mm256_cmpeq_epi32(lanes, _mm256_set1_epi32(j)));
        for (int l = 0; l < kRefill; ++l) {
            cache.height[l] = select(cache.height[l], _mm256_set1_ps(taken.heights[l]), lane);
            cache.slope[l] = select(cache.slope[l], _mm256_set1_ps(taken.slopes[l]), lane);
            cache.key[l] = select(cache.key[l], _mm256_set1_epi32(taken.keys[l]), lane);
        }
        cache.below = select(cache.below, _mm256_set1_epi32(taken.below), lane);
        cache.count = select(cache.count, _mm256_set1_epi32(taken.count), lane);
    }
}

/** Lanes @p pop drop their top vertex: every level moves up one. */
STYLOS_AVX2_INLINE void popTop(Cache& cache, __m256 pop)
{
#pragma GCC unroll 16
    for (int i = 0; i + 1 < kLevels; ++i) {
        cache.height[i] = select(cache.height[i], cache.height[i + 1], pop);
        cache.slope[i] = select(cache.slope[i], cache.slope[i + 1], pop);
        cache.key[i] = select(cache.key[i], cache.key[i + 1], pop);
    }
    cache.count = _mm256_add_epi32(cache.count, _mm256_castps_si256(pop)); // all-ones = −1
}

/** Lanes @p valid push a vertex: every level moves down one, the deepest leaving when the cache is full. */
STYLOS_AVX2_INLINE void push(Cache& cache, __m256 valid, __m256 height, __m256 slope, __m256i key)
{
    const __m256i levels = _mm256_set1_epi32(kLevels);
    const __m256 evict = _mm256_and_ps(valid, asMask(_mm256_cmpeq_epi32(cache.count, levels)));
    cache.below = select(cache.below, cache.key[kLevels - 1], evict);
#pragma GCC unroll 16
    for (int i = kLevels - 1; i > 0; --i) {
        cache.height[i] = select(cache.height[i], cache.height[i - 1], valid);
        cache.slope[i] = select(cache.slope[i], cache.slope[i - 1], valid);
        cache.key[i] = select(cache.key[i], cache.key[i - 1], valid);
    }
    cache.height[0] = select(cache.height[0], height, valid);
    cache.slope[0] = select(cache.slope[0], slope, valid);
    cache.key[0] = select(cache.key[0], key, valid);
    cache.count = _mm256_min_epi32(_mm256_sub_epi32(cache.count, _mm256_castps_si256(valid)), levels);
}

/** What every step of a walk reads: the walk, its hull list and its vector constants. */
struct Walk {
    const GroupWalk& walk;
    std::uint16_t* links;
    HullList list;
    __m256 along, across, nan;
    __m256i firstKeys, laneBits;
    bool sine;

    STYLOS_AVX2_INLINE Walk(const GroupWalk& w, HullStacks& stacks)
        : walk(w), links(stacks.links.data()), list(w, stacks), along(_mm256_set1_ps(w.along)),
          across(_mm256_set1_ps(w.across)), nan(_mm256_set1_ps(std::numeric_limits<float>::quiet_NaN())),
          firstKeys(_mm256_set1_epi32(list.firstKey)), laneBits(_mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128)),
          sine(w.value == HorizonValue::Sine)
    {
    }

    STYLOS_AVX2_INLINE Cache startCache() const
    {
        Cache cache;
        for (int i = 0; i < kLevels; ++i) {
            cache.height[i] = _mm256_set1_ps(-std::numeric_limits<float>::infinity());
            cache.slope[i] = nan;
            cache.key[i] = _mm256_set1_epi32(list.sentinel);
        }
        cache.below = cache.key[0];
        cache.count = _mm256_set1_epi32(1);
        return cache;
    }
};

/**
 * Step @p s of lanes first … first + 7 of the group: the AVX-512 kernel's step (HorizonSweepAvx512.cpp)
 * with 8 lanes, masks as vectors, and masked loads and stores only where a lane lies outside the grid.
 */
STYLOS_AVX2_INLINE void walkStep(Cache& cache, const Walk& c, int s, int first)
{
    const GroupWalk& walk = c.walk;
    constexpr unsigned all = (1u << kWidth) - 1u;
    const __m256 zero = _mm256_setzero_ps();
    const std::size_t row = std::size_t(s) * kGroupLanes + std::size_t(first);
    float* values = walk.values + row;
    // Lane j is element offsets[s] + first + j of the source layout; lanes outside the grid are
    // masked, so the addresses are formed as integers (they may lie outside the arrays).
    const std::uintptr_t offset = std::uintptr_t(walk.offsets[s] + first);
    const unsigned inside = (unsigned(walk.inside[s]) >> first) & all;
    __m256 h, valid;
    if (walk.fromSource) {
        const auto* cell = reinterpret_cast<const float*>(reinterpret_cast<std::uintptr_t>(walk.source) + offset * 4);
        if (inside == all) {
            h = _mm256_loadu_ps(cell);
            valid = _mm256_cmp_ps(h, h, _CMP_ORD_Q);
        } else {
            const __m256i lanes =
                _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(int(inside)), c.laneBits), c.laneBits);
            h = _mm256_maskload_ps(cell, lanes);
            valid = _mm256_and_ps(asMask(lanes), _mm256_cmp_ps(h, h, _CMP_ORD_Q));
        }
        h = select(c.nan, h, valid);
        _mm256_storeu_ps(walk.heights + row, h);
    } else {
        h = _mm256_loadu_ps(walk.heights + row);
        valid = _mm256_cmp_ps(h, h, _CMP_ORD_Q);
    }
    if (_mm256_movemask_ps(valid) == 0) {
        if (walk.output == WalkOutput::Values) _mm256_storeu_ps(values, zero);
        return;
    }
    const __m256i key = _mm256_set1_epi32(walk.reverse ? -walk.keys[s] : walk.keys[s]);

    // Pop: test the top, bring the next level up, until no lane pops.
    __m256 run = distance(_mm256_sub_epi32(key, cache.key[0]), c.along, c.across);
    __m256 next = distance(_mm256_sub_epi32(key, cache.key[1]), c.along, c.across);
    __m256 pop = _mm256_and_ps(
        valid, _mm256_cmp_ps(_mm256_sub_ps(h, cache.height[0]), _mm256_mul_ps(cache.slope[0], run), _CMP_GE_OQ));
    for (int round = 0; round < 1 || _mm256_movemask_ps(pop) != 0; ++round) {
        popTop(cache, pop);
        run = select(run, next, pop);
        next = distance(_mm256_sub_epi32(key, cache.key[1]), c.along, c.across);
        const __m256 dry = _mm256_and_ps(pop, asMask(_mm256_cmpeq_epi32(cache.count, _mm256_setzero_si256())));
        if (const unsigned dryBits = unsigned(_mm256_movemask_ps(dry)); dryBits != 0) {
            refill(cache, dryBits, c.list, first);
            run = distance(_mm256_sub_epi32(key, cache.key[0]), c.along, c.across);
            next = distance(_mm256_sub_epi32(key, cache.key[1]), c.along, c.across);
        }
        pop = _mm256_and_ps(
            pop, _mm256_cmp_ps(_mm256_sub_ps(h, cache.height[0]), _mm256_mul_ps(cache.slope[0], run), _CMP_GE_OQ));
    }

    // Level 0 is every lane's tangent: one square root and one division for the value and the slope.
    const __m256 rise = _mm256_sub_ps(cache.height[0], h);
    const __m256 up = _mm256_max_ps(rise, zero); // NaN → 0, as the portable kernel
    const __m256 hyp = _mm256_sqrt_ps(_mm256_add_ps(_mm256_mul_ps(rise, rise), _mm256_mul_ps(run, run)));
    const __m256 inverse = _mm256_div_ps(_mm256_set1_ps(1.0f), _mm256_mul_ps(hyp, run));
    const __m256 value = c.sine ? _mm256_mul_ps(_mm256_mul_ps(up, run), inverse) : _mm256_div_ps(up, run);
    if (walk.output == WalkOutput::Values) {
        _mm256_storeu_ps(values, _mm256_and_ps(valid, value));
    } else {
        auto* cell = reinterpret_cast<float*>(reinterpret_cast<std::uintptr_t>(walk.sum) + offset * 4);
        const __m256 total = walk.output == WalkOutput::Sum ? value : _mm256_add_ps(_mm256_loadu_ps(values), value);
        // Every lane in the grid: those without a pixel add +0 to a sum of values ≥ +0 (same bits).
        if (inside == all) {
            _mm256_storeu_ps(cell, _mm256_add_ps(_mm256_loadu_ps(cell), _mm256_and_ps(valid, total)));
        } else {
            const __m256i lanes = _mm256_castps_si256(valid);
            _mm256_maskstore_ps(cell, lanes, _mm256_add_ps(_mm256_maskload_ps(cell, lanes), total));
        }
    }

    // Push: the pixel's link is its tangent's step.
    const __m256i tangent = walk.reverse ? _mm256_sub_epi32(_mm256_setzero_si256(), cache.key[0]) : cache.key[0];
    const __m256i link = _mm256_and_si256(_mm256_sub_epi32(tangent, c.firstKeys), _mm256_set1_epi32(0xFFFF));
    const __m128i packed = _mm_packus_epi32(_mm256_castsi256_si128(link), _mm256_extracti128_si256(link, 1));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(c.links + row), packed);
    const __m256 slope = _mm256_mul_ps(_mm256_mul_ps(_mm256_sub_ps(h, cache.height[0]), hyp), inverse);
    push(cache, valid, h, slope, key);
}

/** Lanes first … first + 7 of the group, step by step. */
STYLOS_AVX2 void walkHalf(const GroupWalk& walk, HullStacks& stacks, int first)
{
    const Walk c(walk, stacks);
    Cache cache = c.startCache();
    for (int t = 0; t < walk.steps; ++t) {
        const int s = walk.reverse ? walk.steps - 1 - t : t;
        prefetchAhead(walk, s);
        walkStep(cache, c, s, first);
    }
}

} // namespace

STYLOS_AVX2 void walkGroupAvx2(const GroupWalk& walk, HullStacks& stacks)
{
    if (walk.steps <= 0) return;
    walkHalf(walk, stacks, 0);
    walkHalf(walk, stacks, kWidth);
}

} // namespace stylos::core::shading::detail

#endif
