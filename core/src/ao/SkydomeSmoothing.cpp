#include "stylos/core/ao/SkydomeSmoothing.h"

#include "../shading/ParallelChunks.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace stylos::core::ao {

namespace {

/** Bins of edge `radius`, keyed by their three coordinates (21 bits each, offset so that none is negative). */
struct Bins {
    double edge = 1.0;
    std::array<double, 3> lower{};
    std::vector<std::pair<std::uint64_t, std::uint32_t>> sorted; ///< (key, receiver), by key
    std::vector<std::uint64_t> keys;                              ///< the distinct keys, ascending
    std::vector<std::uint32_t> begin;                             ///< keys + 1 entries: each bin's range in sorted

    static constexpr std::uint64_t kCoordMask = (1u << 21) - 1;

    /** The bin of @p p, each coordinate in [1, 2^21 − 2], so that every neighbour bin's key is a valid key: the
     *  margin of one bin below the lowest receiver can round to 0 ((1.0 − 0.9) / 0.1 < 1), and a key − 1 of a
     *  coordinate 0 would wrap. A receiver moved so lies within rounding of the bin's edge, so its neighbours
     *  within the radius still lie in the bins around it. */
    std::array<std::int64_t, 3> coordsOf(const std::array<float, 3>& p) const
    {
        std::array<std::int64_t, 3> c{};
        for (int a = 0; a < 3; ++a)
            c[std::size_t(a)] = std::clamp(std::int64_t(std::floor((double(p[std::size_t(a)]) - lower[std::size_t(a)]) / edge)),
                                           std::int64_t(1), std::int64_t(kCoordMask - 1));
        return c;
    }
    static std::uint64_t keyOf(std::int64_t x, std::int64_t y, std::int64_t z)
    {
        return (std::uint64_t(z) << 42) | (std::uint64_t(y) << 21) | std::uint64_t(x);
    }
};

/**
 * The weighted sums of one receiver over runs of candidates: weight (1 − d²/r²)² where d² < r² and
 * |n·n'| ≥ minCos, else 0. Four candidates at a time in SSE lanes (x86-64 always has SSE2), the rest one by one;
 * the lanes are added in a fixed order, so the result depends only on the inputs, not on threads or addresses.
 */
struct Accumulator {
    float x, y, z, nx, ny, nz, r2, inverse, minCos;
#if defined(__SSE2__)
    __m128 sum4 = _mm_setzero_ps(), weights4 = _mm_setzero_ps();
#endif
    float sum = 0.0f, weights = 0.0f;

    void add(const float* X, const float* Y, const float* Z, const float* NX, const float* NY, const float* NZ,
             const float* V, std::uint32_t from, std::uint32_t to)
    {
        std::uint32_t l = from;
#if defined(__SSE2__)
        const __m128 px = _mm_set1_ps(x), py = _mm_set1_ps(y), pz = _mm_set1_ps(z);
        const __m128 mx = _mm_set1_ps(nx), my = _mm_set1_ps(ny), mz = _mm_set1_ps(nz);
        const __m128 radius2 = _mm_set1_ps(r2), inv = _mm_set1_ps(inverse), cosine = _mm_set1_ps(minCos);
        const __m128 one = _mm_set1_ps(1.0f), sign = _mm_set1_ps(-0.0f);
        for (; l + 4 <= to; l += 4) {
            const __m128 dx = _mm_sub_ps(_mm_loadu_ps(X + l), px), dy = _mm_sub_ps(_mm_loadu_ps(Y + l), py),
                         dz = _mm_sub_ps(_mm_loadu_ps(Z + l), pz);
            const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
            const __m128 dot = _mm_add_ps(_mm_add_ps(_mm_mul_ps(mx, _mm_loadu_ps(NX + l)), _mm_mul_ps(my, _mm_loadu_ps(NY + l))),
                                          _mm_mul_ps(mz, _mm_loadu_ps(NZ + l)));
            const __m128 facing = _mm_andnot_ps(sign, dot);
            const __m128 keep = _mm_and_ps(_mm_cmplt_ps(d2, radius2), _mm_cmpge_ps(facing, cosine));
            const __m128 t = _mm_sub_ps(one, _mm_mul_ps(d2, inv));
            const __m128 w = _mm_and_ps(keep, _mm_mul_ps(t, t));
            sum4 = _mm_add_ps(sum4, _mm_and_ps(keep, _mm_mul_ps(w, _mm_loadu_ps(V + l)))); // (a far NaN stays out)
            weights4 = _mm_add_ps(weights4, w);
        }
#endif
        for (; l < to; ++l) {
            const float dx = X[l] - x, dy = Y[l] - y, dz = Z[l] - z;
            const float d2 = dx * dx + dy * dy + dz * dz;
            const float facing = std::abs(nx * NX[l] + ny * NY[l] + nz * NZ[l]);
            if (!(d2 < r2) || !(facing >= minCos)) continue;
            const float t = 1.0f - d2 * inverse; // (1 − d²/r²)²: 1 at the centre, 0 at the radius
            sum += t * t * V[l];
            weights += t * t;
        }
    }

