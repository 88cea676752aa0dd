#pragma once
/** @file
 * @brief A point made ready for insertion into the construction octree: its leaf coordinates, its
 *        normal normalised as the leaf averaging uses it, and the normal code of that normal (the code a
 *        leaf takes from its first point). Builders prepare points on reader threads, so the costly
 *        quantisation and encoding stay off the thread that inserts in input order.
 *        Pure functions, thread-safe.
 */
#include "stylos/core/octree/NormalCode.h"
#include "stylos/core/octree/NormalEncoder.h"
#include "stylos/core/octree/RootBox.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace stylos::core::octree {

struct PreparedPoint {
    std::array<std::uint32_t, 3> coords{};   ///< integer coordinates at the leaf level (RootBox::quantise)
    std::array<float, 3> normal{};           ///< unitNormal() of the input normal
    std::uint16_t firstCode = 0;             ///< encodeNormal(kind, normal)
    std::array<std::uint8_t, 3> colour{};    ///< input RGB (0 when the source has no colour)
};

/**
 * @brief The input normal as the leaf averaging uses it (the shared definition): normalised in float,
 *        length = sqrt((x·x + y·y) + z·z) computed in float and each component divided by it;
 *        (0, 0, 0) when that length is 0 or not finite.
 */
inline std::array<float, 3> unitNormal(float x, float y, float z)
{
    const float length = std::sqrt(x * x + y * y + z * z);
    if (!(length > 0.0f) || !std::isfinite(length)) return {0.0f, 0.0f, 0.0f};
    return {x / length, y / length, z / length};
}

/**
 * @brief Prepares the point at @p position (x y z, metres) with normal @p normal (x y z) and colour
 *        @p rgb (may be null) for an octree of @p depth in @p box whose normal code is @p encode's.
 */
inline PreparedPoint preparePoint(const RootBox& box, int depth, const NormalEncoder& encode, const double* position,
                                  const float* normal, const std::uint8_t* rgb)
{
    PreparedPoint p;
    p.coords = box.quantise(position, depth);
    p.normal = unitNormal(normal[0], normal[1], normal[2]);
    p.firstCode = encode(p.normal[0], p.normal[1], p.normal[2]);
    if (rgb) p.colour = {rgb[0], rgb[1], rgb[2]};
    return p;
}

/** @brief The same with a one-off encoder (tests). */
inline PreparedPoint preparePoint(const RootBox& box, int depth, NormalCodeKind kind, const double* position,
                                  const float* normal, const std::uint8_t* rgb)
{
    return preparePoint(box, depth, NormalEncoder(kind), position, normal, rgb);
}

} // namespace stylos::core::octree
