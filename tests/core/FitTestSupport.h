#pragma once
// Helpers of the surface-fit tests: generated scans loaded as clouds (cached per process), the true
// axis of the points as generated, distances between axes, and clouds built here (a cone, a plane, a
// box, two blobs).
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/synth/Random.h"
#include "stylos/core/unroll/Surface.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <string>

namespace stylos::test {

/** A generated scan, loaded, with its truth sidecar. */
struct FitScan {
    core::cloud::PointCloud cloud;
    nlohmann::json truth;
};

/**
 * generateScan() into a folder that lives as long as the process, loaded as a cloud; the same @p key
 * is generated once per process (tests share it). Fails the current test on error.
 */
inline const FitScan& generatedScan(const std::string& key, core::synth::SyntheticKind kind,
                                    const core::synth::SyntheticOptions& options)
{
    static TempDir folder;
    static std::map<std::string, std::unique_ptr<FitScan>> cache;
    auto& entry = cache[key];
    if (!entry) {
        entry = std::make_unique<FitScan>();
        const auto path = folder / (key + ".ply");
        const auto report = generate(kind, options, path);
        auto cloud = core::cloud::loadPointCloud(path);
        EXPECT_TRUE(cloud.ok()) << (cloud.ok() ? "" : cloud.error().message);
        if (cloud.ok()) entry->cloud = std::move(cloud).value();
        std::ifstream in(report.truthPath);
        entry->truth = nlohmann::json::parse(in, nullptr, false);
    }
    return *entry;
}

/** Options of a scan by ONE station that sees all round: its registration error is then a rigid
 *  motion of the whole object, known from the sidecar, so the axis of the points is known exactly. */
inline core::synth::SyntheticOptions allRound(double spacing, std::uint64_t seed, int grooves)
{
    auto o = coarse(spacing, seed);
    o.scans = 1;
    o.scanHalfAngle = std::numbers::pi;
    o.grooves = grooves;
    return o;
}

inline Eigen::Affine3d affineOf(const nlohmann::json& rowMajor)
{
    Eigen::Matrix4d m;
    for (int i = 0; i < 16; ++i)
        m(i / 4, i % 4) = rowMajor[std::size_t(i)].get<double>();
    return Eigen::Affine3d(m);
}

/** The object's axis (its frame's z axis through the origin, the lower bed or plinth bottom) as scan
 *  @p station placed it, registration error included; station −1: the nominal pose. */
inline core::unroll::Axis trueAxis(const nlohmann::json& truth, int station = -1)
{
    const Eigen::Affine3d a =
        station < 0 ? affineOf(truth["pose"]) : affineOf(truth["stations"][std::size_t(station)]["toOutput"]);
    core::unroll::Axis axis;
    axis.point = a * Eigen::Vector3d::Zero();
    axis.direction = (a.linear() * Eigen::Vector3d::UnitZ()).normalized();
    return axis;
}

/** Angle between two axis directions, degrees, whichever way they point. */
inline double angleDegrees(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::atan2(a.cross(b).norm(), std::abs(a.dot(b))) * 180.0 / std::numbers::pi;
}

/** Distance from point @p p to the line @p axis, metres. */
inline double distanceToLine(const Eigen::Vector3d& p, const core::unroll::Axis& axis)
{
    const Eigen::Vector3d w = p - axis.point;
    return (w - w.dot(axis.direction) * axis.direction).norm();
}

/** How far the line of @p fitted strays from @p truth over the object: the larger distance at its
 *  point and @p length along it. */
inline double axisDistance(const core::unroll::Axis& fitted, const core::unroll::Axis& truth, double length)
{
    return std::max(distanceToLine(fitted.point, truth),
                    distanceToLine(fitted.point + length * fitted.direction, truth));
}

/** A truncated cone (a cylinder when the radii are equal) with both bed discs, in a random pose at museum coordinates,
 * with noise and outliers. */
struct ConeCloud {
    core::cloud::PointCloud cloud;
    core::unroll::Axis axis;        ///< through the centre of the wide (lower) bed, toward the narrow end
    double meanLateralRadius = 0.0; ///< mean distance of the lateral points from the axis (noise-free)
};

inline ConeCloud coneCloud(double bottomRadius, double topRadius, double height, std::size_t points, double noise,
                           double outlierShare, std::uint64_t seed)
{
    core::synth::Random random(seed);
    ConeCloud result;
    Eigen::Affine3d pose = Eigen::Affine3d::Identity();
    pose.linear() = random.rotation();
    pose.translation() = Eigen::Vector3d(500.0, -300.0, 40.0) + random.unitVector();
    result.axis.point = pose.translation();
    result.axis.direction = pose.linear().col(2);
    result.cloud.origin = pose.translation().array().round();
    result.cloud.source = "cone";
    const double slant = std::hypot(height, bottomRadius - topRadius);
    const double lateral = std::numbers::pi * (bottomRadius + topRadius) * slant;
    const double bottom = std::numbers::pi * bottomRadius * bottomRadius,
                 top = std::numbers::pi * topRadius * topRadius;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    std::vector<Eigen::Vector3d> local;
    double radiusSum = 0.0;
    std::size_t lateralCount = 0;
    for (std::size_t i = 0; i < points; ++i) {
        const double pick = random.uniform(0.0, lateral + bottom + top),
                     theta = random.uniform(0.0, 2.0 * std::numbers::pi);
        Eigen::Vector3d p = Eigen::Vector3d::Zero(), n = Eigen::Vector3d::UnitZ();
        if (pick < lateral) { // uniform by area: r grows linearly with z, density ∝ r
            const double u = random.uniform();
            const double r2 = bottomRadius * bottomRadius + u * (topRadius * topRadius - bottomRadius * bottomRadius);
            const bool cylinder = topRadius == bottomRadius;
            const double r = cylinder ? bottomRadius : std::sqrt(r2);
            const double z = cylinder ? u * height : height * (r - bottomRadius) / (topRadius - bottomRadius);
            p = {r * std::cos(theta), r * std::sin(theta), z};
            n = Eigen::Vector3d(height * std::cos(theta), height * std::sin(theta), bottomRadius - topRadius)
                    .normalized();
            radiusSum += r;
            ++lateralCount;
        } else {
            const bool isTop = pick >= lateral + bottom;
            const double r = (isTop ? topRadius : bottomRadius) * std::sqrt(random.uniform());
            p = {r * std::cos(theta), r * std::sin(theta), isTop ? height : 0.0};
            n = Eigen::Vector3d(0.0, 0.0, isTop ? 1.0 : -1.0);
        }
        p += noise * random.normal() * n;
        local.push_back(p);
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const std::size_t outliers = std::size_t(outlierShare * double(points));
    for (std::size_t i = 0; i < outliers; ++i)
        local.emplace_back(random.uniform(lo.x(), hi.x()), random.uniform(lo.y(), hi.y()),
                           random.uniform(lo.z(), hi.z()));
    for (const Eigen::Vector3d& p : local)
        result.cloud.addWorld(pose * p);
    result.meanLateralRadius = radiusSum / double(lateralCount);
    return result;
}

/** @p n points of a 1 m square with 1 mm noise; a 1 m cube filled at random; or two Gaussian blobs
 *  (σ 0.1 m) 1 m apart — none remotely a surface of revolution. */
enum class BadShape { Plane, Box, Blobs };

inline core::cloud::PointCloud badCloud(BadShape shape, std::size_t n, std::uint64_t seed)
{
    core::synth::Random random(seed);
    core::cloud::PointCloud cloud;
    cloud.origin = Eigen::Vector3d(100.0, 200.0, 10.0);
    cloud.source = shape == BadShape::Plane ? "plane" : shape == BadShape::Box ? "box" : "blobs";
    for (std::size_t i = 0; i < n; ++i) {
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        switch (shape) {
        case BadShape::Plane:
            p = {random.uniform(), random.uniform(), 0.001 * random.normal()};
            break;
        case BadShape::Box:
            p = {random.uniform(), random.uniform(), random.uniform()};
            break;
        case BadShape::Blobs:
            p = Eigen::Vector3d(i % 2 ? 1.0 : 0.0, 0.0, 0.0) +
                0.1 * Eigen::Vector3d(random.normal(), random.normal(), random.normal());
            break;
        }
        cloud.addWorld(cloud.origin + p);
    }
    return cloud;
}

} // namespace stylos::test
