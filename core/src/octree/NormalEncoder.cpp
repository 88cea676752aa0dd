#include "stylos/core/octree/NormalEncoder.h"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace stylos::core::octree {

namespace {
// The Octahedral16 grid of NormalCode.cpp: map coordinate = k / 126 − 1, k in [0, 252].
constexpr int gridHalf = 126;
constexpr int gridMax = 2 * gridHalf;

/** floor(x) as an int, the call avoided where truncation gives the same. */
int floorInt(double x)
{
    return x >= 0 ? int(x) : int(std::floor(x));
}
} // namespace

NormalEncoder::NormalEncoder(NormalCodeKind kind) : m_kind(kind)
{
    for (int k = 0; k <= gridMax; ++k) m_grid[std::size_t(k)] = double(k - gridHalf) / gridHalf;
}

std::uint16_t NormalEncoder::operator()(float x, float y, float z) const
{
    if (m_kind != NormalCodeKind::Octahedral16) return encodeNormal(m_kind, x, y, z);
    // As encodeNormal: zero or non-finite input encodes +Z; otherwise rescaled by the largest component.
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return octahedral(0, 0, 1);
    const double m = std::max({std::abs(double(x)), std::abs(double(y)), std::abs(double(z))});
    if (m == 0) return octahedral(0, 0, 1);
    return octahedral(x / m, y / m, z / m);
}

std::uint16_t NormalEncoder::octahedral(double x, double y, double z) const
{
    // Folded octahedral map of (x, y, z).
    const double s = std::abs(x) + std::abs(y) + std::abs(z);
    double u = x / s, w = y / s;
    if (z < 0) {
        const double fu = (1 - std::abs(w)) * (u < 0 ? -1 : 1);
        const double fw = (1 - std::abs(u)) * (w < 0 ? -1 : 1);
        u = fu, w = fw;
    }
    const int fu = floorInt((u + 1) * gridHalf), fv = floorInt((w + 1) * gridHalf);
    const double n = std::sqrt(x * x + y * y + z * z);
    std::uint16_t best = std::uint16_t((std::clamp(fu, 0, gridMax) << 8) | std::clamp(fv, 0, gridMax));
    double bestCos = -2;
    for (int du = 0; du < 2; ++du) {
        const int ku = std::clamp(fu + du, 0, gridMax);
        for (int dv = 0; dv < 2; ++dv) {
            const int kv = std::clamp(fv + dv, 0, gridMax);
            // decodeOctDouble(code) of NormalCode.cpp, with the grid values from the table.
            double du0 = m_grid[std::size_t(ku)], dw0 = m_grid[std::size_t(kv)];
            const double dz = 1 - std::abs(du0) - std::abs(dw0);
            if (dz < 0) {
                const double fu2 = (1 - std::abs(dw0)) * (du0 < 0 ? -1 : 1);
                const double fw2 = (1 - std::abs(du0)) * (dw0 < 0 ? -1 : 1);
                du0 = fu2, dw0 = fw2;
            }
            const double cosine =
                (du0 * x + dw0 * y + dz * z) / (n * std::sqrt(du0 * du0 + dw0 * dw0 + dz * dz));
            if (cosine > bestCos) bestCos = cosine, best = std::uint16_t((ku << 8) | kv);
        }
    }
    return best;
}

void NormalEncoder::encode(std::span<const std::array<float, 3>> normals, std::span<std::uint16_t> codes) const
{
    std::size_t i = 0;
#if defined(__SSE2__)
    if (m_kind == NormalCodeKind::Octahedral16)
        for (; i + 2 <= normals.size(); i += 2) encodePair(normals[i], normals[i + 1], codes[i], codes[i + 1]);
#endif
    for (; i < normals.size(); ++i) codes[i] = (*this)(normals[i][0], normals[i][1], normals[i][2]);
}

#if defined(__SSE2__)
namespace {

/** Lane-wise a ? b : c for a comparison mask a. */
inline __m128d select(__m128d mask, __m128d yes, __m128d no)
{
    return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
}

/** −1 where @p v < 0, else 1 (as `v < 0 ? -1 : 1`). */
inline __m128d signOf(__m128d v)
{
    return select(_mm_cmplt_pd(v, _mm_setzero_pd()), _mm_set1_pd(-1.0), _mm_set1_pd(1.0));
}

inline __m128d absOf(__m128d v)
{
    return _mm_andnot_pd(_mm_set1_pd(-0.0), v);
}

bool ordinary(const std::array<float, 3>& v)
{
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) && (v[0] != 0 || v[1] != 0 || v[2] != 0);
}

} // namespace