    std::pair<float, float> total() const
    {
#if defined(__SSE2__)
        alignas(16) float s[4], w[4];
        _mm_store_ps(s, sum4);
        _mm_store_ps(w, weights4);
        return {((s[0] + s[1]) + (s[2] + s[3])) + sum, ((w[0] + w[1]) + (w[2] + w[3])) + weights};
#else
        return {sum, weights};
#endif
    }
};

/** Receivers per chunk of the parallel loops that key, and gather, them. */
constexpr std::size_t kChunk = std::size_t(1) << 16;

/**
 * Sorts @p items (distinct pairs: the result does not depend on how) on @p threads threads: one run per
 * thread sorted at once, then the runs merged pairwise, the merges of a round at once.
 */
void sortInParallel(std::vector<std::pair<std::uint64_t, std::uint32_t>>& items, unsigned threads)
{
    const std::size_t n = items.size();
    const std::size_t runs = std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(1, n / kChunk));
    std::vector<std::size_t> bounds(runs + 1);
    for (std::size_t r = 0; r <= runs; ++r) bounds[r] = n * r / runs;
    shading::detail::parallelChunks(runs, 1, threads, nullptr, [&](std::size_t r, std::size_t, unsigned) {
        std::sort(items.begin() + std::ptrdiff_t(bounds[r]), items.begin() + std::ptrdiff_t(bounds[r + 1]));
    });
    for (std::size_t width = 1; width < runs; width *= 2) {
        const std::size_t merges = (runs + 2 * width - 1) / (2 * width);
        shading::detail::parallelChunks(merges, 1, threads, nullptr, [&](std::size_t m, std::size_t, unsigned) {
            const std::size_t first = bounds[2 * width * m];
            const std::size_t middle = bounds[std::min(runs, 2 * width * m + width)];
            const std::size_t last = bounds[std::min(runs, 2 * width * (m + 1))];
            std::inplace_merge(items.begin() + std::ptrdiff_t(first), items.begin() + std::ptrdiff_t(middle),
                               items.begin() + std::ptrdiff_t(last));
        });
    }
}

} // namespace

