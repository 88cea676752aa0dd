#include "stylos/core/view/GizmoMath.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace stylos::core::view {

namespace {

constexpr double Infinity = std::numeric_limits<double>::infinity();

double segmentDistance2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p)
{
    const Eigen::Vector2d ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

/** Two unit vectors completing the unit @p axis to a right-handed frame. */
std::pair<Eigen::Vector3d, Eigen::Vector3d> planeBasis(const Eigen::Vector3d& axis)
{
    const Eigen::Vector3d seed = std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d u = (seed - seed.dot(axis) * axis).normalized();
    return {u, axis.cross(u)};
}

} // namespace

std::optional<double> closestAxisParameter(const Ray& ray, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction)
{
    // Closest points of the lines origin + s·d and ray.origin + t·r (both unit): s = (b·e − d·w) / (1 − b²).
    const double b = direction.dot(ray.direction);
    const double denominator = 1.0 - b * b;
    if (denominator < 1e-9) return std::nullopt;
    const Eigen::Vector3d w = origin - ray.origin;
    return (b * ray.direction.dot(w) - direction.dot(w)) / denominator;
}

std::optional<Eigen::Vector3d> rayPlane(const Ray& ray, const Eigen::Vector3d& point, const Eigen::Vector3d& normal)
{
    const double cosine = ray.direction.dot(normal);
    if (std::abs(cosine) < 1e-6) return std::nullopt;
    const double t = (point - ray.origin).dot(normal) / cosine;
    if (t < 0) return std::nullopt;
    return ray.origin + t * ray.direction;
}

double signedAngle(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Eigen::Vector3d& axis)
{
    const Eigen::Vector3d a = from - from.dot(axis) * axis;
    const Eigen::Vector3d b = to - to.dot(axis) * axis;
    if (a.squaredNorm() == 0 || b.squaredNorm() == 0) return 0.0;
    return std::atan2(axis.dot(a.cross(b)), a.dot(b));
}

std::optional<double> ringAngle(const Ray& ray, const Eigen::Vector3d& centre, const Eigen::Vector3d& axis,
                                const Eigen::Vector3d& zero)
{
    const auto hit = rayPlane(ray, centre, axis);
    if (!hit || *hit == centre) return std::nullopt;
    return signedAngle(zero, *hit - centre, axis);
}

double unwrapAngle(double previous, double now)
{
    constexpr double Turn = 2 * std::numbers::pi;
    return now + Turn * std::round((previous - now) / Turn);
}

std::optional<double> metresPerPixel(const Camera& camera, const Eigen::Vector3d& point)
{
    if (camera.isOrthographic()) return 1.0 / camera.pixelsPerMetre();
    const double depth = (point - camera.eye()).dot(camera.forward());
    if (depth <= 0) return std::nullopt;
    return depth / (camera.pixelsPerMetre() * camera.distance());
}

double pixelDistanceToSegment(const Camera& camera, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector2d& cursor)
{
    const auto pa = camera.project(a), pb = camera.project(b);
    if (!pa || !pb) return Infinity;
    return segmentDistance2d(pa->head<2>(), pb->head<2>(), cursor);
}

double pixelDistanceToRing(const Camera& camera, const Eigen::Vector3d& centre, const Eigen::Vector3d& axis,
                           double radius, const Eigen::Vector2d& cursor, int segments)
{
    segments = std::max(segments, 3);
    const auto [u, v] = planeBasis(axis);
    double best = Infinity;
    Eigen::Vector2d previous = Eigen::Vector2d::Zero();
    bool hasPrevious = false;
    for (int i = 0; i <= segments; ++i) {
        const double angle = 2 * std::numbers::pi * i / segments;
        const auto p = camera.project(centre + radius * (std::cos(angle) * u + std::sin(angle) * v));
        if (p && hasPrevious) best = std::min(best, segmentDistance2d(previous, p->head<2>(), cursor));
        hasPrevious = p.has_value();
        if (p) previous = p->head<2>();
    }
    return best;
}

double angleStep(double pitch, DragModifiers modifiers)
{
    if (pitch > 0 && !modifiers.precise) return pitch;
    return modifiers.fine ? 0.1 * Degree : Degree;
}

double lengthStep(DragModifiers modifiers) { return modifiers.fine ? 1e-4 : 1e-3; }

double snapToStep(double value, double step)
{
    if (!(step > 0)) return value;
    return step * std::round(value / step);
}

double FineDrag::feed(double raw, bool fine)
{
    m_value += (raw - m_last) * (fine ? 0.1 : 1.0);
    m_last = raw;
    return m_value;
}

} // namespace stylos::core::view
