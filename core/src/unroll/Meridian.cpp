#include "stylos/core/unroll/Meridian.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace stylos::core::unroll {

namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

/** The unit normal of the direction @p d: a quarter turn toward +r, (−dr, dt) / |d|. */
Eigen::Vector2d segmentNormal(const Eigen::Vector2d& d) { return Eigen::Vector2d(-d.y(), d.x()).normalized(); }

Error invalid(const std::string& problem) { return Error{ErrorCode::InvalidArgument, "meridian: " + problem}; }

/** Roots of a·λ² + b·λ + c = 0 (a linear or constant equation when a is negligible). */
int solveQuadratic(double a, double b, double c, double scale, double roots[2])
{
    if (std::abs(a) <= 1e-12 * scale) {
        if (std::abs(b) <= 1e-300) return 0;
        roots[0] = -c / b;
        return 1;
    }
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return 0;
    const double root = std::sqrt(discriminant);
    // The numerically stable pair: q = −(b + sign(b)·√Δ)/2, λ = q/a and c/q.
    const double q = -0.5 * (b + std::copysign(root, b));
    roots[0] = q / a;
    if (q == 0.0) return 1;
    roots[1] = c / q;
    return 2;
}

} // namespace

Result<Meridian> Meridian::create(std::vector<Eigen::Vector2d> vertices, double reach)
{
    if (vertices.size() < 2) return invalid("needs at least 2 vertices, got " + std::to_string(vertices.size()));
    if (!std::isfinite(reach) || reach <= 0.0) return invalid("the reach must be a positive length");
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Eigen::Vector2d& v = vertices[i];
        if (!std::isfinite(v.x()) || !std::isfinite(v.y()))
            return invalid("vertex " + std::to_string(i) + " is not finite");
        if (v.y() < 0.0) return invalid("vertex " + std::to_string(i) + " has a negative radius");
        if (i > 0 && v == vertices[i - 1])
            return invalid("vertices " + std::to_string(i - 1) + " and " + std::to_string(i) + " coincide");
    }
    Meridian m;
    m.m_vertices = std::move(vertices);
    m.m_reach = reach;
    const std::size_t n = m.m_vertices.size(), segments = n - 1;
    std::vector<Eigen::Vector2d> segmentNormals(segments);
    m.m_arc.assign(n, 0.0);
    std::vector<double> lengths(segments);
    for (std::size_t k = 0; k < segments; ++k) {
        const Eigen::Vector2d d = m.m_vertices[k + 1] - m.m_vertices[k];
        segmentNormals[k] = segmentNormal(d);
        lengths[k] = d.norm();
        m.m_arc[k + 1] = m.m_arc[k] + lengths[k];
    }
    m.m_vertexNormals.resize(n);
    m.m_vertexNormals[0] = segmentNormals[0];
    m.m_vertexNormals[n - 1] = segmentNormals[segments - 1];
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const Eigen::Vector2d sum = segmentNormals[i - 1] + segmentNormals[i];
        // A full reversal (a 180° turn) has no bisector: keep the incoming segment's normal.
        m.m_vertexNormals[i] = sum.norm() > 1e-9 ? sum.normalized() : segmentNormals[i - 1];
    }

    // Lookup grid: cells about the median segment length (at least reach / 8 so it stays small).
    std::vector<double> sorted = lengths;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(segments / 2), sorted.end());
    Eigen::Vector2d lo = m.m_vertices[0], hi = m.m_vertices[0];
    for (const Eigen::Vector2d& v : m.m_vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    lo.array() -= reach;
    hi.array() += reach;
    const double extent = std::max(hi.x() - lo.x(), hi.y() - lo.y());
    m.m_cell = std::max({sorted[segments / 2], reach / 8.0, extent / 2048.0});
    m.m_gridOrigin = lo;
    m.m_columns = std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / m.m_cell)));
    m.m_rows = std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / m.m_cell)));
    const std::size_t cells = std::size_t(m.m_columns) * std::size_t(m.m_rows);
    std::vector<std::vector<std::uint32_t>> lists(cells);
    for (std::size_t k = 0; k < segments; ++k) {
        const Eigen::Vector2d a = m.m_vertices[k], b = m.m_vertices[k + 1];
        // The end segments also serve points beyond the ends, along their tangent, up to reach.
        Eigen::Vector2d sLo = a.cwiseMin(b), sHi = a.cwiseMax(b);
        const Eigen::Vector2d tangent = (b - a) / lengths[k];
        if (k == 0) {
            sLo = sLo.cwiseMin(a - reach * tangent);
            sHi = sHi.cwiseMax(a - reach * tangent);
        }
        if (k + 1 == segments) {
            sLo = sLo.cwiseMin(b + reach * tangent);
            sHi = sHi.cwiseMax(b + reach * tangent);
        }
        const int c0 = std::clamp(int(std::floor((sLo.x() - reach - lo.x()) / m.m_cell)), 0, m.m_columns - 1);
        const int c1 = std::clamp(int(std::floor((sHi.x() + reach - lo.x()) / m.m_cell)), 0, m.m_columns - 1);
        const int r0 = std::clamp(int(std::floor((sLo.y() - reach - lo.y()) / m.m_cell)), 0, m.m_rows - 1);
        const int r1 = std::clamp(int(std::floor((sHi.y() + reach - lo.y()) / m.m_cell)), 0, m.m_rows - 1);
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) lists[std::size_t(r) * std::size_t(m.m_columns) + std::size_t(c)].push_back(std::uint32_t(k));
    }
    m.m_cellStart.assign(cells + 1, 0);
    for (std::size_t i = 0; i < cells; ++i) m.m_cellStart[i + 1] = m.m_cellStart[i] + std::uint32_t(lists[i].size());
    m.m_cellSegments.reserve(m.m_cellStart.back());
    for (const auto& list : lists) m.m_cellSegments.insert(m.m_cellSegments.end(), list.begin(), list.end());
    return m;
}