Status smoothSkydome(const AoReceivers& receivers, std::span<float> values, const SkydomeSmoothing& options,
                     ProgressSink* progress)
{
    assert(values.size() == receivers.size() && "smoothSkydome(): one value per receiver");
    const std::size_t n = receivers.size();
    if (!(options.radius > 0.0) || n < 2) return {};

    Bins bins;
    bins.edge = options.radius;
    bins.lower = {double(receivers.positions[0][0]), double(receivers.positions[0][1]), double(receivers.positions[0][2])};
    std::array<double, 3> upper = bins.lower;
    for (const auto& p : receivers.positions)
        for (int a = 0; a < 3; ++a) bins.lower[a] = std::min(bins.lower[a], double(p[a])), upper[a] = std::max(upper[a], double(p[a]));
    // At most 2^21 bins along an axis: a radius too small for the extent is widened (a finer grid than that
    // would hold one receiver per million bins).
    for (int a = 0; a < 3; ++a) bins.edge = std::max(bins.edge, (upper[a] - bins.lower[a]) / double(Bins::kCoordMask - 4));
    for (int a = 0; a < 3; ++a) bins.lower[a] -= bins.edge; // a margin of one bin (coordsOf clamps what rounding moves)

    const unsigned threads = shading::detail::resolveThreads(options.threads);
    bins.sorted.resize(n);
    shading::detail::parallelChunks(n, kChunk, threads, nullptr, [&](std::size_t first, std::size_t last, unsigned) {
        for (std::size_t i = first; i < last; ++i) {
            const auto c = bins.coordsOf(receivers.positions[i]);
            bins.sorted[i] = {Bins::keyOf(c[0], c[1], c[2]), std::uint32_t(i)};
        }
    });
    sortInParallel(bins.sorted, threads);
    for (std::size_t i = 0; i < n; ++i)
        if (i == 0 || bins.sorted[i].first != bins.sorted[i - 1].first) {
            bins.keys.push_back(bins.sorted[i].first);
            bins.begin.push_back(std::uint32_t(i));
        }
    bins.begin.push_back(std::uint32_t(n));
    // The receivers in bin order, one array per coordinate, so that a bin's neighbours are read as contiguous
    // runs, four at a time.
    std::array<std::vector<float>, 7> soa; // x, y, z, nx, ny, nz, value
    for (auto& column : soa) column.resize(n);
    shading::detail::parallelChunks(n, kChunk, threads, nullptr, [&](std::size_t first, std::size_t last, unsigned) {
        for (std::size_t k = first; k < last; ++k) {
            const std::uint32_t i = bins.sorted[k].second;
            const auto& p = receivers.positions[i];
            const auto& m = receivers.normals[i];
            soa[0][k] = p[0], soa[1][k] = p[1], soa[2][k] = p[2];
            soa[3][k] = m[0], soa[4][k] = m[1], soa[5][k] = m[2], soa[6][k] = values[i];
        }
    });
    const float* X = soa[0].data();
    const float* Y = soa[1].data();
    const float* Z = soa[2].data();
    const float* NX = soa[3].data();
    const float* NY = soa[4].data();
    const float* NZ = soa[5].data();
    const float* V = soa[6].data();

    const float r2 = float(options.radius * options.radius), inverse = 1.0f / r2;
    // The results go straight to values: every read is of V (the values in bin order), and each receiver is
    // written once, by the worker of its bin.
    float* out = values.data();
    const bool finished = shading::detail::parallelChunks(
        bins.keys.size(), 256, threads, progress,
        [&](std::size_t first, std::size_t last, unsigned) {
            // The neighbours of bin (x, y, z) in row (y + dy, z + dz) are bins x − 1..x + 1 of that row: keys
            // key − 1 + offset .. key + 1 + offset, consecutive in the sorted keys, so one run of leaves. As the
            // bins go up, each of the nine rows' first key goes up too: a cursor per row that only moves on.
            std::array<std::uint64_t, 9> offset{};
            for (int r = 0; r < 9; ++r)
                offset[std::size_t(r)] = (std::uint64_t(std::int64_t(r % 3 - 1)) << 21) + (std::uint64_t(std::int64_t(r / 3 - 1)) << 42);
            std::array<std::size_t, 9> cursor{};
            const std::size_t keyCount = bins.keys.size();
            for (std::size_t r = 0; r < 9; ++r)
                cursor[r] = std::size_t(std::lower_bound(bins.keys.begin(), bins.keys.end(), bins.keys[first] + offset[r] - 1) -
                                        bins.keys.begin());
            std::array<std::pair<std::uint32_t, std::uint32_t>, 9> ranges;
            for (std::size_t b = first; b < last; ++b) {
                std::size_t count = 0;
                for (std::size_t r = 0; r < 9; ++r) {
                    const std::uint64_t low = bins.keys[b] + offset[r] - 1, high = low + 2;
                    std::size_t c = cursor[r];
                    while (c < keyCount && bins.keys[c] < low) ++c;
                    cursor[r] = c;
                    std::size_t e = c;
                    while (e < keyCount && bins.keys[e] <= high) ++e;
                    if (e > c) ranges[count++] = {bins.begin[c], bins.begin[e]};
                }
                for (std::uint32_t k = bins.begin[b]; k < bins.begin[b + 1]; ++k) {
                    Accumulator acc{X[k], Y[k], Z[k], NX[k], NY[k], NZ[k], r2, inverse, options.minCos};
                    for (std::size_t r = 0; r < count; ++r) acc.add(X, Y, Z, NX, NY, NZ, V, ranges[r].first, ranges[r].second);
                    const auto [sum, weights] = acc.total();
                    out[bins.sorted[k].second] = weights > 0.0f ? sum / weights : V[k];
                }
            }
        });
    if (!finished) { // the values as they were: V holds them all
        for (std::size_t k = 0; k < n; ++k) out[bins.sorted[k].second] = V[k];
        return Error{ErrorCode::Cancelled, "the skydome's smoothing was cancelled"};
    }
    return {};
}

} // namespace stylos::core::ao
