#pragma once
// Docking geometry shared by the docking tests and benchmark (no test framework): a start pose perturbed
// in the drum frame, and the errors of a docked pose against the truth in the drum frame.
#include "stylos/core/cloud/PointCloud.h"
#include "stylos/core/dock/FluteModel.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stylos::test {

/** @p pose moved in the drum frame: rotated about the axis by @p theta, tilted by @p tilt about the
 *  tangential direction and by @p roll about the radial direction at @p centre (drum file frame), moved
 *  radially by @p radial. */
inline Eigen::Isometry3d perturbed(const Eigen::Isometry3d& pose, const core::dock::DrumFrame& frame,
                                   const Eigen::Vector3d& centre, double theta, double tilt, double radial,
                                   double roll = 0.0)
{
    const Eigen::Vector3d d = frame.rows.row(2).transpose();
    const Eigen::Vector3d c = frame.toFrame(centre);
    const Eigen::Vector3d ur = frame.rows.transpose() * Eigen::Vector3d(c.x(), c.y(), 0.0).normalized();
    const Eigen::Vector3d ut = d.cross(ur);
    const Eigen::Isometry3d tiltAbout(Eigen::Translation3d(centre) * Eigen::AngleAxisd(tilt, ut) *
                                     Eigen::AngleAxisd(roll, ur) * Eigen::Translation3d(-centre));
    const Eigen::Isometry3d turn(Eigen::Translation3d(frame.origin) * Eigen::AngleAxisd(theta, d) *
                                 Eigen::Translation3d(-frame.origin));
    return turn * Eigen::Translation3d(radial * ur) * tiltAbout * pose;
}

/** Errors of @p docked against @p truth in the drum frame, at the fragment's centre @p centre (its file frame). */
struct DockErrors {
    double thetaDeg = 0, tiltDeg = 0, radialMm = 0, tangentMm = 0, zMm = 0;
};

inline DockErrors dockErrors(const Eigen::Isometry3d& docked, const Eigen::Isometry3d& truth,
                             const core::dock::DrumFrame& frame, const Eigen::Vector3d& centre)
{
    const Eigen::Matrix3d e = frame.rows * (docked.linear() * truth.linear().transpose()) * frame.rows.transpose();
    DockErrors out;
    const Eigen::AngleAxisd aa(e);
    out.thetaDeg = std::abs(aa.angle() * aa.axis().z()) * 180.0 / std::numbers::pi;
    out.tiltDeg = std::acos(std::clamp((e * Eigen::Vector3d::UnitZ()).z(), -1.0, 1.0)) * 180.0 / std::numbers::pi;
    const Eigen::Vector3d t = frame.toFrame(truth * centre), m = frame.toFrame(docked * centre);
    const Eigen::Vector3d ur = Eigen::Vector3d(t.x(), t.y(), 0.0).normalized(), ut(-ur.y(), ur.x(), 0.0);
    out.radialMm = std::abs((m - t).dot(ur)) * 1e3;
    out.tangentMm = std::abs((m - t).dot(ut)) * 1e3;
    out.zMm = std::abs(m.z() - t.z()) * 1e3;
    return out;
}

inline Eigen::Vector3d cloudCentre(const core::cloud::PointCloud& cloud)
{
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < cloud.size(); ++i) sum += cloud.local(i);
    return cloud.origin + sum / double(std::max<std::size_t>(cloud.size(), 1));
}

} // namespace stylos::test
