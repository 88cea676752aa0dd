#include "stylos/core/dock/GuidesFile.h"

#include "stylos/core/unroll/UnrollMap.h"
#include "stylos/core/util/JsonText.h"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace stylos::core::dock {
namespace {

nlohmann::json vectorJson(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

Error invalid(const std::string& source, const std::string& problem)
{
    return Error::at(ErrorCode::InvalidArgument, source, {}, problem);
}

bool number(const nlohmann::json& o, const char* key, double& out)
{
    const auto it = o.find(key);
    if (it == o.end() || !it->is_number()) return false;
    out = it->get<double>();
    return std::isfinite(out);
}

bool vector3(const nlohmann::json& o, const char* key, Eigen::Vector3d& out)
{
    const auto it = o.find(key);
    if (it == o.end() || !it->is_array() || it->size() != 3) return false;
    for (int k = 0; k < 3; ++k) {
        if (!(*it)[std::size_t(k)].is_number()) return false;
        out[k] = (*it)[std::size_t(k)].get<double>();
    }
    return out.allFinite();
}

} // namespace

nlohmann::json guidesToJson(const DrumGuides& g, double seconds)
{
    nlohmann::json lines = nlohmann::json::array();
    for (const FluteLine& l : g.fluteLines)
        lines.push_back({{"point", vectorJson(l.point)}, {"direction", vectorJson(l.direction)}});
    return {{"axis_point", vectorJson(g.axis.point)},
            {"axis_dir", vectorJson(g.axis.direction)},
            {"radius", g.radius},
            {"radius_slope", g.slope},
            {"flute_depth", g.fluteDepth},
            {"flutes", g.flutes},
            {"flute_lines", std::move(lines)},
            {"phase_deg", g.phase * 180.0 / std::numbers::pi},
            {"rms", g.rms},
            {"profile", g.profile},
            {"seconds", seconds}};
}

Result<DrumGuides> guidesFromJson(const nlohmann::json& o, const std::string& source)
{
    if (!o.is_object()) return invalid(source, "not a guides object");
    DrumGuides g;
    if (!vector3(o, "axis_point", g.axis.point)) return invalid(source, "axis_point must be 3 finite numbers");
    if (!vector3(o, "axis_dir", g.axis.direction) || !(g.axis.direction.norm() > 1e-12))
        return invalid(source, "axis_dir must be 3 finite numbers, not all zero");
    g.axis.direction.normalize();
    if (!number(o, "radius", g.radius) || !(g.radius > 0.0)) return invalid(source, "radius must be a positive number of metres");
    if (!number(o, "flute_depth", g.fluteDepth) || g.fluteDepth < 0.0 || g.fluteDepth >= g.radius)
        return invalid(source, "flute_depth must be a number of metres from 0 to the radius");
    const auto flutes = o.find("flutes");
    if (flutes == o.end() || !flutes->is_number_integer() || flutes->get<long long>() < 3 || flutes->get<long long>() > 1000)
        return invalid(source, "flutes must be a whole number from 3 to 1000");
    g.flutes = flutes->get<int>();
    // The lines are placed again from the count and the phase; a file whose lines disagree with its count was
    // edited by hand (a dock against it failed blaming the fragment's flutes).
    if (const auto lines = o.find("flute_lines"); lines != o.end() && lines->is_array() && !lines->empty() &&
                                                  lines->size() != std::size_t(g.flutes))
        return invalid(source, "flutes (" + std::to_string(g.flutes) + ") disagrees with its " +
                                   std::to_string(lines->size()) + " flute_lines: give the count the guides were fitted with");
    double phaseDeg = 0.0;
    if (!number(o, "phase_deg", phaseDeg)) return invalid(source, "phase_deg must be a number of degrees");
    const double pitch = 2.0 * std::numbers::pi / g.flutes;
    g.phase = phaseDeg * std::numbers::pi / 180.0;
    g.phase -= pitch * std::floor(g.phase / pitch);
    if (o.contains("rms") && !number(o, "rms", g.rms)) return invalid(source, "rms must be a number of metres");
    if (const auto profile = o.find("profile"); profile != o.end() && !profile->empty()) {
        if (!profile->is_array() || profile->size() != std::size_t(DrumGuides::ProfileBins))
            return invalid(source, "profile must be a list of " + std::to_string(DrumGuides::ProfileBins) + " radii");
        for (const auto& v : *profile) {
            if (!v.is_number() || !(v.get<double>() > 0.0) || !std::isfinite(v.get<double>()))
                return invalid(source, "profile must hold positive radii in metres");
            g.profile.push_back(v.get<double>());
        }
    }
    if (o.contains("radius_slope") && (!number(o, "radius_slope", g.slope) || !(std::abs(g.slope) < 1.0)))
        return invalid(source, "radius_slope must be a number between -1 and 1 (metres of radius per metre of axis)");
    g.reference = unroll::defaultReferenceDir(g.axis.direction);
    placeFluteLines(g);
    return g;
}

Result<DrumGuides> readGuidesFile(const std::filesystem::path& path)
{
    auto json = readJsonFile(path);
    if (!json) return json.error();
    return guidesFromJson(json.value(), path.string());
}

} // namespace stylos::core::dock