Eigen::Vector2d Meridian::interpolatedNormal(std::size_t k, double lambda) const
{
    const std::size_t last = m_vertices.size() - 2;
    if ((k == 0 && lambda < 0.0) || (k == last && lambda > 1.0)) // beyond an end: the end's own normal
        return k == 0 && lambda < 0.0 ? m_vertexNormals.front() : m_vertexNormals.back();
    return (m_vertexNormals[k] + lambda * (m_vertexNormals[k + 1] - m_vertexNormals[k])).normalized();
}

std::optional<std::pair<double, double>> Meridian::solveOnSegment(std::size_t k, const Eigen::Vector2d& p) const
{
    const Eigen::Vector2d a = m_vertices[k], d = m_vertices[k + 1] - a;
    const Eigen::Vector2d na = m_vertexNormals[k], e = m_vertexNormals[k + 1] - na;
    const Eigen::Vector2d w = p - a;
    const std::size_t last = m_vertices.size() - 2;
    const bool openStart = k == 0, openEnd = k == last;
    std::optional<std::pair<double, double>> best;
    // The distance to the polyline itself: past an end, to the end vertex.
    auto consider = [&](double lambda) {
        const Eigen::Vector2d nearest = a + std::clamp(lambda, 0.0, 1.0) * d;
        const double distance = (p - nearest).norm();
        if (!best || distance < best->second) best = std::make_pair(lambda, distance);
    };
    // Within the segment: cross(w − λd, na + λe) = 0 → −cross(d, e)·λ² + (cross(w, e) − cross(d, na))·λ + cross(w, na) = 0.
    double roots[2];
    const double scale = d.squaredNorm() + w.squaredNorm();
    const int count = solveQuadratic(-cross2(d, e), cross2(w, e) - cross2(d, na), cross2(w, na), scale, roots);
    constexpr double slack = 1e-12;
    for (int i = 0; i < count; ++i)
        if (roots[i] >= -slack && roots[i] <= 1.0 + slack) consider(std::clamp(roots[i], 0.0, 1.0));
    // Beyond an end, along the tangent with the end's constant normal: the foot is the orthogonal projection.
    const double along = w.dot(d) / d.squaredNorm();
    if (openStart && along < 0.0) consider(along);
    if (openEnd && along > 1.0) consider(along);
    return best;
}

std::optional<MeridianCoords> Meridian::project(double t, double r) const
{
    const Eigen::Vector2d p(t, r);
    const int c = int(std::floor((t - m_gridOrigin.x()) / m_cell));
    const int row = int(std::floor((r - m_gridOrigin.y()) / m_cell));
    if (c < 0 || row < 0 || c >= m_columns || row >= m_rows) return std::nullopt;
    const std::size_t cell = std::size_t(row) * std::size_t(m_columns) + std::size_t(c);
    std::size_t bestSegment = 0;
    double bestLambda = 0.0, bestDistance = std::numeric_limits<double>::infinity();
    for (std::uint32_t i = m_cellStart[cell]; i < m_cellStart[cell + 1]; ++i) {
        const std::size_t k = m_cellSegments[i];
        const auto hit = solveOnSegment(k, p);
        if (hit && hit->second < bestDistance) {
            bestDistance = hit->second;
            bestLambda = hit->first;
            bestSegment = k;
        }
    }
    if (!(bestDistance <= m_reach)) return std::nullopt;
    const Eigen::Vector2d a = m_vertices[bestSegment], d = m_vertices[bestSegment + 1] - a;
    const Eigen::Vector2d foot = a + bestLambda * d;
    const double length = m_arc[bestSegment + 1] - m_arc[bestSegment];
    return MeridianCoords{m_arc[bestSegment] + bestLambda * length,
                          (p - foot).dot(interpolatedNormal(bestSegment, bestLambda))};
}

std::pair<std::size_t, double> Meridian::locate(double v) const
{
    const std::size_t segments = m_vertices.size() - 1;
    // First vertex with arc length > v, minus one: the segment holding v.
    const auto it = std::upper_bound(m_arc.begin(), m_arc.end(), v);
    std::size_t k = it == m_arc.begin() ? 0 : std::size_t(it - m_arc.begin()) - 1;
    k = std::min(k, segments - 1);
    return {k, (v - m_arc[k]) / (m_arc[k + 1] - m_arc[k])};
}

Eigen::Vector2d Meridian::point(double v, double h) const
{
    const auto [k, lambda] = locate(v);
    const Eigen::Vector2d foot = m_vertices[k] + lambda * (m_vertices[k + 1] - m_vertices[k]);
    return foot + h * interpolatedNormal(k, lambda);
}

Eigen::Vector2d Meridian::normalAt(double v) const
{
    const auto [k, lambda] = locate(v);
    return interpolatedNormal(k, lambda);
}

} // namespace stylos::core::unroll
