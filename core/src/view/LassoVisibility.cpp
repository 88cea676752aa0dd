#include "stylos/core/view/LassoVisibility.h"


#include <algorithm>
#include <cmath>
#include <limits>

namespace stylos::core::view {

namespace {

/** The polygon rasterised at pixel centres over a window of whole pixels (the even-odd rule of insidePolygon). */
class PolygonMask {
public:
    PolygonMask(const std::vector<Eigen::Vector2d>& polygon, int x0, int y0, int width, int height)
        : m_x0(x0), m_y0(y0), m_width(width), m_height(height), m_inside(std::size_t(width) * std::size_t(height), 0)
    {
        std::vector<double> crossings;
        const std::size_t n = polygon.size();
        for (int row = 0; row < height; ++row) {
            const double y = y0 + row + 0.5;
            crossings.clear();
            for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
                const Eigen::Vector2d& a = polygon[i];
                const Eigen::Vector2d& b = polygon[j];
                if ((a.y() > y) != (b.y() > y)) crossings.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
            }
            std::sort(crossings.begin(), crossings.end());
            // A pixel centre x is inside when an odd number of crossings lie beyond it: c[2m] ≤ x < c[2m+1].
            for (std::size_t m = 0; m + 1 < crossings.size(); m += 2) {
                const int from = std::max(0, int(std::ceil(crossings[m] - 0.5 - x0)));
                const int to = std::min(width, int(std::ceil(crossings[m + 1] - 0.5 - x0)));
                for (int c = from; c < to; ++c) m_inside[std::size_t(row) * std::size_t(width) + std::size_t(c)] = 1;
            }
        }
    }

    bool contains(double x, double y) const
    {
        const double fx = std::floor(x) - m_x0, fy = std::floor(y) - m_y0;
        if (fx < 0 || fy < 0 || fx >= m_width || fy >= m_height) return false;
        return m_inside[std::size_t(fy) * std::size_t(m_width) + std::size_t(fx)] != 0;
    }

private:
    int m_x0, m_y0, m_width, m_height;
    std::vector<std::uint8_t> m_inside;
};

/** A target leaf inside the polygon, waiting for the depth buffer to be complete. */
struct Candidate {
    std::uint32_t target;    // index into the targets
    std::uint32_t leaf;
    std::uint32_t cell;      // depth-buffer cell
    float depth;             // metres
    float tolerance;         // metres
};

} // namespace

bool insidePolygon(const std::vector<Eigen::Vector2d>& polygon, double x, double y)
{
    bool inside = false;
    const std::size_t n = polygon.size();
    if (n < 3) return false;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const Eigen::Vector2d& a = polygon[i];
        const Eigen::Vector2d& b = polygon[j];
        if ((a.y() > y) != (b.y() > y) && x < a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) inside = !inside;
    }
    return inside;
}

