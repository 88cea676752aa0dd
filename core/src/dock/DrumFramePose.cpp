#include "stylos/core/dock/DrumFramePose.h"

#include <cmath>

namespace stylos::core::dock {

double DrumFramePose::value(DockUnknown unknown) const
{
    switch (unknown) {
    case DockUnknown::Theta: return theta;
    case DockUnknown::Z: return z;
    case DockUnknown::R: return r;
    case DockUnknown::Tangent: return 0.0;
    case DockUnknown::TiltLean: return tiltLean;
    case DockUnknown::TiltRoll: return tiltRoll;
    }
    return 0.0;
}

void DrumFramePose::set(DockUnknown unknown, double v)
{
    switch (unknown) {
    case DockUnknown::Theta: theta = v; break;
    case DockUnknown::Z: z = v; break;
    case DockUnknown::R: r = v; break;
    case DockUnknown::Tangent: break;
    case DockUnknown::TiltLean: tiltLean = v; break;
    case DockUnknown::TiltRoll: tiltRoll = v; break;
    }
}

DrumFramePose drumFramePose(const DrumFrame& frame, const Eigen::Isometry3d& pose, const Eigen::Vector3d& centre)
{
    DrumFramePose out;
    const Eigen::Vector3d c = frame.toFrame(pose * centre);
    out.theta = std::atan2(c.y(), c.x());
    out.z = c.z();
    out.r = std::hypot(c.x(), c.y());
    // R_cyl = Rz(θ)ᵀ · rows · R = Ry(lean) · Rx(roll) · Rz(spin): its row 1 is (cos roll sin spin, cos roll cos
    // spin, −sin roll), its column 2 (sin lean cos roll, −sin roll, cos lean cos roll).
    const Eigen::Matrix3d m =
        Eigen::AngleAxisd(-out.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix() * frame.rows * pose.linear();
    out.tiltRoll = std::atan2(-m(1, 2), std::hypot(m(1, 0), m(1, 1)));
    if (std::hypot(m(1, 0), m(1, 1)) > 1e-12) {
        out.spin = std::atan2(m(1, 0), m(1, 1));
        out.tiltLean = std::atan2(m(0, 2), m(2, 2));
    } else { // roll ±90°: spin 0, Ry(lean)·Rx(±90°) reads lean from row 0
        out.spin = 0.0;
        out.tiltLean = std::atan2(-m(2, 0), m(0, 0));
    }
    return out;
}

Eigen::Isometry3d placeInDrumFrame(const DrumFrame& frame, const DrumFramePose& v, const Eigen::Vector3d& centre)
{
    const Eigen::Matrix3d cylindrical = (Eigen::AngleAxisd(v.tiltLean, Eigen::Vector3d::UnitY()) *
                                         Eigen::AngleAxisd(v.tiltRoll, Eigen::Vector3d::UnitX()) *
                                         Eigen::AngleAxisd(v.spin, Eigen::Vector3d::UnitZ()))
                                            .toRotationMatrix();
    const Eigen::Matrix3d inFrame = Eigen::AngleAxisd(v.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix() * cylindrical;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = frame.rows.transpose() * inFrame;
    const Eigen::Vector3d placed = frame.toWorld({v.r * std::cos(v.theta), v.r * std::sin(v.theta), v.z});
    pose.translation() = placed - pose.linear() * centre;
    return pose;
}

} // namespace stylos::core::dock