void NormalEncoder::encodePair(const std::array<float, 3>& a, const std::array<float, 3>& b, std::uint16_t& codeA,
                               std::uint16_t& codeB) const
{
    if (!ordinary(a) || !ordinary(b)) {
        codeA = (*this)(a[0], a[1], a[2]);
        codeB = (*this)(b[0], b[1], b[2]);
        return;
    }
    // operator() for two inputs at once, lane 0 = a, lane 1 = b: the same double operations in the
    // same order (packed SSE2 rounds exactly as scalar SSE2), without branches.
    const __m128d one = _mm_set1_pd(1.0);
    __m128d x = _mm_set_pd(b[0], a[0]), y = _mm_set_pd(b[1], a[1]), z = _mm_set_pd(b[2], a[2]);
    const __m128d m = _mm_max_pd(_mm_max_pd(absOf(x), absOf(y)), absOf(z));
    x = _mm_div_pd(x, m), y = _mm_div_pd(y, m), z = _mm_div_pd(z, m);
    // octahedral(x, y, z): the folded map, the grid cell, the four candidates.
    const __m128d s = _mm_add_pd(_mm_add_pd(absOf(x), absOf(y)), absOf(z));
    __m128d u = _mm_div_pd(x, s), w = _mm_div_pd(y, s);
    const __m128d below = _mm_cmplt_pd(z, _mm_setzero_pd());
    const __m128d foldU = _mm_mul_pd(_mm_sub_pd(one, absOf(w)), signOf(u));
    const __m128d foldW = _mm_mul_pd(_mm_sub_pd(one, absOf(u)), signOf(w));
    u = select(below, foldU, u), w = select(below, foldW, w);
    const __m128d half = _mm_set1_pd(gridHalf);
    // (u + 1) · 126 >= 0 (|u| <= 1), so truncation is the floor.
    alignas(16) std::int32_t fu[4], fv[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(fu), _mm_cvttpd_epi32(_mm_mul_pd(_mm_add_pd(u, one), half)));
    _mm_store_si128(reinterpret_cast<__m128i*>(fv), _mm_cvttpd_epi32(_mm_mul_pd(_mm_add_pd(w, one), half)));
    const __m128d n = _mm_sqrt_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(x, x), _mm_mul_pd(y, y)), _mm_mul_pd(z, z)));
    int ku[2][2], kv[2][2];  // [lane][du or dv]
    for (int lane = 0; lane < 2; ++lane)
        for (int d = 0; d < 2; ++d) {
            ku[lane][d] = std::clamp(fu[lane] + d, 0, gridMax);
            kv[lane][d] = std::clamp(fv[lane] + d, 0, gridMax);
        }
    __m128d bestCos = _mm_set1_pd(-2.0);
    __m128d best = _mm_set_pd(double((ku[1][0] << 8) | kv[1][0]), double((ku[0][0] << 8) | kv[0][0]));
    for (int du = 0; du < 2; ++du) {
        for (int dv = 0; dv < 2; ++dv) {
            const __m128d u0 = _mm_set_pd(m_grid[std::size_t(ku[1][du])], m_grid[std::size_t(ku[0][du])]);
            const __m128d w0 = _mm_set_pd(m_grid[std::size_t(kv[1][dv])], m_grid[std::size_t(kv[0][dv])]);
            const __m128d dz = _mm_sub_pd(_mm_sub_pd(one, absOf(u0)), absOf(w0));
            const __m128d folded = _mm_cmplt_pd(dz, _mm_setzero_pd());
            const __m128d du1 = select(folded, _mm_mul_pd(_mm_sub_pd(one, absOf(w0)), signOf(u0)), u0);
            const __m128d dw1 = select(folded, _mm_mul_pd(_mm_sub_pd(one, absOf(u0)), signOf(w0)), w0);
            const __m128d dot = _mm_add_pd(_mm_add_pd(_mm_mul_pd(du1, x), _mm_mul_pd(dw1, y)), _mm_mul_pd(dz, z));
            const __m128d norm =
                _mm_sqrt_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(du1, du1), _mm_mul_pd(dw1, dw1)), _mm_mul_pd(dz, dz)));
            const __m128d cosine = _mm_div_pd(dot, _mm_mul_pd(n, norm));
            const __m128d better = _mm_cmpgt_pd(cosine, bestCos);
            const __m128d code = _mm_set_pd(double((ku[1][du] << 8) | kv[1][dv]), double((ku[0][du] << 8) | kv[0][dv]));
            bestCos = select(better, cosine, bestCos);
            best = select(better, code, best);
        }
    }
    alignas(16) double codes[2];
    _mm_store_pd(codes, best);
    codeA = std::uint16_t(codes[0]);
    codeB = std::uint16_t(codes[1]);
}
#endif

} // namespace stylos::core::octree
