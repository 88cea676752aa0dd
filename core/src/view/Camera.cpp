#include "stylos/core/view/Camera.h"

#include <algorithm>
#include <cmath>

namespace stylos::core::view {

namespace {

/** Rotation whose columns are the camera's right, up and back axes in scene coordinates. */
Eigen::Quaterniond fromAxes(const Eigen::Vector3d& right, const Eigen::Vector3d& up, const Eigen::Vector3d& back)
{
    Eigen::Matrix3d m;
    m.col(0) = right;
    m.col(1) = up;
    m.col(2) = back;
    return Eigen::Quaterniond(m).normalized();
}

} // namespace

Camera::Camera() : m_orientation(standardOrientation(StandardView::Front)) {}

void Camera::setViewport(int width, int height)
{
    m_width = std::max(1, width);
    m_height = std::max(1, height);
}

void Camera::setFieldOfView(double radians) { m_fov = std::clamp(radians, 1e-3, 3.0); }

void Camera::setDistance(double metres) { m_distance = std::max(metres, 1e-6); }

void Camera::setOrientation(const Eigen::Quaterniond& orientation) { m_orientation = orientation.normalized(); }

Eigen::Vector3d Camera::eye() const { return m_target + m_orientation * Eigen::Vector3d::UnitZ() * m_distance; }
Eigen::Vector3d Camera::forward() const { return -(m_orientation * Eigen::Vector3d::UnitZ()); }
Eigen::Vector3d Camera::up() const { return m_orientation * Eigen::Vector3d::UnitY(); }
Eigen::Vector3d Camera::right() const { return m_orientation * Eigen::Vector3d::UnitX(); }

void Camera::orbit(double yaw, double pitch)
{
    const Eigen::AngleAxisd aboutZ(yaw, Eigen::Vector3d::UnitZ());
    // A rotation about the camera's own x axis by −pitch raises the eye for a positive pitch.
    const Eigen::AngleAxisd aboutRight(-pitch, Eigen::Vector3d::UnitX());
    setOrientation(Eigen::Quaterniond(aboutZ) * m_orientation * Eigen::Quaterniond(aboutRight));
}

void Camera::pan(double dx, double dy)
{
    const double metresPerPixel = viewHeight() / double(m_height);
    m_target += (-dx * right() + dy * up()) * metresPerPixel;
}

void Camera::dolly(double factor)
{
    if (factor > 0 && std::isfinite(factor)) setDistance(m_distance * factor);
}

Eigen::Quaterniond Camera::standardOrientation(StandardView view)
{
    const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
    switch (view) {
    case StandardView::Front: return fromAxes(x, z, -y);
    case StandardView::Back: return fromAxes(-x, z, y);
    case StandardView::Left: return fromAxes(-y, z, -x);
    case StandardView::Right: return fromAxes(y, z, x);
    case StandardView::Top: return fromAxes(x, y, z);
    case StandardView::Bottom: return fromAxes(-x, y, -z);
    case StandardView::Iso: {
        const Eigen::Vector3d back = Eigen::Vector3d(1, -1, 1).normalized();
        const Eigen::Vector3d right = z.cross(back).normalized();
        return fromAxes(right, back.cross(right), back);
    }
    }
    return fromAxes(x, z, -y);
}

void Camera::setStandardView(StandardView view) { m_orientation = standardOrientation(view); }

void Camera::fit(const Eigen::AlignedBox3d& box)
{
    if (box.isEmpty()) return;
    std::vector<Eigen::Vector3d> corners;
    for (int corner = 0; corner < 8; ++corner) corners.push_back(box.corner(Eigen::AlignedBox3d::CornerType(corner)));
    fit(corners);
}

void Camera::fit(const std::vector<Eigen::Vector3d>& points)
{
    if (points.empty()) return;
    // The margin narrows the field the points must fit in (their picture spans 1 / Margin of the view), so that
    // the eye placed for that field keeps the picture exactly centred.
    constexpr double Margin = 1.05;
    const double tanY = std::tan(0.5 * m_fov) / Margin, tanX = tanY * aspect();
    const Eigen::Vector3d r = right(), u = up(), back = -forward();
    // In the camera's axes (x right, y up, z towards the eye). A point is in a perspective view from the eye
    // (ex, ey, ez) when |x − ex| ≤ tanX (ez − z): ex − tanX ez ≤ x − tanX z and ex + tanX ez ≥ x + tanX z for
    // all points, so the nearest eye has ez = (max(x + tanX z) − min(x − tanX z)) / (2 tanX) (and the same in
    // y), ex halfway: the picture centred.
    Eigen::AlignedBox3d box;
    double loX = INFINITY, hiX = -INFINITY, loY = INFINITY, hiY = -INFINITY;
    for (const Eigen::Vector3d& p : points) {
        const Eigen::Vector3d c(p.dot(r), p.dot(u), p.dot(back));
        box.extend(c);
        loX = std::min(loX, c.x() - tanX * c.z());
        hiX = std::max(hiX, c.x() + tanX * c.z());
        loY = std::min(loY, c.y() - tanY * c.z());
        hiY = std::max(hiY, c.y() + tanY * c.z());
    }
    const Eigen::Vector3d centre = box.center();
    Eigen::Vector3d target = centre; // camera axes
    double distance = 0;
    if (m_orthographic) {
        // Orthographic: the view height is 2 · distance · tanY.
        distance = std::max(0.5 * box.sizes().y(), 0.5 * box.sizes().x() / aspect()) / tanY;
    } else {
        // The target straight ahead of that eye, at the depth of the box centre.
        const double ez = std::max((hiX - loX) / (2 * tanX), (hiY - loY) / (2 * tanY));
        target = Eigen::Vector3d(0.5 * (loX + hiX), 0.5 * (loY + hiY), centre.z());
        distance = ez - centre.z();
    }
    if (!(distance > 0)) distance = 1e-3; // a single point
    m_target = target.x() * r + target.y() * u + target.z() * back;
    setDistance(distance);
}

Eigen::Matrix4d Camera::viewMatrix() const
{
    const Eigen::Matrix3d toCamera = m_orientation.toRotationMatrix().transpose();
    Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
    view.topLeftCorner<3, 3>() = toCamera;
    view.topRightCorner<3, 1>() = -toCamera * eye();
    return view;
}

void Camera::clipRange(double& nearPlane, double& farPlane) const
{
    if (m_bounds.isEmpty()) {
        nearPlane = 0.01 * m_distance;
        farPlane = 100.0 * m_distance;
        return;
    }
    const double radius = std::max(0.5 * m_bounds.diagonal().norm(), 1e-6) * 1.05;
    const double depth = (m_bounds.center() - eye()).dot(forward());
    nearPlane = depth - radius;
    farPlane = depth + radius;
    if (!m_orthographic) {
        if (farPlane <= 0) farPlane = m_distance + radius; // the scene is behind: anything valid
        nearPlane = std::max(nearPlane, std::max(farPlane * 1e-4, 1e-6));
        // A scene deeper than the depth buffer's 1e4 : 1 (a fragment moved kilometres away) must not push the
        // near plane past what the camera looks at: the target's surroundings stay in range, and what lies
        // beyond 1e4 near-plane distances is clipped instead.
        // Only when the near plane would cut into what the camera looks at (past half its distance): a close-up
        // in a tall scene keeps the planes the scene gives.
        const double closest = std::max(0.05 * m_distance, 1e-6);
        if (nearPlane > 0.5 * m_distance && depth - radius < closest) {
            nearPlane = std::max(depth - radius, closest);
            farPlane = std::min(farPlane, nearPlane * 1e4);
        }
    }
}

double Camera::nearPlane() const
{
    double n = 0, f = 0;
    clipRange(n, f);
    return n;
}

double Camera::farPlane() const
{
    double n = 0, f = 0;
    clipRange(n, f);
    return f;
}

double Camera::viewHeight() const { return 2.0 * m_distance * std::tan(0.5 * m_fov); }

Eigen::Matrix4d Camera::projectionMatrix() const
{
    double n = 0, f = 0;
    clipRange(n, f);
    Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
    if (m_orthographic) {
        const double halfHeight = 0.5 * viewHeight();
        const double halfWidth = halfHeight * aspect();
        p(0, 0) = 1.0 / halfWidth;
        p(1, 1) = 1.0 / halfHeight;
        p(2, 2) = -2.0 / (f - n);
        p(2, 3) = -(f + n) / (f - n);
        p(3, 3) = 1.0;
    } else {
        const double focal = 1.0 / std::tan(0.5 * m_fov);
        p(0, 0) = focal / aspect();
        p(1, 1) = focal;
        p(2, 2) = (f + n) / (n - f);
        p(2, 3) = 2.0 * f * n / (n - f);
        p(3, 2) = -1.0;
    }
    return p;
}

Ray Camera::rayAt(double x, double y) const
{
    const double ndcX = 2.0 * x / double(m_width) - 1.0;
    const double ndcY = 1.0 - 2.0 * y / double(m_height);
    const double halfHeight = std::tan(0.5 * m_fov); // at unit depth
    Ray ray;
    if (m_orthographic) {
        const double h = 0.5 * viewHeight();
        ray.direction = forward();
        ray.origin = eye() + right() * (ndcX * h * aspect()) + up() * (ndcY * h) + forward() * nearPlane();
    } else {
        const Eigen::Vector3d local(ndcX * halfHeight * aspect(), ndcY * halfHeight, -1.0);
        ray.origin = eye();
        ray.direction = (m_orientation * local).normalized();
    }
    return ray;
}

std::optional<Eigen::Vector3d> Camera::project(const Eigen::Vector3d& point) const
{
    const Eigen::Vector4d clip = viewProjection() * point.homogeneous();
    if (clip.w() <= 0) return std::nullopt;
    const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
    return Eigen::Vector3d((ndc.x() + 1.0) * 0.5 * m_width, (1.0 - ndc.y()) * 0.5 * m_height, ndc.z());
}

} // namespace stylos::core::view
