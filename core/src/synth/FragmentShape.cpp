#include "stylos/core/synth/FragmentShape.h"

#include "stylos/core/synth/Random.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stylos::core::synth {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kFractureWavelength = 0.08; ///< coarsest octave of the fracture faces, metres
constexpr int kFractureOctaves = 5;

DrumParameters unbroken(DrumParameters drum)
{
    drum.broken = false; // the fragment is itself what broke away
    return drum;
}

} // namespace

/** @brief A fracture face: the sides (a = r, b = z), the inner face (a = arc at the inner radius,
 *         b = z) and the lower face (a = across the sector, b = along its middle radius). */
class FragmentShape::FracturePatch final : public SurfacePatch {
public:
    FracturePatch(const FragmentShape& shape, Face face) : m_shape(shape), m_face(face)
    {
        const DrumParameters& d = shape.m_drum.parameters();
        const double margin = shape.fractureBound() + 0.005;
        const double rIn = shape.innerRadius();
        const double sector = shape.m_f.halfAngle + margin / rIn;
        switch (face) {
        case Face::SideLow:
        case Face::SideHigh:
            m_rows = {shape.m_f.zMin - margin, d.height, false};
            m_columns = {rIn - margin, d.radius + margin, false};
            m_orientation = face == Face::SideLow ? 1.0 : -1.0;
            break;
        case Face::Inner:
            m_rows = {shape.m_f.zMin - margin, d.height, false};
            m_columns = {-sector * rIn, sector * rIn, false};
            m_orientation = -1.0;
            break;
        default: // Bottom
            m_rows = {rIn - margin, d.radius + margin, false};
            m_columns = {-(d.radius + margin) * std::sin(sector), (d.radius + margin) * std::sin(sector), false};
            m_orientation = 1.0;
            break;
        }
        m_centre = shape.scanCentre().head<2>();
    }

    ParameterRange rows() const override { return m_rows; }
    ParameterRange columns(double) const override { return m_columns; }
    double azimuth(double a, double b) const override
    {
        const FragmentParameters& f = m_shape.m_f;
        double x = 0.0;
        double y = 0.0;
        if (m_face == Face::Bottom) {
            x = b * std::cos(f.thetaCentre) - a * std::sin(f.thetaCentre);
            y = b * std::sin(f.thetaCentre) + a * std::cos(f.thetaCentre);
        } else {
            const double rIn = m_shape.innerRadius();
            const double r = m_face == Face::Inner ? rIn : a;
            const double theta = m_face == Face::Inner  ? f.thetaCentre + a / rIn
                                 : m_face == Face::SideLow ? f.thetaCentre - f.halfAngle
                                                           : f.thetaCentre + f.halfAngle;
            x = r * std::cos(theta);
            y = r * std::sin(theta);
        }
        return std::atan2(y - m_centre.y(), x - m_centre.x());
    }
    Eigen::Vector3d position(double a, double b) const override { return m_shape.fracturePoint(m_face, a, b); }
    bool contains(double, double, const Eigen::Vector3d& p) const override { return m_shape.inside(p, m_face); }

private:
    const FragmentShape& m_shape;
    Face m_face;
    ParameterRange m_rows;
    ParameterRange m_columns;
    Eigen::Vector2d m_centre;
};

FragmentParameters FragmentParameters::random(const DrumParameters& drum, Random& random)
{
    FragmentParameters f;
    f.thetaCentre = random.uniform(0.0, kTwoPi);
    f.zMin = 0.45 * drum.height;
    f.thickness = std::min(0.18, 0.4 * drum.radius);
    f.roughness = std::min(0.006, 0.05 * f.thickness);
    f.noiseSeed = random.bits();
    return f;
}

FragmentShape::FragmentShape(const DrumParameters& drum, const FragmentParameters& fragment)
    : m_drum(unbroken(drum)), m_f(fragment),
      m_sideLow(Random::derive(fragment.noiseSeed, 1), kFractureWavelength, fragment.roughness, kFractureOctaves),
      m_sideHigh(Random::derive(fragment.noiseSeed, 2), kFractureWavelength, fragment.roughness, kFractureOctaves),
      m_inner(Random::derive(fragment.noiseSeed, 3), kFractureWavelength, fragment.roughness, kFractureOctaves),
      m_bottom(Random::derive(fragment.noiseSeed, 4), kFractureWavelength, fragment.roughness, kFractureOctaves)
{
    const DrumParameters& d = m_drum.parameters();
    const double margin = fractureBound() + 0.005;
    const double sector = m_f.halfAngle + margin / innerRadius();
    const Eigen::Vector2d centre = scanCentre().head<2>();
    const DrumPatchRange lateral{m_f.thetaCentre - sector, m_f.thetaCentre + sector, m_f.zMin - margin, d.height};
    const DrumPatchRange bed{m_f.thetaCentre - sector, m_f.thetaCentre + sector, innerRadius() - margin, d.radius};
    m_outer = std::make_unique<DrumLateralPatch>(m_drum, lateral, centre,
                                                 [this](const Eigen::Vector3d& p) { return inside(p, Face::Outer); });
    m_top = std::make_unique<DrumBedPatch>(m_drum, true, bed, centre,
                                           [this](const Eigen::Vector3d& p) { return inside(p, Face::Top); });
    const Face faces[] = {Face::SideLow, Face::SideHigh, Face::Inner, Face::Bottom};
    for (std::size_t i = 0; i < 4; ++i) m_fractures[i] = std::make_unique<FracturePatch>(*this, faces[i]);
}

