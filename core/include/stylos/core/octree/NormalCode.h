#pragma once
/** @file
 * @brief Quantised unit normals for the packed octree: the paper's 15-bit code (Duguet et al.,
 *        VAST 2004: octant + 6 levels of triangular subdivision of the octahedron face) and the 16-bit
 *        octahedral map (Meyer et al. 2010, Cigolle et al. 2014). Pure functions, thread-safe.
 *
 * Errors measured over 1 M uniformly random unit vectors (seed 1, `measureNormalCodeError`; see
 * tests/core/NormalCodeTest.cpp, `NormalCode.ErrorTable`):
 *   - Paper15:      mean 0.474°, max 1.257°
 *   - Octahedral16: mean 0.317°, max 0.639° (precise encoding; round-to-nearest: mean 0.340°,
 *                   max 0.950°). The better code of the two, with one bit more.
 *
 * Failure modes: none reported. A zero vector, or one with a NaN or infinite component, encodes as +Z
 * (so a missing normal is a defined, valid code). Input need not be unit length; it is rescaled by its
 * largest component first, so neither tiny nor huge finite vectors under- or overflow (denormal
 * components keep only their few significant bits, so their direction is coarser).
 */
#include <array>
#include <cstddef>
#include <cstdint>

namespace stylos::core::octree {

/** @brief The two normal codes. */
enum class NormalCodeKind : std::uint8_t {
    /**
     * 15 bits (bit 15 is always 0, ignored on decode): bits 14..12 the octant (bit 12 set for x < 0,
     * bit 13 for y < 0, bit 14 for z < 0; −0 counts as positive), then 6 levels of 2 bits, level 0 in
     * bits 11..10: 0, 1, 2 the sub-triangle at the face's x, y, z corner, 3 the central one. The face
     * x+y+z = 1 is subdivided in the plane (midpoints); decode is the centroid of the final triangle,
     * normalised. code → decode → encode is the identity on all 2^15 codes.
     */
    Paper15,
    /**
     * 16 bits: high byte u, low byte v of the folded octahedral map, each on the grid k/126 − 1,
     * k in [0, 252] (bytes above 252 decode as 252). The grid steps by 1/126 so that the axes and the
     * octant diagonals (±1/3, ±2/3 on the map) are exact. Encoding keeps, of the 4 grid points around
     * the projection, the one whose decoded vector is nearest in angle ("precise" variant).
     */
    Octahedral16,
};

/** @brief Number of distinct codes of a kind: 2^15 for Paper15, 2^16 for Octahedral16. */
std::size_t normalCodeCount(NormalCodeKind kind);

/** @brief Code of the direction (x, y, z); need not be unit. Zero or non-finite input gives +Z's code. */
std::uint16_t encodeNormal(NormalCodeKind kind, float x, float y, float z);

/** @brief Unit vector of a code (computed; for bulk decoding use `normalDecodeTable`). */
std::array<float, 3> decodeNormal(NormalCodeKind kind, std::uint16_t code);

/**
 * @brief Decoded unit vectors of every code, indexed by code: `normalCodeCount(kind)` entries (index
 *        Paper15 codes with `code & 0x7FFF`). Built once on first use (thread-safe static
 *        initialisation), then shared and immutable; 384 KiB for Paper15, 768 KiB for Octahedral16.
 */
const std::array<float, 3>* normalDecodeTable(NormalCodeKind kind);

/** @brief Angular error of a code over random directions, in radians. */
struct NormalCodeError {
    double meanRadians = 0;
    double maxRadians = 0;
};

/**
 * @brief Mean and max angle between v and decode(encode(v)) over `samples` uniformly random unit
 *        vectors (3 Gaussians by Box–Muller on std::mt19937_64(seed), normalised: deterministic on
 *        every platform). Zero samples give zero errors.
 */
NormalCodeError measureNormalCodeError(NormalCodeKind kind, std::size_t samples, std::uint64_t seed);

/**
 * @brief Octahedral16 with plain round-to-nearest quantisation instead of the precise search; kept
 *        to document (and test) why the precise variant is the default. Same code layout.
 */
std::uint16_t encodeOctahedral16Rounded(float x, float y, float z);

} // namespace stylos::core::octree
