#pragma once
/** @file
 * @brief A reference 3D skydome against the POINTS of a scan, not cells (issue 17): each point is a disc
 *        (its position, its estimated normal, a radius of the local spacing), and a ray from a receiver
 *        is blocked when it crosses another point's disc. The quality benchmark of the skydome on real
 *        scans (tests/benchmarks/AoPointReference.cpp, docs/benchmarks.md), where no analytic solid exists.
 *
 * Discs (discsFromPoints): the normal from estimateNormals (k = 16 PCA, normals/NormalEstimation.h), the
 * radius = radiusScale × the mean distance to the point's k nearest other points (default k = 8, scale 1):
 * neighbouring discs overlap, so a densely sampled surface is closed to rays. Optionally each centre is
 * projected onto the plane of its neighbours (projectionNeighbours): on a raw scan the noise (and the
 * misregistration of merged scans) puts neighbours a few spacings away above a point's tangent plane, where
 * they would stop its grazing rays (measured on the Happy Buddha: docs/benchmarks.md).
 * Rays (DiscGrid::blocked): a uniform grid of cells (CSR: offsets and disc indices), each disc listed in
 * every cell its bounding box touches; a 3D DDA (Amanatides and Woo) from the receiver; a disc blocks when
 * the ray meets its plane at t > 0 within its radius. Self-shadowing: discs whose centre lies within
 * `skip` of the receiver are ignored — the receiver's own disc and its neighbours' overlap it, and with
 * normals that differ by noise they would stop grazing rays of an open face; an offset of the ray's origin
 * along the normal would not (at grazing angles the neighbours' discs rise above any small offset). The
 * benchmark skips 2 spacings: relief narrower than that is below the sampling anyway.
 * Value (discSkydome): over unit directions d (ao/Directions.h), those with d·n > 0, the fraction not
 * blocked; two-sided (as AoOptions::twoSided), the same with −n for d·n < 0 and the larger of the two:
 * the side that looks into a closed surface sees almost nothing, so an estimated normal's sign does not
 * matter.
 *
 * Units: the cloud's (metres). Memory: 40 bytes per disc plus the grid (4 bytes per cell + 4 per listing).
 * Thread-safety: a built DiscGrid is read-only; discSkydome may run on many threads at once.
 * Failure modes: discsFromPoints: InvalidArgument (fewer than k + 1 points, sizes that disagree), the
 * normal estimation's errors.
 */
#include "stylos/core/util/Result.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace stylos::core::ao {

struct DiscCloud {
    std::vector<std::array<double, 3>> centres;
    std::vector<std::array<float, 3>> normals; ///< unit
    std::vector<float> radii;
    std::size_t size() const { return centres.size(); }
};

struct DiscCloudOptions {
    std::size_t neighbours = 8;  ///< k for the spacing (the point itself not counted)
    double radiusScale = 1.0;    ///< radius = scale × mean distance to the k nearest
    unsigned threads = 0;        ///< normal estimation; 0: hardware concurrency
    /** > 0: each disc's centre projected along its normal onto the plane through the centroid of its
     *  projectionNeighbours nearest points (itself included): the scanner's noise off, the relief kept
     *  (one step of a moving-least-squares projection). 0: the points as they are. */
    std::size_t projectionNeighbours = 0;
};

/** @brief Discs for @p positions (x y z interleaved): see the file comment. */
Result<DiscCloud> discsFromPoints(std::span<const double> positions, const DiscCloudOptions& options = {});

/** @brief t > 0 at which the ray o + t·d (d unit) crosses the disc (centre c, unit normal n, radius r). */
std::optional<double> rayHitsDisc(const std::array<double, 3>& o, const std::array<double, 3>& d,
                                  const std::array<double, 3>& c, const std::array<float, 3>& n, double r);

/** @brief The discs of a DiscCloud in a uniform grid for ray queries (the cloud must outlive it). */
class DiscGrid {
public:
    /** @p cell: the grid's cell edge; 0 chooses 4 × the median radius, widened so that the grid has at
     *  most 2^25 cells. */
    explicit DiscGrid(const DiscCloud& discs, double cell = 0.0);

    /** @brief Whether the ray o + t·d (t > 0, d unit) crosses a disc whose centre is farther than
     *         @p skip from @p o. */
    bool blocked(const std::array<double, 3>& o, const std::array<double, 3>& d, double skip) const;

    double cell() const { return m_cell; }
    const std::array<int, 3>& dimensions() const { return m_dims; }

private:
    const DiscCloud& m_discs;
    double m_cell = 1.0;
    std::array<double, 3> m_lo{};
    std::array<int, 3> m_dims{1, 1, 1};
    std::vector<std::uint32_t> m_begin; ///< per cell (x fastest), then one past the end
    std::vector<std::uint32_t> m_items; ///< disc indices
};

/**
 * @brief The visible-sky fraction at @p p with unit normal @p n over @p directions (unit): see the file
 *        comment. 0 when no direction lies in front (or, two-sided, behind).
 */
double discSkydome(const DiscGrid& grid, const std::array<double, 3>& p, const std::array<double, 3>& n,
                   std::span<const std::array<double, 3>> directions, double skip, bool twoSided = true);

} // namespace stylos::core::ao