FragmentShape::~FragmentShape() = default;

bool FragmentShape::inside(const Eigen::Vector3d& p, Face except) const
{
    const DrumParameters& d = m_drum.parameters();
    const double r = std::hypot(p.x(), p.y());
    const double theta = std::atan2(p.y(), p.x());
    const double dTheta = wrapAngle(theta - m_f.thetaCentre);
    if (except != Face::Outer && r > m_drum.lateralRadius(theta, p.z())) return false;
    if (except != Face::Top && p.z() > d.height - m_drum.bedDepth(p.x(), p.y(), true)) return false;
    // Each fracture face lies within ±bound of its nominal surface: the noise is evaluated only in that
    // slab (a distance d beyond the nominal surface, inwards positive, is inside when d ≥ noise).
    const double bound = fractureBound();
    auto beyond = [bound](double d, auto&& noise) {
        if (d >= bound) return true;
        if (d < -bound) return false;
        return d >= noise();
    };
    const double rIn = innerRadius();
    const double z = p.z();
    if (except != Face::SideLow && !beyond((dTheta + m_f.halfAngle) * r, [&] { return m_sideLow.value(r, z); }))
        return false;
    if (except != Face::SideHigh && !beyond((m_f.halfAngle - dTheta) * r, [&] { return -m_sideHigh.value(r, z); }))
        return false;
    if (except != Face::Inner && !beyond(r - rIn, [&] { return m_inner.value(dTheta * rIn, z); })) return false;
    if (except != Face::Bottom &&
        !beyond(z - m_f.zMin, [&] { return m_bottom.value(r * std::cos(dTheta), r * std::sin(dTheta)); }))
        return false;
    return true;
}

Eigen::Vector3d FragmentShape::fracturePoint(Face face, double a, double b) const
{
    const double rIn = innerRadius();
    double r = a;
    double theta = 0.0;
    switch (face) {
    case Face::SideLow: theta = m_f.thetaCentre - m_f.halfAngle + m_sideLow.value(a, b) / a; break;
    case Face::SideHigh: theta = m_f.thetaCentre + m_f.halfAngle + m_sideHigh.value(a, b) / a; break;
    case Face::Inner:
        theta = m_f.thetaCentre + a / rIn;
        r = rIn + m_inner.value(a, b);
        break;
    default: { // Bottom: b along the sector's middle radius, a across it
        const double c = std::cos(m_f.thetaCentre);
        const double s = std::sin(m_f.thetaCentre);
        return {b * c - a * s, b * s + a * c, m_f.zMin + m_bottom.value(b, a)};
    }
    }
    return {r * std::cos(theta), r * std::sin(theta), b};
}

std::vector<const SurfacePatch*> FragmentShape::patches() const
{
    std::vector<const SurfacePatch*> list{m_outer.get(), m_top.get()};
    for (const auto& patch : m_fractures) list.push_back(patch.get());
    return list;
}

Eigen::Vector3d FragmentShape::scanCentre() const
{
    const DrumParameters& d = m_drum.parameters();
    const double r = 0.5 * (d.radius + innerRadius());
    return {r * std::cos(m_f.thetaCentre), r * std::sin(m_f.thetaCentre), 0.5 * (m_f.zMin + d.height)};
}

double FragmentShape::extent() const
{
    const DrumParameters& d = m_drum.parameters();
    const double margin = fractureBound() + 0.005;
    return std::hypot(0.5 * m_f.thickness + margin, d.radius * std::sin(m_f.halfAngle) + margin);
}

void FragmentShape::describe(nlohmann::json& truth) const
{
    m_drum.describe(truth);
    truth["fragment"] = {{"thetaCentre", m_f.thetaCentre},
                         {"halfAngle", m_f.halfAngle},
                         {"thetaMin", m_f.thetaCentre - m_f.halfAngle},
                         {"thetaMax", m_f.thetaCentre + m_f.halfAngle},
                         {"zMin", m_f.zMin},
                         {"zMax", m_drum.parameters().height},
                         {"innerRadius", innerRadius()},
                         {"thickness", m_f.thickness},
                         {"roughness", m_f.roughness},
                         {"fractureBound", fractureBound()},
                         {"bedFace", "top"}};
}

} // namespace stylos::core::synth
