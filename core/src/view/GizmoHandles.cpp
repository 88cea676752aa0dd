#include "stylos/core/view/GizmoHandles.h"

#include "stylos/core/view/GizmoMath.h"

#include <Eigen/Geometry>

#include <array>

namespace stylos::core::view {

namespace {

/** A unit vector normal to the unit @p axis (for a radial direction when the centre lies on the axis). */
Eigen::Vector3d anyNormal(const Eigen::Vector3d& axis)
{
    const Eigen::Vector3d seed = std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    return (seed - seed.dot(axis) * axis).normalized();
}

void addDrumHandles(std::vector<GizmoHandle>& out, const GizmoTarget& target, const DrumAxis& drum, bool tilts,
                    double mpp, const GizmoSizes& sizes)
{
    const Eigen::Vector3d c = target.centre();
    const Eigen::Vector3d a = drum.direction.normalized();
    const Eigen::Vector3d onAxis = drum.point + (c - drum.point).dot(a) * a; // the axis point level with c
    const Eigen::Vector3d offset = c - onAxis;
    const double radius = offset.norm();
    const Eigen::Vector3d radial = radius > 1e-9 ? Eigen::Vector3d(offset / radius) : anyNormal(a);
    out.push_back({HandleRole::DrumZ, c, a, sizes.arrow * mpp, 0.0});
    out.push_back({HandleRole::DrumRadial, c, radial, sizes.arrow * mpp, 0.0});
    out.push_back({HandleRole::DrumTheta, onAxis, a, radius > 1e-9 ? radius : sizes.ring * mpp, drum.pitch});
    if (tilts) {
        out.push_back({HandleRole::TiltRadial, c, radial, sizes.tilt * mpp, 0.0});
        out.push_back({HandleRole::TiltTangential, c, a.cross(radial), sizes.tilt * mpp, 0.0});
    }
}

} // namespace

bool isTranslation(HandleRole role)
{
    return role == HandleRole::MoveX || role == HandleRole::MoveY || role == HandleRole::MoveZ ||
           role == HandleRole::DrumZ || role == HandleRole::DrumRadial;
}

std::vector<GizmoHandle> gizmoHandles(const GizmoTarget& target, GizmoFrame frame, bool tilts, double mpp,
                                      const GizmoSizes& sizes)
{
    std::vector<GizmoHandle> handles;
    if (frame == GizmoFrame::Drum && target.drum) {
        addDrumHandles(handles, target, *target.drum, tilts, mpp, sizes);
        return handles;
    }
    const Eigen::Vector3d c = target.centre();
    const Eigen::Matrix3d axes = frame == GizmoFrame::Fragment ? Eigen::Matrix3d(target.pose.topLeftCorner<3, 3>())
                                                               : Eigen::Matrix3d::Identity();
    constexpr std::array<HandleRole, 3> Moves = {HandleRole::MoveX, HandleRole::MoveY, HandleRole::MoveZ};
    constexpr std::array<HandleRole, 3> Turns = {HandleRole::TurnX, HandleRole::TurnY, HandleRole::TurnZ};
    for (int i = 0; i < 3; ++i) handles.push_back({Moves[std::size_t(i)], c, axes.col(i).normalized(), sizes.arrow * mpp, 0.0});
    for (int i = 0; i < 3; ++i) handles.push_back({Turns[std::size_t(i)], c, axes.col(i).normalized(), sizes.ring * mpp, 0.0});
    return handles;
}

std::vector<GizmoHandle> visibleGizmoHandles(const GizmoTarget& target, GizmoFrame frame, bool tilts,
                                             const Camera& camera, const GizmoSizes& sizes)
{
    const Eigen::Vector3d centre = target.centre();
    const auto mpp = metresPerPixel(camera, centre);
    if (!mpp) return {};
    const Eigen::Vector3d sight = camera.isOrthographic() ? camera.forward() : Eigen::Vector3d((centre - camera.eye()).normalized());
    std::vector<GizmoHandle> handles = gizmoHandles(target, frame, tilts, *mpp, sizes);
    std::erase_if(handles, [&sight](const GizmoHandle& h) {
        const double along = std::abs(sight.dot(h.direction));
        if (h.translates()) return along > std::cos(8 * Degree);
        return h.role != HandleRole::DrumTheta && along < std::sin(6 * Degree);
    });
    return handles;
}

Eigen::Matrix4d applyHandle(const GizmoHandle& handle, const Eigen::Matrix4d& start, double value)
{
    Eigen::Matrix4d motion = Eigen::Matrix4d::Identity();
    if (handle.translates()) {
        motion.topRightCorner<3, 1>() = value * handle.direction;
    } else {
        const Eigen::Matrix3d r = Eigen::AngleAxisd(value, handle.direction).toRotationMatrix();
        motion.topLeftCorner<3, 3>() = r;
        motion.topRightCorner<3, 1>() = handle.origin - r * handle.origin; // about the line through origin
    }
    return motion * start;
}

std::optional<std::size_t> pickHandle(const std::vector<GizmoHandle>& handles, const Camera& camera,
                                      const Eigen::Vector2d& cursor, double radius)
{
    std::optional<std::size_t> best;
    double bestDistance = radius;
    for (std::size_t i = 0; i < handles.size(); ++i) {
        const GizmoHandle& h = handles[i];
        const double d = h.translates()
                             ? pixelDistanceToSegment(camera, h.origin, h.origin + h.size * h.direction, cursor)
                             : pixelDistanceToRing(camera, h.origin, h.direction, h.size, cursor);
        if (d < bestDistance || (!best && d <= bestDistance)) {
            bestDistance = d;
            best = i;
        }
    }
    return best;
}

} // namespace stylos::core::view
