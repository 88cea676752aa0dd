#include "stylos/core/octree/CellPick.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>

namespace stylos::core::octree {

namespace {

using Vec3 = std::array<double, 3>;

struct Node {
    int level = 0;
    std::uint64_t index = 0;
    std::array<std::uint32_t, 3> coords{};
};

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double maxAbs(const Vec3& v) { return std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])}); }

/**
 * Branch-and-bound descent shared by both queries. A Query provides `target` (level), `bound(node)`
 * (a lower bound of the key of any target cell under the node, +infinity when none can qualify, and
 * such nodes are skipped),
 * `prunes(bound)` (no cell with that bound can beat the best so far) and `offer(node)` (a target cell).
 * Children are visited in increasing bound, so the best answer tends to come first and prune the rest.
 */
template <typename Query>
class Descent {
public:
    Descent(const PackedOctree& octree, Query& query) : m_octree(octree), m_query(query) {}

    void run(const Node& node)
    {
        if (node.level == m_query.target) {
            m_query.offer(node);
            return;
        }
        const std::uint8_t mask = m_octree.mask(node.level, node.index);
        const std::uint64_t first = m_octree.firstChild(node.level, node.index);
        std::array<std::pair<double, Node>, 8> children;
        std::size_t n = 0;
        unsigned rank = 0;
        for (unsigned slot = 0; slot < 8; ++slot) {
            if ((mask & (1u << slot)) == 0) continue;
            Node child;
            child.level = node.level + 1;
            child.index = first + rank++;
            child.coords = {2 * node.coords[0] + (slot & 1u), 2 * node.coords[1] + ((slot >> 1) & 1u),
                            2 * node.coords[2] + ((slot >> 2) & 1u)};
            const double b = m_query.bound(child);
            if (b == std::numeric_limits<double>::infinity() || m_query.prunes(b)) continue;
            std::size_t i = n++;
            for (; i > 0 && children[i - 1].first > b; --i) children[i] = children[i - 1];
            children[i] = {b, child};
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (m_query.prunes(children[i].first)) break;
            run(children[i].second);
        }
    }

private:
    const PackedOctree& m_octree;
    Query& m_query;
};

/** What both queries share: the target level, the box of target centres under a cell, a tolerance. */
class QueryBase {
public:
    QueryBase(const PackedOctree& octree, int level, const Vec3& query)
        : m_octree(octree), m_box(octree.box())
    {
        assert(level >= -1 && level <= octree.depth() && "pick: level must be -1 or 0..depth");
        target = level < 0 ? octree.depth() : level;
        m_targetHalf = 0.5 * m_box.cellSize(target);
        m_eps = 1e-11 * (m_box.size + maxAbs(m_box.origin) + maxAbs(query));
    }

    int target = 0;

protected:
    /** Corners of the box holding the centres of the target cells under @p node, minus @p from. */
    void centreBox(const Node& node, const Vec3& from, Vec3& lo, Vec3& hi) const
    {
        const double size = m_box.cellSize(node.level);
        for (std::size_t a = 0; a < 3; ++a) {
            const double base = m_box.origin[a] - from[a];
            lo[a] = base + double(node.coords[a]) * size + m_targetHalf;
            hi[a] = base + double(node.coords[a] + 1) * size - m_targetHalf;
        }
    }

    Vec3 centre(const Node& node) const
    {
        return m_box.cellCentre(node.level, node.coords[0], node.coords[1], node.coords[2]);
    }

    const PackedOctree& m_octree;
    const RootBox& m_box;
    double m_targetHalf = 0;
    double m_eps = 0;
};

class NearestQuery : public QueryBase {
public:
    NearestQuery(const PackedOctree& octree, int level, const Vec3& point, double maxDistance)
        : QueryBase(octree, level, point), m_point(point), m_limit(maxDistance)
    {
    }

    double bound(const Node& node) const
    {
        Vec3 lo, hi;
        centreBox(node, m_point, lo, hi);
        double d2 = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            const double d = lo[a] > 0 ? lo[a] : (hi[a] < 0 ? -hi[a] : 0.0);
            d2 += d * d;
        }
        return std::sqrt(d2);
    }

    bool prunes(double bound) const { return bound > m_limit + m_eps; }

    void offer(const Node& node)
    {
        const Vec3 c = centre(node);
        const double dx = c[0] - m_point[0], dy = c[1] - m_point[1], dz = c[2] - m_point[2];
        const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
        if (!(d <= m_limit)) return;
        if (m_found && d == m_limit && node.index >= m_bestNode.index) return;
        m_found = true;
        m_limit = d; // from now on only as near or nearer can win
        m_bestNode = node;
    }

    std::optional<PickedCell> answer() const
    {
        if (!m_found) return std::nullopt;
        return PickedCell{m_octree.cell(m_bestNode.level, m_bestNode.index, m_bestNode.coords), m_limit};
    }

