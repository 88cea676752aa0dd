#pragma once
/** @file
 * @brief The meridian of a general surface of revolution: a polyline in the (t, r) half-plane
 *        (t along the axis, r ≥ 0 the distance from it) with a smoothly interpolated normal field, so
 *        that every point near it has exact meridian coordinates (v, h) and back.
 *
 * Vertices are ordered so that the outside of the surface (away from the material) lies to the LEFT
 * of the direction of travel in the (t, r) plane, i.e. from the bottom (low t) to the top for the
 * outer surface of a drum or an omphalos. Segment k runs from vertex k to k + 1; its unit normal is
 * the direction (dt, dr) turned a quarter turn toward +r: n = (−dr, dt) / length (outward for an outer
 * surface). A vertex normal is the normalised sum of the unit normals of its two segments (the
 * segment's own normal at the two ends). Along a segment, at parameter λ ∈ [0, 1], the foot point is
 * F(λ) = A + λ(B − A) and the normal n(λ) = normalise(nA + λ(nB − nA)).
 *
 * Coordinates of a point P = (t, r): the (λ, segment) for which P − F(λ) is parallel to n(λ) (a
 * quadratic in λ per segment), taken on the segment where |P − F(λ)| is smallest; then
 *     v = arc length from vertex 0 to F(λ)   (metres),
 *     h = (P − F(λ)) · n(λ)                   (metres, positive outward).
 * Before vertex 0 and past the last vertex the end segments extend along their tangent with their
 * own constant normal (v < 0 or v > length()). point(v, h) = F + h·n inverts project() exactly (up to
 * rounding) wherever the normal field does not fold, i.e. within the local radius of curvature.
 *
 * Units: metres. Thread-safety: immutable once created; concurrent project() calls are safe.
 * Cost: project() looks up a grid of segments (cell ~ the median segment length) and solves one
 * quadratic per segment near the point: O(1) for a well-sampled meridian.
 */
#include "stylos/core/util/Result.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace stylos::core::unroll {

/** @brief Position on a surface of revolution: along the meridian and off the surface. */
struct MeridianCoords {
    double v = 0.0; ///< arc length along the meridian (or axial position for a cylinder/cone), metres
    double h = 0.0; ///< height above the surface, metres, positive outward
};

class Meridian {
public:
    /**
     * @brief A meridian through @p vertices ((t, r) pairs, metres).
     * @param reach how far from the polyline project() must find points, metres (> 0): sizes the
     *        lookup grid; points farther away get no coordinates.
     * @return the meridian, or InvalidArgument when there are fewer than 2 vertices, a coordinate is
     *         not finite, r < 0, or two consecutive vertices coincide.
     */
    static Result<Meridian> create(std::vector<Eigen::Vector2d> vertices, double reach);

    const std::vector<Eigen::Vector2d>& vertices() const { return m_vertices; }
    /** Total arc length, metres. */
    double length() const { return m_arc.back(); }
    double reach() const { return m_reach; }

    /** @brief (v, h) of the point (t, r) (see the file comment); nullopt when its distance to the polyline
     *         (past an end: to the end vertex) exceeds reach(). */
    std::optional<MeridianCoords> project(double t, double r) const;
    /** @brief The (t, r) point at meridian coordinates (v, h); any v (extrapolated past the ends). */
    Eigen::Vector2d point(double v, double h) const;
    /** @brief The unit normal n(v) of the interpolated field. */
    Eigen::Vector2d normalAt(double v) const;

private:
    Meridian() = default;
    /** Segment holding arc length v (clamped to the first or last), and λ on it (not clamped). */
    std::pair<std::size_t, double> locate(double v) const;
    /** Best (λ, |distance|) of P on segment k, λ restricted to the segment (or its extension at an end). */
    std::optional<std::pair<double, double>> solveOnSegment(std::size_t k, const Eigen::Vector2d& p) const;
    Eigen::Vector2d interpolatedNormal(std::size_t k, double lambda) const;

    std::vector<Eigen::Vector2d> m_vertices;
    std::vector<Eigen::Vector2d> m_vertexNormals;
    std::vector<double> m_arc; ///< arc length at each vertex (m_arc[0] = 0)
    double m_reach = 0.0;
    // Lookup grid over the (t, r) bounds grown by reach: each cell lists the segments whose box
    // (grown by reach) overlaps it.
    Eigen::Vector2d m_gridOrigin = Eigen::Vector2d::Zero();
    double m_cell = 1.0;
    int m_columns = 0; ///< cells along t
    int m_rows = 0;    ///< cells along r
    std::vector<std::uint32_t> m_cellStart; ///< m_columns × m_rows + 1 offsets into m_cellSegments
    std::vector<std::uint32_t> m_cellSegments;
};

} // namespace stylos::core::unroll
