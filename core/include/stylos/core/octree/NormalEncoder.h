#pragma once
/** @file
 * @brief encodeNormal() bit for bit, faster, for the octree builders' hot loops: encode() runs the
 *        Octahedral16 search on two normals at once with packed SSE2 operations and no branches (the
 *        same double operations in the same order, and packed SSE2 rounds as scalar SSE2 does, so the
 *        same codes); the grid values are tabulated. Paper15 forwards to encodeNormal(). tests/core/NormalEncoderTest.cpp checks the equality on every code's direction
 *        and on millions of random and degenerate vectors.
 *        Immutable once constructed: thread-safe.
 */
#include "stylos/core/octree/NormalCode.h"

#include <array>
#include <cstdint>
#include <span>

namespace stylos::core::octree {

class NormalEncoder {
public:
    explicit NormalEncoder(NormalCodeKind kind);

    /** @brief encodeNormal(kind, x, y, z). */
    std::uint16_t operator()(float x, float y, float z) const;
    /** @brief codes[i] = encodeNormal(kind, normals[i]) for every i (two at a time, branch-free, where
     *         SSE2 is available). @p codes has the size of @p normals. */
    void encode(std::span<const std::array<float, 3>> normals, std::span<std::uint16_t> codes) const;
    NormalCodeKind kind() const { return m_kind; }

private:
    std::uint16_t octahedral(double x, double y, double z) const;
    void encodePair(const std::array<float, 3>& a, const std::array<float, 3>& b, std::uint16_t& codeA,
                    std::uint16_t& codeB) const;

    NormalCodeKind m_kind;
    std::array<double, 253> m_grid{};   ///< k / 126 − 1 as NormalCode.cpp computes it
};

} // namespace stylos::core::octree
