#include "stylos/core/synth/AnalyticSkydome.h"

#include "stylos/core/synth/DrumShape.h"
#include "stylos/core/synth/FragmentShape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stylos::core::synth {
namespace {

class DrumSolid final : public AnalyticSolid {
public:
    explicit DrumSolid(const DrumShape& drum) : m_drum(drum) {}
    bool inside(const Eigen::Vector3d& p) const override { return m_drum.inside(p); }
    double clearance(const Eigen::Vector3d& p) const override
    {
        // The solid lies in the cylinder ρ ≤ R, 0 ≤ z ≤ H: the distance to that cylinder bounds it.
        const auto& d = m_drum.parameters();
        const double radial = std::max(0.0, std::hypot(p.x(), p.y()) - d.radius);
        const double axial = std::max({0.0, -p.z(), p.z() - d.height});
        return std::hypot(radial, axial);
    }
    Eigen::Vector3d boundCentre() const override { return {0.0, 0.0, 0.5 * m_drum.parameters().height}; }
    double boundRadius() const override
    {
        return std::hypot(m_drum.parameters().radius, 0.5 * m_drum.parameters().height) * 1.001;
    }

private:
    const DrumShape& m_drum;
};

class FragmentSolid final : public AnalyticSolid {
public:
    explicit FragmentSolid(const FragmentShape& fragment) : m_fragment(fragment)
    {
        const auto& d = fragment.drum().parameters();
        const auto& f = fragment.parameters();
        m_bound = fragment.fractureBound();
        m_rMin = std::max(0.0, fragment.innerRadius() - m_bound);
        // (θ − θc)·ρ ≥ −(half·ρ + b) with ρ ≥ rMin: |θ − θc| ≤ half + b / rMin.
        m_halfAngle = f.halfAngle + (m_rMin > 0.0 ? m_bound / m_rMin : std::numbers::pi);
        m_zMin = f.zMin - m_bound;
        m_centre = fragment.scanCentre();
        for (const double rho : {m_rMin, d.radius})
            for (const double side : {-1.0, 0.0, 1.0})
                for (const double z : {m_zMin, d.height}) {
                    const double theta = f.thetaCentre + side * std::min(m_halfAngle, std::numbers::pi);
                    const Eigen::Vector3d corner(rho * std::cos(theta), rho * std::sin(theta), z);
                    m_radius = std::max(m_radius, 1.001 * (corner - m_centre).norm() + 1e-3);
                }
    }
    bool inside(const Eigen::Vector3d& p) const override { return m_fragment.inside(p); }
    double clearance(const Eigen::Vector3d& p) const override
    {
        // The distance to an intersection is at least the distance to each of the sets: the cylinder
        // ρ ≤ R, the slab zMin − b ≤ z ≤ H, ρ ≥ rIn − b and the wedge |θ − θc| ≤ halfAngle.
        const auto& d = m_fragment.drum().parameters();
        const double rho = std::hypot(p.x(), p.y());
        double c = std::max({rho - d.radius, p.z() - d.height, m_zMin - p.z(), m_rMin - rho, 0.0});
        const double outside =
            std::fabs(wrapAngle(std::atan2(p.y(), p.x()) - m_fragment.parameters().thetaCentre)) - m_halfAngle;
        if (outside > 0.0) c = std::max(c, outside >= 0.5 * std::numbers::pi ? rho : rho * std::sin(outside));
        return c;
    }
    Eigen::Vector3d boundCentre() const override { return m_centre; }
    double boundRadius() const override { return m_radius; }

private:
    const FragmentShape& m_fragment;
    double m_bound = 0.0, m_rMin = 0.0, m_halfAngle = 0.0, m_zMin = 0.0, m_radius = 0.0;
    Eigen::Vector3d m_centre;
};

} // namespace

std::unique_ptr<AnalyticSolid> drumSolid(const DrumShape& drum) { return std::make_unique<DrumSolid>(drum); }

std::unique_ptr<AnalyticSolid> fragmentSolid(const FragmentShape& fragment)
{
    return std::make_unique<FragmentSolid>(fragment);
}

std::unique_ptr<AnalyticSolid> analyticSolid(const SyntheticObject& object)
{
    if (const auto* drum = dynamic_cast<const DrumShape*>(&object)) return drumSolid(*drum);
    if (const auto* fragment = dynamic_cast<const FragmentShape*>(&object)) return fragmentSolid(*fragment);
    return nullptr;
}

bool analyticRayBlocked(const AnalyticSolid& solid, const Eigen::Vector3d& p, const Eigen::Vector3d& d,
                        const AnalyticSkydomeOptions& options)
{
    const double reach = (p - solid.boundCentre()).norm() + solid.boundRadius();
    for (double t = options.start; t <= reach;) {
        const Eigen::Vector3d q = p + t * d;
        const double clear = solid.clearance(q);
        if (clear > 0.0) {
            t += std::max(clear, options.step);
            continue;
        }
        if (solid.inside(q)) return true;
        t += options.step;
    }
    return false;
}

AnalyticSkyCount analyticSkydome(const AnalyticSolid& solid, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                                 const std::vector<std::array<double, 3>>& directions,
                                 const AnalyticSkydomeOptions& options)
{
    AnalyticSkyCount count;
    for (const auto& dir : directions) {
        const Eigen::Vector3d d(dir[0], dir[1], dir[2]);
        if (!(d.dot(n) > 0.0)) continue;
        ++count.front;
        if (!analyticRayBlocked(solid, p, d, options)) ++count.free;
    }
    return count;
}

} // namespace stylos::core::synth
