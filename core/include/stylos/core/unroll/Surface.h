#pragma once
/** @file
 * @brief The fitted surface a développée is unrolled from: a cylinder, a cone or a general surface of
 *        revolution about an axis, with the meridian coordinates every point maps to.
 *
 * Axis: a world point and a unit direction. t = (p − axis.point) · axis.direction is the axial
 * coordinate, r = |(p − axis.point) − t · direction| the distance from the axis.
 *   - Cylinder: r = radius. v = t, h = r − radius.
 *   - Cone: r(t) = radius + slope · t (radius at the axis point, slope = dr/dt = tan of the half-angle,
 *     positive when widening toward +direction). v = t, h = r − r(t) (radial height).
 *   - Revolution: a Meridian (Meridian.h) in the (t, r) plane; v = arc length along it, h = height
 *     along its interpolated normal.
 * referenceRadius() is the radius at which the unroller measures arc length around the axis
 * (u = referenceRadius · angle): the radius of the cylinder, the mean radius of the cone over the fitted
 * points, the arc-length-weighted mean radius of a meridian (SurfaceFit chooses it; any value > 0).
 *
 * Units: metres. Thread-safety: a value type, immutable after construction (a revolution shares its
 * immutable Meridian); concurrent use is safe. Failure modes: the factories return InvalidArgument for
 * a non-unit or non-finite axis, a radius ≤ 0, a bad meridian.
 */
#include "stylos/core/unroll/Meridian.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stylos::core::unroll {

enum class SurfaceKind { Cylinder, Cone, Revolution };

/** "cylinder", "cone", "revolution". */
const char* surfaceKindName(SurfaceKind kind);
/** The kind named @p name (as surfaceKindName writes it); nullopt otherwise. */
std::optional<SurfaceKind> surfaceKindFromName(std::string_view name);

/** @brief A line in world coordinates: a point and a unit direction, metres. */
struct Axis {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

class Surface {
public:
    /** Checks the axis (finite, |direction| within 1e-9 of 1) and radius (finite, > 0). */
    static Result<Surface> cylinder(const Axis& axis, double radius);
    /** radius at the axis point (> 0), slope finite. */
    static Result<Surface> cone(const Axis& axis, double radius, double slope, double referenceRadius);
    /** @p meridian in this axis's (t, r) frame; referenceRadius > 0. */
    static Result<Surface> revolution(const Axis& axis, Meridian meridian, double referenceRadius);

    SurfaceKind kind() const { return m_kind; }
    const Axis& axis() const { return m_axis; }
    /** Radius at which arc length around the axis is measured (u = referenceRadius · angle), metres. */
    double referenceRadius() const { return m_referenceRadius; }
    /** Cylinder: its radius; cone: the radius at the axis point; revolution: referenceRadius(). */
    double radius() const { return m_radius; }
    /** Cone: dr/dt; 0 otherwise. */
    double slope() const { return m_slope; }
    /** The meridian of a revolution; nullptr otherwise. */
    const Meridian* meridian() const { return m_meridian.get(); }

    /** Axial coordinate t of a world point, metres. */
    double axial(const Eigen::Vector3d& p) const { return (p - m_axis.point).dot(m_axis.direction); }
    /** @brief (v, h) of the point at axial coordinate @p t and distance @p r from the axis; nullopt for
     *         a revolution when the point is farther than the meridian's reach. */
    std::optional<MeridianCoords> meridianCoords(double t, double r) const;
    /** @brief The (t, r) at meridian coordinates (v, h): the exact inverse of meridianCoords(). */
    Eigen::Vector2d meridianPoint(double v, double h) const;

    /** {"kind", "axis_point", "axis_dir", "radius", "reference_radius", "slope", "meridian": [[t, r], ...]}
     *  (slope for a cone, meridian and its "reach" for a revolution). */
    nlohmann::json toJson() const;
    /** Reads toJson()'s object; InvalidArgument naming @p source and the key that is missing or wrong. */
    static Result<Surface> fromJson(const nlohmann::json& json, const std::string& source);

private:
    Surface() = default;
    SurfaceKind m_kind = SurfaceKind::Cylinder;
    Axis m_axis;
    double m_radius = 1.0;
    double m_slope = 0.0;
    double m_referenceRadius = 1.0;
    std::shared_ptr<const Meridian> m_meridian;
};

} // namespace stylos::core::unroll