private:
    Vec3 m_point;
    double m_limit; ///< maxDistance, then the best distance found
    bool m_found = false;
    Node m_bestNode;
};

class RayQuery : public QueryBase {
public:
    RayQuery(const PackedOctree& octree, int level, const Vec3& origin, const Vec3& direction, double r0, double k)
        : QueryBase(octree, level, origin), m_origin(origin), m_r0(r0), m_k(k)
    {
        const double len = std::sqrt(dot(direction, direction));
        assert(len > 0 && std::isfinite(len) && "pickRay(): direction must be non-zero and finite");
        m_dir = {direction[0] / len, direction[1] / len, direction[2] / len};
    }

    double bound(const Node& node) const
    {
        Vec3 lo, hi;
        centreBox(node, m_origin, lo, hi);
        double tmin = 0, tmax = 0;
        Vec3 m;
        double rho2 = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            const double p = m_dir[a] * lo[a], q = m_dir[a] * hi[a];
            tmin += std::min(p, q);
            tmax += std::max(p, q);
            m[a] = 0.5 * (lo[a] + hi[a]);
            rho2 += 0.25 * (hi[a] - lo[a]) * (hi[a] - lo[a]);
        }
        constexpr double none = std::numeric_limits<double>::infinity();
        if (tmax < -m_eps) return none; // entirely behind the origin
        // Distance from the line to any point of the box ≥ (distance to the box's centre) − half diagonal.
        const double tm = dot(m, m_dir);
        const Vec3 w{m[0] - tm * m_dir[0], m[1] - tm * m_dir[1], m[2] - tm * m_dir[2]};
        const double perp = std::sqrt(dot(w, w)) - std::sqrt(rho2);
        if (perp > m_r0 + m_k * std::max(tmax, 0.0) + m_eps) return none;
        return std::max(tmin, 0.0);
    }

    bool prunes(double bound) const { return bound > m_bestT + m_eps; }

    void offer(const Node& node)
    {
        const Vec3 c = centre(node);
        const Vec3 v{c[0] - m_origin[0], c[1] - m_origin[1], c[2] - m_origin[2]};
        const double t = dot(v, m_dir);
        if (!(t >= 0)) return;
        const Vec3 w{v[0] - t * m_dir[0], v[1] - t * m_dir[1], v[2] - t * m_dir[2]};
        if (!(std::sqrt(dot(w, w)) <= m_r0 + m_k * t)) return;
        if (m_found && (t > m_bestT || (t == m_bestT && node.index >= m_bestNode.index))) return;
        m_found = true;
        m_bestT = t;
        m_bestNode = node;
    }

    std::optional<PickedCell> answer() const
    {
        if (!m_found) return std::nullopt;
        return PickedCell{m_octree.cell(m_bestNode.level, m_bestNode.index, m_bestNode.coords), m_bestT};
    }

private:
    Vec3 m_origin;
    Vec3 m_dir{};
    double m_r0;
    double m_k;
    bool m_found = false;
    double m_bestT = std::numeric_limits<double>::infinity();
    Node m_bestNode;
};

template <typename Query>
std::optional<PickedCell> search(const PackedOctree& octree, Query& query)
{
    const Node root;
    const double b = query.bound(root);
    if (b == std::numeric_limits<double>::infinity() || query.prunes(b)) return std::nullopt;
    Descent<Query>(octree, query).run(root);
    return query.answer();
}

} // namespace

std::optional<PickedCell> nearestCell(const PackedOctree& octree, const std::array<double, 3>& point,
                                      double maxDistance, int level)
{
    if (!(maxDistance >= 0)) return std::nullopt;
    NearestQuery query(octree, level, point, maxDistance);
    return search(octree, query);
}

std::optional<PickedCell> pickRay(const PackedOctree& octree, const std::array<double, 3>& origin,
                                  const std::array<double, 3>& direction, double radiusAtOrigin,
                                  double radiusPerMetre, int level)
{
    assert(radiusAtOrigin >= 0 && radiusPerMetre >= 0 && "pickRay(): radii must be non-negative");
    RayQuery query(octree, level, origin, direction, radiusAtOrigin, radiusPerMetre);
    return search(octree, query);
}

} // namespace stylos::core::octree
