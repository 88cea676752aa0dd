#pragma once
/** @file
 * @brief Private to core/normals: how the tiled file driver cuts a cloud into tiles, and how wide each
 *        tile's halo must be. Built from a uniform random sample of the cloud (pass 1), so it never
 *        needs the whole cloud in memory. Units: metres. Immutable once built; thread-safe to read.
 */
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace stylos::core::normals::detail {

/** @brief An axis-aligned box; sides on the outside of the cloud are ±infinity. */
struct TileBox {
    std::array<double, 3> lo;
    std::array<double, 3> hi;
};

/**
 * @brief Estimates the halo width for k-neighbourhoods, in metres, from a uniform sample of
 *        @p sample.size()/3 points drawn from a cloud of @p totalPoints points.
 *
 * The k-th neighbour distances r are measured within the sample, together with the distances at
 * a fifth of k, whose ratio gives the cloud's local dimension D (2 for a surface scan); at full density
 * the distances shrink by (sample/total)^(1/D). The margin is 1.5 × the 99th percentile of the scaled r
 * (the percentile covers uneven density, the factor the error of the scaling), so the halo covers the
 * neighbourhoods of all but isolated points (those are counted as truncated).
 * Returns +infinity when the sample is too small to say (fewer than 2k points).
 */
double estimateHaloMargin(std::span<const double> sample, std::uint64_t totalPoints, std::size_t k);

/**
 * @brief A partition of space into 2^levels tiles with about equal numbers of points: each cell is
 *        split at the sample median along its longest side (a k-d partition, so the grid follows the
 *        longest axes of the cloud). Every point belongs to exactly one tile.
 */
class TilePlan {
public:
    /** @param bounds lower x y z, upper x y z of the cloud; @p margin the halo width. */
    TilePlan(std::span<const double> sample, const std::array<double, 6>& bounds, unsigned levels, double margin);

    std::size_t size() const { return m_boxes.size(); }
    const TileBox& box(std::size_t tile) const { return m_boxes[tile]; }
    double margin() const { return m_margin; }

    /** The tile that owns point @p p (x y z). */
    std::uint32_t ownTile(const double* p) const;
    /** Tiles other than the owner whose box grown by the margin contains @p p; replaces @p out. */
    void haloTiles(const double* p, std::vector<std::uint32_t>& out) const;

private:
    struct Split {
        int axis;            ///< −1 for a leaf
        double value;        ///< points with p[axis] < value go low
        std::uint32_t low;   ///< node indices, or the tile index of a leaf (in low)
        std::uint32_t high;
    };
    std::uint32_t build(std::vector<double>& sample, std::size_t begin, std::size_t end, TileBox box,
                        unsigned depth, unsigned levels, const std::array<double, 6>& bounds);
    void collect(std::uint32_t node, const double* p, std::uint32_t own, std::vector<std::uint32_t>& out) const;

    std::vector<Split> m_nodes;
    std::vector<TileBox> m_boxes;
    double m_margin = 0;
};

} // namespace stylos::core::normals::detail
