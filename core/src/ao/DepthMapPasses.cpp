// The DepthMap skydome's two passes (see DepthMapKernel.cpp for what they compute and why), written once
// as always-inline loops over blocks of cells and compiled into one function per instruction set: the
// block loops auto-vectorise (4 or 8 lanes), the map accesses between them stay scalar. No multiply-add
// is contracted (AVX-512 implies FMA), so all variants give the same bits, and both passes the same keys.
#include "DepthMapPasses.h"

#include <algorithm>
#include <bit>
#include <cmath>

#define STYLOS_DEPTHMAP_INLINE __attribute__((always_inline)) inline
#define STYLOS_DEPTHMAP_LAMBDA_INLINE __attribute__((always_inline))

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#endif

namespace stylos::core::ao::detail {
namespace {

constexpr std::size_t kBlock = DepthMapScratch::kBlock;

STYLOS_DEPTHMAP_INLINE void splatImpl(const DepthMapFrame& f, const PreparedCells& cells, std::int32_t* map,
                                      DepthMapScratch& scratch)
{
    // Per cell of the block: the index of its 2 × 2 pixels' first, and the entries for them: row[2k],
    // row[2k + 1] for pixels (iu, iv), (iu + 1, iv); below[2k], below[2k + 1] for (iu, iv + 1), (iu + 1, iv + 1).
    std::uint32_t* index = scratch.index;
    std::int32_t* row = scratch.row;
    std::int32_t* below = scratch.below;
    // Slab k of the cube's hexagon: |q·N_k| ≤ h_k for q = pixel centre − the cell's projection. With the
    // block's pixel at (floor(u − ½), floor(v − ½)) and fractions (a, b), corner (cx, cy) has
    // q = (cx − a, cy − b), so q·N_k = cx·nu_k + cy·nv_k − s_k with s_k = a·nu_k + b·nv_k.
    const float nu0 = f.nu[0], nu1 = f.nu[1], nu2 = f.nu[2], nv0 = f.nv[0], nv1 = f.nv[1], nv2 = f.nv[2];
    const float h0 = f.h[0], h1 = f.h[1], h2 = f.h[2];
    const float uShift = f.u0 - 0.5f, vShift = f.v0 - 0.5f;
    const float e10 = f.e1[0], e11 = f.e1[1], e12 = f.e1[2], e20 = f.e2[0], e21 = f.e2[1], e22 = f.e2[2];
    const float d0 = f.d[0], d1 = f.d[1], d2 = f.d[2], keyMin = f.keyMin, keyScale = f.keyScale;
    const std::size_t w = std::size_t(f.width);
    const std::uint32_t width = std::uint32_t(f.width);
    for (std::size_t first = 0; first < cells.size(); first += kBlock) {
        const std::size_t count = std::min(kBlock, cells.size() - first);
        const float* x = cells.x.data() + first;
        const float* y = cells.y.data() + first;
        const float* z = cells.z.data() + first;
        for (std::size_t k = 0; k < count; ++k) {
            const float u = x[k] * e10 + y[k] * e11 + z[k] * e12 + uShift;
            const float v = x[k] * e20 + y[k] * e21 + z[k] * e22 + vShift;
            const float key = x[k] * d0 + y[k] * d1 + z[k] * d2;
            const std::int32_t packedKey = (std::int32_t((key - keyMin) * keyScale) + 1) << 8;
            const std::int32_t ju = std::int32_t(u), jv = std::int32_t(v);
            const float a = u - float(ju), b = v - float(jv);
            const float s0 = a * nu0 + b * nv0, s1 = a * nu1 + b * nv1, s2 = a * nu2 + b * nv2;
            const bool in0 = (std::abs(s0) <= h0) & (std::abs(s1) <= h1) & (std::abs(s2) <= h2);
            const bool in1 = (std::abs(nu0 - s0) <= h0) & (std::abs(nu1 - s1) <= h1) & (std::abs(nu2 - s2) <= h2);
            const bool in2 = (std::abs(nv0 - s0) <= h0) & (std::abs(nv1 - s1) <= h1) & (std::abs(nv2 - s2) <= h2);
            const bool in3 =
                (std::abs(nu0 + nv0 - s0) <= h0) & (std::abs(nu1 + nv1 - s1) <= h1) & (std::abs(nu2 + nv2 - s2) <= h2);
            // Offset of the cell's centre from each corner's pixel centre, (a − cx, b − cy) ∈ (−1, 1)²,
            // in steps of 1/8: 4 bits per axis, stored as (offset + 1) · 8.
            const std::int32_t qa0 = std::int32_t((a + 1.0f) * 8.0f) << 4, qa1 = std::int32_t(a * 8.0f) << 4;
            const std::int32_t qb0 = std::int32_t((b + 1.0f) * 8.0f), qb1 = std::int32_t(b * 8.0f);
            index[k] = std::uint32_t(ju) + std::uint32_t(jv) * width;
            row[2 * k] = in0 ? packedKey | qa0 | qb0 : 0;
            row[2 * k + 1] = in1 ? packedKey | qa1 | qb0 : 0;
            below[2 * k] = in2 ? packedKey | qa0 | qb1 : 0;
            below[2 * k + 1] = in3 ? packedKey | qa1 | qb1 : 0;
        }
        // One pixel at a time: consecutive cells share pixels, and a store forwards to a load of the same
        // 4 bytes only (measured: 2-pixel loads and stores, or skipping the empty corners through a
        // compacted list, are 10–30 % slower).
        for (std::size_t k = 0; k < count; ++k) {
            std::int32_t* p = map + index[k];
            p[0] = std::max(p[0], row[2 * k]);
            p[1] = std::max(p[1], row[2 * k + 1]);
            p[w] = std::max(p[w], below[2 * k]);
            p[w + 1] = std::max(p[w + 1], below[2 * k + 1]);
        }
    }
}

/**
 * Pass 2's decision for one block of @p count receivers (see testBlocks), in a function of its own: its
 * pointers are restrict, so the loops vectorise (without it, the eighteen arrays need more run-time alias
 * checks than GCC makes, and the loop stayed scalar: 40 % of `stylos-cli ao` on the 2 mm drum). Every loop
 * here vectorises for AVX-512, AVX2 and SSE2 (`-fopt-info-vec`); the same bits as the scalar code.
 */
template <bool TwoSided, typename Hidden>
STYLOS_DEPTHMAP_INLINE void decideBlock(std::size_t count, const float* __restrict x, const float* __restrict y,
                                        const float* __restrict z, const float* __restrict nx,
                                        const float* __restrict ny, const float* __restrict nz,
                                        const std::int32_t* __restrict ownKey, const std::int32_t* __restrict entry,
                                        const float* __restrict toPixelU, const float* __restrict toPixelV,
                                        float* __restrict seen, float* __restrict total, float* __restrict seenBack,
                                        float* __restrict totalBack, std::uint32_t* __restrict seenMask,
                                        float* __restrict nDotD, float d0, float d1, float d2, float inverse,
                                        bool cosine, const Hidden& hidden)
{
    // Whether receiver k, measured with the normal (mx, my, mz), is hidden by the occluder stored at its pixel,
    // whose centre relative to the receiver is found along d from the keys, across d from the receiver's offset
    // to its pixel centre plus the stored offset.
    const auto isHidden = [=](std::size_t k, float mx, float my, float mz) STYLOS_DEPTHMAP_LAMBDA_INLINE {
        const std::int32_t p = entry[k];
        const std::int32_t ahead = (p >> 8) - ownKey[k];
        const float along = float(ahead) * inverse;
        const float across1 = toPixelU[k] + float((p >> 4) & 15) * 0.125f - 0.9375f;
        const float across2 = toPixelV[k] + float(p & 15) * 0.125f - 0.9375f;
        return hidden(x[k], y[k], z[k], mx, my, mz, p, ahead, along, across1, across2);
    };
    if constexpr (TwoSided) {
        // Two loops: the test on the side d lies on, then the sums, the choices made with masks on the bits.
        // In one loop GCC sinks the test into a branch of the sums (with float operations in its arms, which it
        // cannot if-convert for AVX2: "could trap"), and the loop stays scalar.
        for (std::size_t k = 0; k < count; ++k) {
            // The side d lies on: the front (n·d > 0) or the back (n·d < 0, measured with −n). copysign
            // differs from "nd < 0 ? −1 : 1" only at nd = −0 or NaN, where both weights are 0 below.
            const float nd = nx[k] * d0 + ny[k] * d1 + nz[k] * d2;
            nDotD[k] = nd; // kept for the sums
            const float side = std::copysign(1.0f, nd);
            seenMask[k] = std::uint32_t(isHidden(k, side * nx[k], side * ny[k], side * nz[k])) - 1u; // all ones: seen
        }
        // directionWeight(|n·d|) on the side d lies on, 0 on the other (and both 0 at n·d = 0 or NaN).
        const std::uint32_t cosineMask = cosine ? ~0u : 0u, one = std::bit_cast<std::uint32_t>(1.0f);
        for (std::size_t k = 0; k < count; ++k) {
            const float nd = nDotD[k];
            const std::uint32_t weight = (std::bit_cast<std::uint32_t>(std::abs(nd)) & cosineMask) | (one & ~cosineMask);
            const std::uint32_t front = weight & (0u - std::uint32_t(nd > 0.0f));
            const std::uint32_t back = weight & (0u - std::uint32_t(nd < 0.0f));
            total[k] += std::bit_cast<float>(front);
            seen[k] += std::bit_cast<float>(front & seenMask[k]);
            totalBack[k] += std::bit_cast<float>(back);
            seenBack[k] += std::bit_cast<float>(back & seenMask[k]);
        }
        return;
    }
    for (std::size_t k = 0; k < count; ++k) {
        const float nd = nx[k] * d0 + ny[k] * d1 + nz[k] * d2;
        const bool hiddenHere = isHidden(k, nx[k], ny[k], nz[k]);
        const float weight = directionWeight(nd, cosine);
        total[k] += weight;
        seen[k] += hiddenHere ? 0.0f : weight;
    }
}

/**
 * Pass 2's frame for every facing block: each receiver projected to its pixel (its key along d, the map entry
 * there, its offset to the pixel centre), then @p hidden decides from the stored occluder, and the direction's
 * weight is added. @p hidden(k, p, ahead, along, across1, across2) gets, for receiver k of the block, the map
 * entry p, how many keys the occluder lies ahead and its offset along d and across it (cell edges).
 */
template <bool TwoSided, typename Hidden>
STYLOS_DEPTHMAP_INLINE void testBlocks(const DepthMapFrame& f, const PreparedCells& cells, const std::int32_t* map,
                                       const std::uint8_t* facing, bool cosine, Accumulator& sums,
                                       DepthMapScratch& scratch, Hidden&& hidden)
{
    std::uint32_t* index = scratch.index;
    std::int32_t* ownKey = scratch.ownKey;
    std::int32_t* entry = scratch.entry;
    float* toPixelU = scratch.toPixel[0];
    float* toPixelV = scratch.toPixel[1];
    const std::uint32_t width = std::uint32_t(f.width);
    // Local copies: the compiler cannot otherwise tell the frame from the float arrays written below.
    const float e10 = f.e1[0], e11 = f.e1[1], e12 = f.e1[2], e20 = f.e2[0], e21 = f.e2[1], e22 = f.e2[2];
    const float d0 = f.d[0], d1 = f.d[1], d2 = f.d[2], u0 = f.u0, v0 = f.v0;
    const float keyMin = f.keyMin, keyScale = f.keyScale, inverse = f.keyInverse;
    for (std::size_t first = 0; first < cells.size(); first += kBlock) {
        if (!TwoSided && !facing[first / kBlock]) continue; // every weight 0: nothing to add
        const std::size_t count = std::min(kBlock, cells.size() - first);
        const float* x = cells.x.data() + first;
        const float* y = cells.y.data() + first;
        const float* z = cells.z.data() + first;
        const float* nx = cells.nx.data() + first;
        const float* ny = cells.ny.data() + first;
        const float* nz = cells.nz.data() + first;
        for (std::size_t k = 0; k < count; ++k) {
            const float u = x[k] * e10 + y[k] * e11 + z[k] * e12 + u0;
            const float v = x[k] * e20 + y[k] * e21 + z[k] * e22 + v0;
            const float key = x[k] * d0 + y[k] * d1 + z[k] * d2;
            ownKey[k] = std::int32_t((key - keyMin) * keyScale) + 1;
            const std::int32_t ju = std::int32_t(u), jv = std::int32_t(v);
            index[k] = std::uint32_t(ju) + std::uint32_t(jv) * width;
            toPixelU[k] = float(ju) + 0.5f - u;
            toPixelV[k] = float(jv) + 0.5f - v;
        }
        for (std::size_t k = 0; k < count; ++k)
            entry[k] = map[index[k]];
        float* seenBack = TwoSided ? sums.seenBack.data() + first : nullptr;
        float* totalBack = TwoSided ? sums.totalBack.data() + first : nullptr;
        decideBlock<TwoSided>(count, x, y, z, nx, ny, nz, ownKey, entry, toPixelU, toPixelV, sums.seen.data() + first,
                              sums.total.data() + first, seenBack, totalBack, scratch.seenMask, scratch.nDotD, d0,
                              d1, d2, inverse, cosine, hidden);
    }
}

// Adding 1.5 · 2^23 and taking it away rounds a float of magnitude < 2^22 to the nearest integer.
constexpr float kRound = 12582912.0f;

STYLOS_DEPTHMAP_INLINE void testImpl(const DepthMapFrame& f, const PreparedCells& cells, const std::int32_t* map,
                                     const std::uint8_t* facing, float bias, bool cosine, Accumulator& sums,
                                     DepthMapScratch& scratch)
{
    const float e10 = f.e1[0], e11 = f.e1[1], e12 = f.e1[2], e20 = f.e2[0], e21 = f.e2[1], e22 = f.e2[2];
    const float d0 = f.d[0], d1 = f.d[1], d2 = f.d[2];
    testBlocks<false>(f, cells, map, facing, cosine, sums, scratch,
               [=](float, float, float, float nx, float ny, float nz, std::int32_t, std::int32_t ahead, float along,
                   float across1, float across2) STYLOS_DEPTHMAP_LAMBDA_INLINE {
                   // Both cells are on the integer lattice and the estimate is within 0.1 of it, so rounding
                   // gives the exact offset.
                   const float dx = (along * d0 + across1 * e10 + across2 * e20 + kRound) - kRound;
                   const float dy = (along * d1 + across1 * e11 + across2 * e21 + kRound) - kRound;
                   const float dz = (along * d2 + across1 * e12 + across2 * e22 + kRound) - kRound;
                   const float above = dx * nx + dy * ny + dz * nz;
                   return (ahead > 0) & (above > bias);
               });
}

// Pass 2 for receivers off the cells' lattice (leaves, AoCells.h's AoReceivers): the same map read, the
// stored occluder's centre rebuilt exactly (the estimate receiver + Δ is within 0.1 of the lattice of
// cell centres, so rounding it to the nearest centre gives that cell), and the rule for a receiver at any
// point of its cell: hidden iff the occluder lies ahead and its centre is more than the cube's half-extent
// along n, ½(|nx| + |ny| + |nz|), plus the bias (AoOptions::receiverBias) above the receiver's tangent plane. A cube that the
// receiver's tangent plane cuts never hides it (an open flat face reads 1), whatever the plane's slope.
// Two-sided (AoOptions::twoSided): the same rule on each side of the tangent plane, every direction counted
// on the side it lies on (with −n on the back), front and back summed apart.
template <bool TwoSided>
STYLOS_DEPTHMAP_INLINE void testOffLatticeImpl(const DepthMapFrame& f, const PreparedCells& cells,
                                               const std::int32_t* map, const std::uint8_t* facing, float bias,
                                               bool cosine, Accumulator& sums, DepthMapScratch& scratch)
{
    const float e10 = f.e1[0], e11 = f.e1[1], e12 = f.e1[2], e20 = f.e2[0], e21 = f.e2[1], e22 = f.e2[2];
    const float d0 = f.d[0], d1 = f.d[1], d2 = f.d[2];
    testBlocks<TwoSided>(f, cells, map, facing, cosine, sums, scratch,
               [=](float x, float y, float z, float nx, float ny, float nz, std::int32_t p, std::int32_t ahead,
                   float along, float across1, float across2) STYLOS_DEPTHMAP_LAMBDA_INLINE {
                   // The occluder's centre c = receiver + Δ lies at (integer + ½) on every axis.
                   const float cx = ((x + (along * d0 + across1 * e10 + across2 * e20) - 0.5f + kRound) - kRound) + 0.5f;
                   const float cy = ((y + (along * d1 + across1 * e11 + across2 * e21) - 0.5f + kRound) - kRound) + 0.5f;
                   const float cz = ((z + (along * d2 + across1 * e12 + across2 * e22) - 0.5f + kRound) - kRound) + 0.5f;
                   const float above = (cx - x) * nx + (cy - y) * ny + (cz - z) * nz;
                   const float reach = 0.5f * (std::abs(nx) + std::abs(ny) + std::abs(nz)) + bias;
                   return (p != 0) & (ahead > 0) & (above > reach);
               });
}

void splatPortable(const DepthMapFrame& f, const PreparedCells& cells, std::int32_t* map, DepthMapScratch& s)
{
    splatImpl(f, cells, map, s);
}
void testPortable(const DepthMapFrame& f, const PreparedCells& cells, const std::int32_t* map,
                  const std::uint8_t* facing, float bias, bool cosine, Accumulator& sums, DepthMapScratch& s)
{
    testImpl(f, cells, map, facing, bias, cosine, sums, s);
}
void testOffLatticePortable(const DepthMapFrame& f, const PreparedCells& cells, const std::int32_t* map,
                            const std::uint8_t* facing, float bias, bool cosine, Accumulator& sums, DepthMapScratch& s)
{
    testOffLatticeImpl<false>(f, cells, map, facing, bias, cosine, sums, s);
}
void testTwoSidedPortable(const DepthMapFrame& f, const PreparedCells& cells, const std::int32_t* map,
    const std::uint8_t* facing, float bias, bool cosine, Accumulator& sums, DepthMapScratch& s)
{
    testOffLatticeImpl<true>(f, cells, map, facing, bias, cosine, sums, s);
}

#if defined(__x86_64__) && defined(__GNUC__)
#define STYLOS_DEPTHMAP_VARIANTS 1
__attribute__((target("avx2"))) void splatAvx2(const DepthMapFrame& f, const PreparedCells& cells, std::int32_t* map,
                                               DepthMapScratch& s)
{
    splatImpl(f, cells, map, s);
}
__attribute__((target("avx2"))) void testAvx2(const DepthMapFrame& f, const PreparedCells& cells,
                                              const std::int32_t* map, const std::uint8_t* facing, float bias,
                                              bool cosine, Accumulator& sums, DepthMapScratch& s)
{
    testImpl(f, cells, map, facing, bias, cosine, sums, s);
}
__attribute__((target("avx2"))) void testOffLatticeAvx2(const DepthMapFrame& f, const PreparedCells& cells,
                                                        const std::int32_t* map, const std::uint8_t* facing, float bias,
                                                        bool cosine, Accumulator& sums, DepthMapScratch& s)
{
    testOffLatticeImpl<false>(f, cells, map, facing, bias, cosine, sums, s);
}
__attribute__((target("avx2"))) void testTwoSidedAvx2(const DepthMapFrame& f, const PreparedCells& cells, const std::int32_t* map,
    const std::uint8_t* facing, float bias, bool cosine, Accumulator& sums, DepthMapScratch& s)
{
    testOffLatticeImpl<true>(f, cells, map, facing, bias, cosine, sums, s);
}
// 256-bit vectors: as fast here as 512-bit ones, without their clock penalty on some processors.
#define STYLOS_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq,avx512bw,prefer-vector-width=256")))
STYLOS_AVX512 void splatAvx512(const DepthMapFrame& f, const PreparedCells& cells, std::int32_t* map,
                               DepthMapScratch& s)
{
    splatImpl(f, cells, map, s);
}
STYLOS_AVX512 void testAvx512(const DepthMapFrame& f, const PreparedCells& cells, const std::int32_t* map,
                              const std::uint8_t* facing, float bias, bool cosine, Accumulator& sums,
                              DepthMapScratch& s)
{
    testImpl(f, cells, map, facing, bias, cosine, sums, s);
}
STYLOS_AVX512 void testOffLatticeAvx512(const DepthMapFrame& f, const PreparedCells& cells, const std::int32_t* map,
                                        const std::uint8_t* facing, float bias, bool cosine, Accumulator& sums,
                                        DepthMapScratch& s)
{
    testOffLatticeImpl<false>(f, cells, map, facing, bias, cosine, sums, s);
}
STYLOS_AVX512 void testTwoSidedAvx512(const DepthMapFrame& f, const PreparedCells& cells, const std::int32_t* map,
    const std::uint8_t* facing, float bias, bool cosine, Accumulator& sums, DepthMapScratch& s)
{
    testOffLatticeImpl<true>(f, cells, map, facing, bias, cosine, sums, s);
}
#endif

} // namespace

std::vector<DepthMapPasses> depthMapPassVariants()
{
    std::vector<DepthMapPasses> variants;
#ifdef STYLOS_DEPTHMAP_VARIANTS
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq") &&
        __builtin_cpu_supports("avx512bw"))
        variants.push_back({splatAvx512, testAvx512, testOffLatticeAvx512, testTwoSidedAvx512, "avx512"});
    if (__builtin_cpu_supports("avx2")) variants.push_back({splatAvx2, testAvx2, testOffLatticeAvx2, testTwoSidedAvx2, "avx2"});
#endif
    variants.push_back({splatPortable, testPortable, testOffLatticePortable, testTwoSidedPortable, "portable"});
    return variants;
}

} // namespace stylos::core::ao::detail
