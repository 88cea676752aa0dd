#include "stylos/core/view/GizmoDrag.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <vector>
#include <numbers>

namespace stylos::core::view {

namespace {

/** Below this |cos| between the ray and a ring's axis the ring is turned by its tangent on screen. */
constexpr double PlaneFacing = 0.2;

/** The point of the ring nearest @p cursor on screen (a polygon of 360 sides); within half a pixel of the
 *  nearest, the nearest to the eye: the front of a ring seen edge-on. */
std::optional<Eigen::Vector3d> nearestRingPoint(const GizmoHandle& h, const Camera& camera, const Eigen::Vector2d& cursor)
{
    const Eigen::Vector3d seed = std::abs(h.direction.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d u = (seed - seed.dot(h.direction) * h.direction).normalized();
    const Eigen::Vector3d v = h.direction.cross(u);
    struct Sample {
        Eigen::Vector3d point;
        double distance;
        double depth;
    };
    std::vector<Sample> samples;
    double nearest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 360; ++i) {
        const double angle = 2 * std::numbers::pi * i / 360;
        const Eigen::Vector3d p = h.origin + h.size * (std::cos(angle) * u + std::sin(angle) * v);
        const auto q = camera.project(p);
        if (!q) continue;
        samples.push_back({p, (q->head<2>() - cursor).norm(), q->z()});
        nearest = std::min(nearest, samples.back().distance);
    }
    std::optional<Sample> best;
    for (const Sample& s : samples)
        if (s.distance <= nearest + 0.5 && (!best || s.depth < best->depth)) best = s;
    if (!best) return std::nullopt;
    return best->point;
}

} // namespace

std::optional<GizmoDrag> GizmoDrag::begin(const GizmoHandle& handle, const Camera& camera, const Eigen::Vector2d& cursor,
                                          const Eigen::Matrix4d& start)
{
    GizmoDrag drag(handle, camera, cursor, start);
    const Ray ray = camera.rayAt(cursor.x(), cursor.y());
    if (handle.translates()) {
        const auto s = closestAxisParameter(ray, handle.origin, handle.direction);
        if (!s) return std::nullopt;
        drag.m_pressParameter = *s;
        return drag;
    }
    if (std::abs(ray.direction.dot(handle.direction)) >= PlaneFacing) {
        if (const auto hit = rayPlane(ray, handle.origin, handle.direction); hit && *hit != handle.origin) {
            drag.m_zero = *hit - handle.origin;
            return drag;
        }
    }
    // Nearly edge-on: along the ring's tangent on screen at the ring point under the cursor.
    const auto point = nearestRingPoint(handle, camera, cursor);
    if (!point) return std::nullopt;
    const Eigen::Vector3d tangent = handle.direction.cross(*point - handle.origin); // |·| = radius per radian
    constexpr double Step = 1e-3;
    const auto ahead = camera.project(*point + Step * tangent), behind = camera.project(*point - Step * tangent);
    if (!ahead || !behind) return std::nullopt;
    drag.m_tangentPixels = (ahead->head<2>() - behind->head<2>()) / (2 * Step);
    if (drag.m_tangentPixels.norm() < 1.0) {
        // The tangent points at the eye (the ring's silhouette): across the projected axis, a radius a radian.
        const auto o = camera.project(handle.origin), tip = camera.project(handle.origin + handle.size * handle.direction);
        const auto mpp = metresPerPixel(camera, *point);
        if (!o || !tip || !mpp) return std::nullopt;
        const Eigen::Vector2d axis = tip->head<2>() - o->head<2>();
        if (axis.norm() < 1.0) return std::nullopt;
        drag.m_tangentPixels = Eigen::Vector2d(-axis.y(), axis.x()).normalized() * (handle.size / *mpp);
    }
    drag.m_tangent = true;
    return drag;
}

std::optional<double> GizmoDrag::raw(const Eigen::Vector2d& cursor) const
{
    if (m_tangent) return (cursor - m_pressCursor).dot(m_tangentPixels) / m_tangentPixels.squaredNorm();
    const Ray ray = m_camera.rayAt(cursor.x(), cursor.y());
    if (m_handle.translates()) {
        const auto s = closestAxisParameter(ray, m_handle.origin, m_handle.direction);
        if (!s) return std::nullopt;
        return *s - m_pressParameter;
    }
    const auto angle = ringAngle(ray, m_handle.origin, m_handle.direction, m_zero);
    if (!angle) return std::nullopt;
    return unwrapAngle(m_lastRaw, *angle);
}

std::optional<Eigen::Matrix4d> GizmoDrag::update(const Eigen::Vector2d& cursor, DragModifiers modifiers)
{
    const auto r = raw(cursor);
    if (!r) return std::nullopt;
    m_lastRaw = *r;
    const double value = m_fine.feed(*r, modifiers.fine);
    const double step = m_handle.translates() ? lengthStep(modifiers) : angleStep(m_handle.pitch, modifiers);
    m_snapped = snapToStep(value, step);
    return applyHandle(m_handle, m_start, m_snapped);
}

} // namespace stylos::core::view