std::vector<LassoLeaves> lassoVisibleLeaves(const std::vector<ViewFragment>& fragments, const Camera& camera,
                                            const std::vector<std::uint64_t>& targets,
                                            const std::vector<Eigen::Vector2d>& polygon, const LassoOptions& options)
{
    std::vector<LassoLeaves> out;
    for (const ViewFragment& f : fragments)
        if (f.visible && f.octree && std::find(targets.begin(), targets.end(), f.id) != targets.end())
            if (std::none_of(out.begin(), out.end(), [&](const LassoLeaves& l) { return l.fragment == f.id; }))
                out.push_back({f.id, {}});
    std::stable_sort(out.begin(), out.end(), [&](const LassoLeaves& a, const LassoLeaves& b) {
        return std::find(targets.begin(), targets.end(), a.fragment) < std::find(targets.begin(), targets.end(), b.fragment);
    });
    if (polygon.size() < 3 || out.empty()) return out;

    // The window: the polygon's bounding box in whole pixels, within the viewport.
    double minX = polygon[0].x(), maxX = minX, minY = polygon[0].y(), maxY = minY;
    for (const Eigen::Vector2d& p : polygon) {
        minX = std::min(minX, p.x()), maxX = std::max(maxX, p.x());
        minY = std::min(minY, p.y()), maxY = std::max(maxY, p.y());
    }
    const int x0 = std::max(0, int(std::floor(minX))), y0 = std::max(0, int(std::floor(minY)));
    const int x1 = std::min(camera.width(), int(std::ceil(maxX))), y1 = std::min(camera.height(), int(std::ceil(maxY)));
    if (x1 <= x0 || y1 <= y0) return out;
    const PolygonMask mask(polygon, x0, y0, x1 - x0, y1 - y0);

    const double cell = std::max(1.0, options.cellPixels);
    const int columns = int(std::ceil((x1 - x0) / cell)), rows = int(std::ceil((y1 - y0) / cell));
    std::vector<float> buffer(std::size_t(columns) * std::size_t(rows), std::numeric_limits<float>::infinity());
    std::vector<Candidate> candidates;

    const Eigen::Matrix4d view = camera.viewMatrix();
    const Eigen::Matrix4d projection = camera.projectionMatrix();
    const double halfHeight = 0.5 * camera.height(), halfWidth = 0.5 * camera.width();
    const double near = camera.isOrthographic() ? -std::numeric_limits<double>::infinity() : 1e-9;

    for (const ViewFragment& f : fragments) {
        if (!f.visible || !f.octree) continue;
        const auto target = std::find_if(out.begin(), out.end(), [&](const LassoLeaves& l) { return l.fragment == f.id; });
        const bool isTarget = target != out.end();
        const auto targetIndex = std::uint32_t(target - out.begin());
        const octree::PackedOctree& tree = *f.octree;
        const Eigen::Matrix4d modelView = view * f.pose;
        const Eigen::Matrix3d rotation = modelView.topLeftCorner<3, 3>();
        const Eigen::Matrix4d clipMatrix = projection * modelView;
        tree.forEachCell(tree.depth(), [&](const octree::CellView& leaf) {
            const Eigen::Vector4d p(leaf.centre[0], leaf.centre[1], leaf.centre[2], 1.0);
            const Eigen::Vector3d c = (modelView * p).head<3>();
            const double depth = -c.z();
            if (depth <= near) return true;
            const Eigen::Vector4d clip = clipMatrix * p;
            const double px = (clip.x() / clip.w() + 1.0) * halfWidth, py = (1.0 - clip.y() / clip.w()) * halfHeight;
            const double pixelsPerMetre = projection(1, 1) * halfHeight / clip.w();
            const double radius = std::max(double(tree.leafSpacing(leaf.index)), 0.5 * leaf.size); // metres
            const double reach = radius * pixelsPerMetre;                                            // pixels
            const double gx = (px - x0) / cell, gy = (py - y0) / cell;
            const int ci = int(std::floor(gx)), cj = int(std::floor(gy));
            const int i0 = std::max(0, int(std::floor(gx - reach / cell))), i1 = std::min(columns - 1, int(std::floor(gx + reach / cell)));
            const int j0 = std::max(0, int(std::floor(gy - reach / cell))), j1 = std::min(rows - 1, int(std::floor(gy + reach / cell)));
            if (i0 > i1 || j0 > j1) return true;
            // The disc in the plane of the normal turned toward the eye (grazing ones bounded, as the splats are).
            Eigen::Vector3d n = rotation * Eigen::Vector3d(leaf.normal[0], leaf.normal[1], leaf.normal[2]);
            if (n.z() < 0) n = -n;
            const double nz = std::max(n.z(), 0.35);
            for (int j = j0; j <= j1; ++j)
                for (int i = i0; i <= i1; ++i) {
                    const double dx = (x0 + (i + 0.5) * cell) - px, dy = (y0 + (j + 0.5) * cell) - py;
                    if (dx * dx + dy * dy > reach * reach && (i != ci || j != cj)) continue;
                    const double ox = dx / pixelsPerMetre, oy = -dy / pixelsPerMetre; // camera x right, y up
                    const double along = std::clamp((n.x() * ox + n.y() * oy) / nz, -radius, radius);
                    float& b = buffer[std::size_t(j) * std::size_t(columns) + std::size_t(i)];
                    b = std::min(b, float(depth + along));
                }
            if (isTarget && ci >= 0 && cj >= 0 && ci < columns && cj < rows && mask.contains(px, py)) {
                const double tolerance = options.toleranceSpacings * radius + options.slopeAllowance * cell / pixelsPerMetre;
                candidates.push_back({targetIndex, std::uint32_t(leaf.index), std::uint32_t(cj * columns + ci),
                                      float(depth), float(tolerance)});
            }
            return true;
        });
    }
    for (const Candidate& c : candidates)
        if (c.depth <= buffer[c.cell] + c.tolerance) out[c.target].leaves.push_back(c.leaf);
    for (LassoLeaves& l : out) std::sort(l.leaves.begin(), l.leaves.end());
    return out;
}

} // namespace stylos::core::view
