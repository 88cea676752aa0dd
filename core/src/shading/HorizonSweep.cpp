#include "HorizonKernelParts.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace stylos::core::shading::detail {

// The lanes one after the other at each step, each with its stack level by level; the pop loop and
// the arithmetic are those of the vector kernels (HorizonSweepAvx2.cpp, HorizonSweepAvx512.cpp), in the
// same order.
void walkGroupScalar(const GroupWalk& walk, HullStacks& stacks)
{
    constexpr int L = kGroupLanes;
    float* stackH = stacks.heights.data();
    float* stackS = stacks.slopes.data();
    std::int32_t* stackK = stacks.keys.data();
    const int n = walk.steps;
    if (n <= 0) return;
    const float none = std::numeric_limits<float>::quiet_NaN();
    const std::int32_t sentinel = (walk.reverse ? -walk.keys[n - 1] : walk.keys[0]) - 1;
    int tops[L];
    for (int j = 0; j < L; ++j) {
        stackH[j] = -std::numeric_limits<float>::infinity();
        stackS[j] = none;
        stackK[j] = sentinel;
        tops[j] = 0;
    }
    for (int t = 0; t < n; ++t) {
        const int s = walk.reverse ? n - 1 - t : t;
        const std::int32_t key = walk.reverse ? -walk.keys[s] : walk.keys[s];
        float* heights = walk.heights + std::size_t(s) * L;
        float* values = walk.values + std::size_t(s) * L;
        const std::int64_t offset = walk.offsets[s];
        prefetchAhead(walk, s);
        if (walk.fromSource) {
            const unsigned inside = walk.inside[s];
            for (int j = 0; j < L; ++j) {
                float h = none;
                const std::int64_t e = offset + j;
                if ((inside >> j) & 1u) h = walk.source[e];
                heights[j] = h;
            }
        }
        for (int j = 0; j < L; ++j) {
            const float h = heights[j];
            if (std::isnan(h)) {
                if (walk.output == WalkOutput::Values) values[j] = 0.0f;
                continue;
            }
            int c = tops[j];
            std::size_t v;
            float run;
            for (;;) {
                v = std::size_t(c) * L + std::size_t(j);
                run = keyDistance(key - stackK[v], walk.along, walk.across);
                if (!(h - stackH[v] >= stackS[v] * run)) break; // NaN slopes never pop
                --c;
            }
            const float rise = stackH[v] - h;
            const float up = rise > 0.0f ? rise : 0.0f; // as _mm512_max_ps(rise, 0)
            const float hyp = std::sqrt(rise * rise + run * run);
            const float inverse = 1.0f / (hyp * run);
            const float value = walk.value == HorizonValue::Sine ? up * run * inverse : up / run;
            switch (walk.output) {
            case WalkOutput::Values: values[j] = value; break;
            case WalkOutput::SumWithValues: walk.sum[offset + j] += values[j] + value; break;
            case WalkOutput::Sum: walk.sum[offset + j] += value; break;
            }
            const float num = h - stackH[v];
            ++c;
            const std::size_t w = std::size_t(c) * L + std::size_t(j);
            stackH[w] = h;
            stackS[w] = num * hyp * inverse;
            stackK[w] = key;
            tops[j] = c;
        }
    }
}

} // namespace stylos::core::shading::detail
