#include "stylos/core/unroll/UnrollMap.h"

#include "stylos/core/util/AtomicTextFile.h"

#include "stylos/core/shading/HeightField.h"
#include "stylos/core/util/JsonText.h"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <cassert>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <system_error>

namespace stylos::core::unroll {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

nlohmann::json vectorJson(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

/** e1 made unit and exactly ⊥ @p a, unless it already is within 1e-12 (then kept bit for bit). */
Eigen::Vector3d orthonormalised(const Eigen::Vector3d& e1, const Eigen::Vector3d& a)
{
    if (std::abs(e1.norm() - 1.0) <= 1e-12 && std::abs(e1.dot(a)) <= 1e-12) return e1;
    return (e1 - e1.dot(a) * a).normalized();
}

} // namespace

Eigen::Vector3d defaultReferenceDir(const Eigen::Vector3d& axisDirection)
{
    const Eigen::Vector3d a = axisDirection.normalized();
    const Eigen::Vector3d seed = std::abs(a.x()) > 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
    return (seed - seed.dot(a) * a).normalized();
}

UnrollMap::UnrollMap(Surface surface, Eigen::Vector3d referenceDir, double cutAngle, double pixelSize, int width,
                     int height, double vTop)
    : m_surface(std::move(surface)), m_cutAngle(cutAngle), m_pixelSize(pixelSize), m_width(width),
      m_height(height), m_vTop(vTop)
{
    const Eigen::Vector3d& a = m_surface.axis().direction;
    assert(referenceDir.allFinite() && "UnrollMap::UnrollMap(): reference direction not finite");
    assert(referenceDir.norm() > 0.0 && std::abs(referenceDir.normalized().dot(a)) < 0.87
           && "UnrollMap::UnrollMap(): reference direction within 30 degrees of the axis");
    assert(std::isfinite(pixelSize) && pixelSize > 0.0 && "UnrollMap::UnrollMap(): pixel size not positive");
    assert(width >= 0 && height >= 0 && "UnrollMap::UnrollMap(): negative image size");
    assert(std::isfinite(cutAngle) && std::isfinite(vTop) && "UnrollMap::UnrollMap(): cut angle or v_top not finite");
    m_e1 = orthonormalised(referenceDir, a);
    m_e2 = a.cross(m_e1);
    m_circumference = kTwoPi * m_surface.referenceRadius();
}

double UnrollMap::angleFrom(double x, double y) const
{
    double angle = std::atan2(y, x) - m_cutAngle;
    angle -= kTwoPi * std::floor(angle / kTwoPi);
    if (!(angle < kTwoPi) || angle < 0.0) angle = 0.0; // −ε wraps to 2π by rounding
    return angle;
}

std::optional<Eigen::Vector3d> UnrollMap::surfaceCoords(const Eigen::Vector3d& world) const
{
    if (!world.allFinite()) return std::nullopt;
    const AxialCoords c = axialCoords(world);
    const auto coords = m_surface.meridianCoords(c.t, c.r);
    if (!coords) return std::nullopt;
    return Eigen::Vector3d(m_surface.referenceRadius() * angleFrom(c.x, c.y), coords->v, coords->h);
}

Eigen::Vector3d UnrollMap::worldAt(double u, double v, double h) const
{
    const Eigen::Vector2d tr = m_surface.meridianPoint(v, h);
    const double phi = u / m_surface.referenceRadius() + m_cutAngle;
    const Axis& axis = m_surface.axis();
    return axis.point + tr.x() * axis.direction + tr.y() * (std::cos(phi) * m_e1 + std::sin(phi) * m_e2);
}

std::optional<PixelHit> UnrollMap::pixelOf(const Eigen::Vector3d& world) const
{
    const auto coords = surfaceCoords(world);
    if (!coords) return std::nullopt;
    return PixelHit{coords->x() / m_pixelSize, (m_vTop - coords->y()) / m_pixelSize, coords->z()};
}

Eigen::Vector3d UnrollMap::worldAtPixel(double column, double row, double h) const
{
    return worldAt(column * m_pixelSize, m_vTop - row * m_pixelSize, h);
}

nlohmann::json UnrollMap::toJson() const
{
    return nlohmann::json{{"format", kFormat},
                          {"version", kVersion},
                          {"units", "metres, radians"},
                          {"surface", m_surface.toJson()},
                          {"reference_dir", vectorJson(m_e1)},
                          {"cut_angle", m_cutAngle},
                          {"pixel_size", m_pixelSize},
                          {"width", m_width},
                          {"height", m_height},
                          {"v_top", m_vTop}};
}

Result<UnrollMap> UnrollMap::fromJson(const nlohmann::json& j, const std::string& source)
{
    auto bad = [&](const std::string& key, const std::string& problem) {
        return Error::at(ErrorCode::Malformed, source, key, problem);
    };
    auto number = [&](const char* key, double& out) -> bool {
        if (!j.contains(key) || !j[key].is_number()) return false;
        out = j[key].get<double>();
        return std::isfinite(out);
    };
    auto side = [&](const char* key, int& out) -> bool {
        if (!j.contains(key) || !j[key].is_number_integer()) return false;
        const auto value = j[key].get<std::int64_t>();
        if (value < 1 || value > shading::HeightField::kMaxSide) return false;
        out = int(value);
        return true;
    };
    if (!j.is_object()) return Error::at(ErrorCode::Malformed, source, {}, "not a JSON object");
    if (!j.contains("format") || !j["format"].is_string())
        return bad("format", "is missing or not a string (expected \"" + std::string(kFormat) + "\")");
    if (j["format"].get<std::string>() != kFormat)
        return bad("format", "is \"" + j["format"].get<std::string>() + "\", not \"" + kFormat + "\"");
    if (!j.contains("version") || !j["version"].is_number_integer())
        return bad("version", "is missing or not an integer");
    if (j["version"].get<std::int64_t>() != kVersion)
        return bad("version", "is " + j["version"].dump() + "; this build reads version " + std::to_string(kVersion));
    if (!j.contains("surface")) return bad("surface", "is missing");
    auto surface = Surface::fromJson(j["surface"], source);
    if (!surface) return Error{ErrorCode::Malformed, surface.error().message};

    Eigen::Vector3d e1;
    const auto& jdir = j.contains("reference_dir") ? j["reference_dir"] : nlohmann::json();
    bool dirOk = jdir.is_array() && jdir.size() == 3;
    for (std::size_t i = 0; dirOk && i < 3; ++i) {
        dirOk = jdir[i].is_number();
        if (dirOk) e1[int(i)] = jdir[i].get<double>();
    }
    if (!dirOk || !e1.allFinite()) return bad("reference_dir", "is missing or not 3 finite numbers");
    if (std::abs(e1.norm() - 1.0) > 1e-6 || std::abs(e1.dot(surface->axis().direction)) > 1e-6)
        return bad("reference_dir", "is not a unit vector perpendicular to the axis");

    double cut = 0, pixel = 0, vTop = 0;
    int width = 0, height = 0;
    if (!number("cut_angle", cut)) return bad("cut_angle", "is missing or not a finite number");
    if (!number("pixel_size", pixel) || !(pixel > 0.0))
        return bad("pixel_size", "is missing or not a positive number");
    const std::string sideRange = "is missing or not an integer in [1, " + std::to_string(shading::HeightField::kMaxSide) + "]";
    if (!side("width", width)) return bad("width", sideRange);
    if (!side("height", height)) return bad("height", sideRange);
    if (!number("v_top", vTop)) return bad("v_top", "is missing or not a finite number");
    return UnrollMap(std::move(surface).value(), e1, cut, pixel, width, height, vTop);
}

Status UnrollMap::writeSidecar(const std::filesystem::path& path) const
{
    return writeTextFileAtomically(path, toJson().dump(2) + "\n");
}

Result<UnrollMap> UnrollMap::readSidecar(const std::filesystem::path& path)
{
    auto json = readJsonFile(path);
    if (!json) return json.error();
    return fromJson(json.value(), path.string());
}

} // namespace stylos::core::unroll
