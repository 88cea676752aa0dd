#include "stylos/core/unroll/Surface.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace stylos::core::unroll {

namespace {

Error invalid(const std::string& problem) { return Error{ErrorCode::InvalidArgument, "surface: " + problem}; }

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

Status checkAxis(const Axis& axis)
{
    if (!finite(axis.point) || !finite(axis.direction)) return invalid("the axis is not finite");
    if (std::abs(axis.direction.norm() - 1.0) > 1e-9) return invalid("the axis direction is not a unit vector");
    return {};
}

bool positive(double x) { return std::isfinite(x) && x > 0.0; }

nlohmann::json vectorJson(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

} // namespace

const char* surfaceKindName(SurfaceKind kind)
{
    switch (kind) {
    case SurfaceKind::Cylinder: return "cylinder";
    case SurfaceKind::Cone: return "cone";
    case SurfaceKind::Revolution: return "revolution";
    }
    return "cylinder";
}

std::optional<SurfaceKind> surfaceKindFromName(std::string_view name)
{
    for (SurfaceKind kind : {SurfaceKind::Cylinder, SurfaceKind::Cone, SurfaceKind::Revolution})
        if (name == surfaceKindName(kind)) return kind;
    return std::nullopt;
}

Result<Surface> Surface::cylinder(const Axis& axis, double radius)
{
    if (auto s = checkAxis(axis); !s) return s.error();
    if (!positive(radius)) return invalid("the radius must be a positive length");
    Surface surface;
    surface.m_kind = SurfaceKind::Cylinder;
    surface.m_axis = axis;
    surface.m_radius = radius;
    surface.m_referenceRadius = radius;
    return surface;
}

Result<Surface> Surface::cone(const Axis& axis, double radius, double slope, double referenceRadius)
{
    if (auto s = checkAxis(axis); !s) return s.error();
    if (!positive(radius) || !positive(referenceRadius)) return invalid("the radii must be positive lengths");
    if (!std::isfinite(slope)) return invalid("the slope is not finite");
    Surface surface;
    surface.m_kind = SurfaceKind::Cone;
    surface.m_axis = axis;
    surface.m_radius = radius;
    surface.m_slope = slope;
    surface.m_referenceRadius = referenceRadius;
    return surface;
}

Result<Surface> Surface::revolution(const Axis& axis, Meridian meridian, double referenceRadius)
{
    if (auto s = checkAxis(axis); !s) return s.error();
    if (!positive(referenceRadius)) return invalid("the reference radius must be a positive length");
    Surface surface;
    surface.m_kind = SurfaceKind::Revolution;
    surface.m_axis = axis;
    surface.m_radius = referenceRadius;
    surface.m_referenceRadius = referenceRadius;
    surface.m_meridian = std::make_shared<const Meridian>(std::move(meridian));
    return surface;
}

std::optional<MeridianCoords> Surface::meridianCoords(double t, double r) const
{
    switch (m_kind) {
    case SurfaceKind::Cylinder: return MeridianCoords{t, r - m_radius};
    case SurfaceKind::Cone: return MeridianCoords{t, r - (m_radius + m_slope * t)};
    case SurfaceKind::Revolution: return m_meridian->project(t, r);
    }
    return std::nullopt;
}

Eigen::Vector2d Surface::meridianPoint(double v, double h) const
{
    switch (m_kind) {
    case SurfaceKind::Cylinder: return {v, m_radius + h};
    case SurfaceKind::Cone: return {v, m_radius + m_slope * v + h};
    case SurfaceKind::Revolution: return m_meridian->point(v, h);
    }
    return {v, m_radius + h};
}

nlohmann::json Surface::toJson() const
{
    nlohmann::json j{{"kind", surfaceKindName(m_kind)},
                     {"axis_point", vectorJson(m_axis.point)},
                     {"axis_dir", vectorJson(m_axis.direction)},
                     {"radius", m_radius},
                     {"reference_radius", m_referenceRadius}};
    if (m_kind == SurfaceKind::Cone) j["slope"] = m_slope;
    if (m_kind == SurfaceKind::Revolution) {
        nlohmann::json vertices = nlohmann::json::array();
        for (const Eigen::Vector2d& v : m_meridian->vertices()) vertices.push_back({v.x(), v.y()});
        j["meridian"] = std::move(vertices);
        j["reach"] = m_meridian->reach();
    }
    return j;
}

Result<Surface> Surface::fromJson(const nlohmann::json& j, const std::string& source)
{
    auto bad = [&](const std::string& key, const std::string& problem) {
        return Error::at(ErrorCode::Malformed, source, "surface." + key, problem);
    };
    auto number = [&](const char* key, double& out) -> bool {
        if (!j.contains(key) || !j[key].is_number()) return false;
        out = j[key].get<double>();
        return std::isfinite(out);
    };
    auto vector = [&](const char* key, Eigen::Vector3d& out) -> bool {
        if (!j.contains(key) || !j[key].is_array() || j[key].size() != 3) return false;
        for (int i = 0; i < 3; ++i) {
            if (!j[key][std::size_t(i)].is_number()) return false;
            out[i] = j[key][std::size_t(i)].get<double>();
        }
        return out.allFinite();
    };
    if (!j.is_object()) return Error::at(ErrorCode::Malformed, source, "surface", "is not a JSON object");
    if (!j.contains("kind") || !j["kind"].is_string()) return bad("kind", "is missing or not a string");
    const std::string kindName = j["kind"].get<std::string>();
    const auto kind = surfaceKindFromName(kindName);
    if (!kind) return bad("kind", "is \"" + kindName + "\", not cylinder, cone or revolution");
    Axis axis;
    if (!vector("axis_point", axis.point)) return bad("axis_point", "is missing or not 3 finite numbers");
    if (!vector("axis_dir", axis.direction)) return bad("axis_dir", "is missing or not 3 finite numbers");
    if (axis.direction.norm() < 1e-12) return bad("axis_dir", "is a zero vector");
    // Written with 17 significant digits a unit vector reads back exactly; a hand-edited one may not be unit.
    if (std::abs(axis.direction.norm() - 1.0) > 1e-12) axis.direction.normalize();
    double radius = 0, reference = 0, slope = 0, reach = 0;
    if (!number("radius", radius)) return bad("radius", "is missing or not a finite number");
    if (!number("reference_radius", reference)) return bad("reference_radius", "is missing or not a finite number");
    Result<Surface> surface = invalid("unreachable");
    switch (*kind) {
    case SurfaceKind::Cylinder: surface = cylinder(axis, radius); break;
    case SurfaceKind::Cone:
        if (!number("slope", slope)) return bad("slope", "is missing or not a finite number");
        surface = cone(axis, radius, slope, reference);
        break;
    case SurfaceKind::Revolution: {
        if (!number("reach", reach)) return bad("reach", "is missing or not a finite number");
        if (!j.contains("meridian") || !j["meridian"].is_array()) return bad("meridian", "is missing or not an array");
        std::vector<Eigen::Vector2d> vertices;
        for (const auto& v : j["meridian"]) {
            if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
                return bad("meridian", "holds a vertex that is not a pair of numbers");
            vertices.emplace_back(v[0].get<double>(), v[1].get<double>());
        }
        auto meridian = Meridian::create(std::move(vertices), reach);
        if (!meridian) return bad("meridian", meridian.error().message);
        surface = revolution(axis, std::move(meridian).value(), reference);
        break;
    }
    }
    if (!surface) return Error::at(ErrorCode::Malformed, source, "surface", surface.error().message);
    return surface;
}

} // namespace stylos::core::unroll
