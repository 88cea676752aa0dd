#pragma once
/** @file
 * @brief The octree's root cube and the integer cell grid inside it. The root box is the only geometry
 *        an octree stores: every cell's centre and size follow from it, its level and its integer
 *        coordinates. Positions stay in double until they are made relative to this box.
 *
 * Level l divides the cube into 2^l cells per axis; a cell at level l has integer coordinates
 * (ix, iy, iz) in [0, 2^l). The cell of a point at level l is its depth-L cell shifted right by L − l.
 * Units: metres. Pure value type, thread-safe.
 */
#include <array>
#include <cstdint>

namespace stylos::core::octree {

/** @brief Deepest level an octree may have (integer coordinates stay within 21 bits per axis). */
inline constexpr int MaxOctreeDepth = 21;
/** @brief Shallowest level an octree may have (a root with children). */
inline constexpr int MinOctreeDepth = 1;

struct RootBox {
    std::array<double, 3> origin{0, 0, 0};  ///< minimum corner, metres
    double size = 1;                        ///< edge length of the cube, metres (> 0)

    bool operator==(const RootBox&) const = default;

    /**
     * @brief The cube around axis-aligned bounds {minX, minY, minZ, maxX, maxY, maxZ}: edge = the
     *        largest extent (1 m when every extent is 0), centred on the bounds' centre. Deterministic:
     *        every builder computes the same box from the same bounds.
     */
    static RootBox enclosing(const std::array<double, 6>& bounds);

    /** @brief Edge length of a cell at @p level. */
    double cellSize(int level) const;

    /**
     * @brief Integer coordinates of the depth-@p depth cell holding @p p: floor((p − origin) / size ·
     *        2^depth), clamped to [0, 2^depth − 1] (so points on the maximum faces, and the rare point a
     *        rounding puts outside, land in the last cell). The one quantisation every builder uses.
     */
    std::array<std::uint32_t, 3> quantise(const double* p, int depth) const;

    /** @brief Centre of the cell (ix, iy, iz) at @p level. */
    std::array<double, 3> cellCentre(int level, std::uint32_t ix, std::uint32_t iy, std::uint32_t iz) const;
};

/**
 * @brief Child slot (0..7) of the level-(l+1) cell under its parent: bit 0 from x, bit 1 from y,
 *        bit 2 from z. Child tables hold a cell's children in increasing slot order.
 */
inline unsigned childSlot(std::uint32_t ix, std::uint32_t iy, std::uint32_t iz)
{
    return (ix & 1u) | ((iy & 1u) << 1) | ((iz & 1u) << 2);
}

} // namespace stylos::core::octree
