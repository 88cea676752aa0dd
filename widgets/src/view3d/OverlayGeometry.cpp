#include "view3d/OverlayGeometry.h"

#include "stylos/core/view/GizmoMath.h"

#include <cmath>
#include <numbers>

namespace stylos::widgets {

OverlayGeometry::OverlayGeometry(const core::view::Camera& camera, const Eigen::Vector3d& origin)
    : m_camera(camera), m_origin(origin)
{
}

bool OverlayGeometry::across(const Eigen::Vector3d& a, const Eigen::Vector3d& b, Eigen::Vector3d& side) const
{
    const Eigen::Vector3d middle = 0.5 * (a + b);
    const Eigen::Vector3d sight = m_camera.isOrthographic() ? m_camera.forward() : Eigen::Vector3d(middle - m_camera.eye());
    const Eigen::Vector3d cross = (b - a).cross(sight);
    if (cross.squaredNorm() < 1e-30) return false;
    side = cross.normalized();
    return true;
}

void OverlayGeometry::vertex(const Eigen::Vector3d& p, const QColor& colour)
{
    const Eigen::Vector3d q = p - m_origin;
    m_triangles.push_back({float(q.x()), float(q.y()), float(q.z()), float(colour.redF()), float(colour.greenF()),
                           float(colour.blueF()), float(colour.alphaF())});
}

void OverlayGeometry::addSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double width, const QColor& colour)
{
    const auto ma = core::view::metresPerPixel(m_camera, a), mb = core::view::metresPerPixel(m_camera, b);
    Eigen::Vector3d side;
    if (!ma || !mb || !across(a, b, side)) return;
    const Eigen::Vector3d da = 0.5 * width * *ma * side, db = 0.5 * width * *mb * side;
    vertex(a - da, colour);
    vertex(a + da, colour);
    vertex(b + db, colour);
    vertex(a - da, colour);
    vertex(b + db, colour);
    vertex(b - db, colour);
}

void OverlayGeometry::addRing(const Eigen::Vector3d& centre, const Eigen::Vector3d& axis, double radius, double width,
                              const QColor& colour, int segments)
{
    const Eigen::Vector3d seed = std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d u = (seed - seed.dot(axis) * axis).normalized(), v = axis.cross(u);
    Eigen::Vector3d previous = centre + radius * u;
    for (int i = 1; i <= segments; ++i) {
        const double angle = 2 * std::numbers::pi * i / segments;
        const Eigen::Vector3d p = centre + radius * (std::cos(angle) * u + std::sin(angle) * v);
        addSegment(previous, p, width, colour);
        previous = p;
    }
}

void OverlayGeometry::addArrow(const Eigen::Vector3d& base, const Eigen::Vector3d& tip, double width, double head,
                               const QColor& colour)
{
    const auto mpp = core::view::metresPerPixel(m_camera, tip);
    Eigen::Vector3d side;
    if (!mpp || !across(base, tip, side)) return;
    const Eigen::Vector3d along = (tip - base).normalized();
    const Eigen::Vector3d neck = tip - std::min(head * *mpp, 0.5 * (tip - base).norm()) * along;
    addSegment(base, neck, width, colour);
    const Eigen::Vector3d half = 0.4 * head * *mpp * side;
    vertex(neck - half, colour);
    vertex(neck + half, colour);
    vertex(tip, colour);
}

} // namespace stylos::widgets
