#include "stylos/core/synth/DrumShape.h"

#include "stylos/core/synth/Random.h"
#include "stylos/core/synth/SyntheticScan.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace stylos::core::synth {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kClawCell = 0.04;        ///< length of one set of claw strokes along the band, metres
constexpr double kClawStrokeAngle = 1.05; ///< strokes' angle to the horizontal, radians (≈ 60°)
constexpr double kRecessEdge = 0.005;     ///< width of the slope from the contact ring to the recess

double smoothStep(double t)
{
    t = std::clamp(t, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

} // namespace

DrumParameters DrumParameters::fromOptions(const SyntheticOptions& options, Random& random)
{
    DrumParameters p;
    p.radius = options.radius;
    p.height = options.height;
    p.grooves = options.grooves;
    p.grooveDepth = options.grooveDepth;
    p.taper = options.taper;
    const double h = p.height;
    p.clawMin = 0.84 * h;
    p.clawMax = 0.92 * h;
    p.brokenZMin = 0.2 * h;
    p.brokenZMax = 0.56 * h;
    p.brokenDepth = std::min(0.035, 0.1 * p.radius);
    p.fractureRoughness = std::min(0.004, 0.2 * p.brokenDepth);
    p.ringWidth = std::min(0.08, 0.2 * p.radius);
    p.groovePhase = p.grooves > 0 ? random.uniform(0.0, kTwoPi / p.grooves) : 0.0;
    p.brokenCentre = random.uniform(0.0, kTwoPi);
    p.brokenHalfAngle = std::min(0.26, 0.2 * kTwoPi);
    p.noiseSeed = random.bits();
    return p;
}

std::string DrumParameters::problem() const
{
    if (!(radius > 0.0) || !(height > 0.0) || !std::isfinite(radius) || !std::isfinite(height))
        return "drum radius and height must be positive";
    if (!std::isfinite(taper) || std::fabs(taper) > 0.2 * radius)
        return "the taper must lie within a fifth of the radius (" + std::to_string(std::lround(200.0 * radius)) + " mm)";
    if (grooves == 0) return {};
    if (grooves < 3 || grooves > 1000) return "groove count must be 0 or between 3 and 1000";
    if (!(filletFraction >= 0.0 && filletFraction < 1.0)) return "fillet fraction must be in [0, 1)";
    const double halfWidth = 0.5 * (kTwoPi / grooves) * (1.0 - filletFraction);
    const double flat = radius * (1.0 - std::cos(halfWidth));
    if (!(grooveDepth > flat) || !(grooveDepth < 0.25 * radius))
        return "groove depth must lie between " + std::to_string(flat) + " m (a flat flute) and a quarter "
               "of the radius";
    return {};
}

DrumShape::DrumShape(const DrumParameters& parameters)
    : m_p(parameters),
      m_fracture(Random::derive(parameters.noiseSeed, 1), 0.06, parameters.fractureRoughness, 5),
      m_dressing(Random::derive(parameters.noiseSeed, 2), 0.01, parameters.bedRoughness, 4)
{
    if (m_p.grooves > 0) {
        const double r = m_p.radius;
        const double d = m_p.grooveDepth;
        m_pitch = kTwoPi / m_p.grooves;
        m_halfWidth = 0.5 * m_pitch * (1.0 - m_p.filletFraction);
        // The arc through the groove's edges (radius R, azimuth ±halfWidth) and its bottom (R - d, 0):
        // centre on the groove's mid-line at distance c from the axis, outside the drum.
        m_arcCentre = ((r - d) * (r - d) - r * r) / (2.0 * (r - d - r * std::cos(m_halfWidth)));
        m_arcRadius = m_arcCentre - (r - d);
    }
    const Eigen::Vector2d axis = Eigen::Vector2d::Zero();
    m_lateral = std::make_unique<DrumLateralPatch>(*this, DrumPatchRange{0.0, 0.0, 0.0, m_p.height}, axis);
    m_bottom = std::make_unique<DrumBedPatch>(*this, false, DrumPatchRange{0.0, 0.0, 0.0, m_p.radius}, axis);
    m_top = std::make_unique<DrumBedPatch>(*this, true, DrumPatchRange{0.0, 0.0, 0.0, m_p.radius}, axis);
}

double DrumShape::fluteRadius(double theta) const
{
    if (m_p.grooves == 0) return m_p.radius;
    double phi = theta - m_p.groovePhase;
    phi -= m_pitch * std::nearbyint(phi / m_pitch);
    if (std::fabs(phi) >= m_halfWidth) return m_p.radius;
    const double s = m_arcCentre * std::sin(phi);
    return m_arcCentre * std::cos(phi) - std::sqrt(m_arcRadius * m_arcRadius - s * s);
}

double DrumShape::clawMarks(double theta, double z) const
{
    if (!m_p.clawBand || z < m_p.clawMin || z > m_p.clawMax) return 0.0;
    // Sets of parallel tooth furrows, alternately tilted one way and the other along the band.
    const double u = m_p.radius * (theta - kTwoPi * std::floor(theta / kTwoPi));
    const double cell = std::floor(u / kClawCell);
    const double tilt = std::fmod(cell, 2.0) == 0.0 ? kClawStrokeAngle : -kClawStrokeAngle;
    const double across = u * std::sin(tilt) - z * std::cos(tilt);
    return m_p.clawDepth * 0.5 * (1.0 - std::cos(kTwoPi * across / m_p.clawPitch));
}

double DrumShape::cavityRadius(double theta, double z) const
{
    if (!m_p.broken) return std::numeric_limits<double>::infinity();
    const double dTheta = wrapAngle(theta - m_p.brokenCentre);
    const double zCentre = 0.5 * (m_p.brokenZMin + m_p.brokenZMax);
    const double zHalf = 0.5 * (m_p.brokenZMax - m_p.brokenZMin);
    const double qa = dTheta / m_p.brokenHalfAngle;
    const double qz = (z - zCentre) / zHalf;
    const double q = qa * qa + qz * qz;
    if (q >= 1.0) return std::numeric_limits<double>::infinity();
    const double rough = m_fracture.value(m_p.radius * dTheta, z);
    return m_p.radius - std::sqrt(1.0 - q) * (m_p.brokenDepth + rough);
}

double DrumShape::lateralRadius(double theta, double z) const
{
    return scaleAt(z) * std::min(fluteRadius(theta) - clawMarks(theta, z), cavityRadius(theta, z));
}

double DrumShape::bedDepth(double x, double y, bool top) const
{
    const double inner = m_p.radius - m_p.ringWidth;
    const double rho = std::sqrt(x * x + y * y);
    if (!m_p.anathyrosis || rho >= inner) return 0.0;
    const double slope = smoothStep((inner - rho) / kRecessEdge);
    // The dressing is shifted to be ≥ 0 (no crease, so the normals stay defined everywhere).
    const double dressing = m_dressing.value(x + (top ? 17.0 : 0.0), y);
    return slope * (m_p.recess + 0.5 * (dressing + m_dressing.bound()));
}

double DrumShape::maxLateralDepth() const
{
    const double flutes = (m_p.grooves > 0 ? m_p.grooveDepth : 0.0) + (m_p.clawBand ? m_p.clawDepth : 0.0);
    const double cavity = m_p.broken ? m_p.brokenDepth + m_fracture.bound() : 0.0;
    return std::max(flutes, cavity);
}

bool DrumShape::inside(const Eigen::Vector3d& p) const
{
    if (!(p.z() > 0.0 && p.z() < m_p.height)) return false;
    const double rho = std::hypot(p.x(), p.y());
    if (rho >= m_p.radius * std::max(scaleAt(0.0), scaleAt(m_p.height))) return false; // a quick test (taper < 0 widens)
    if (!(p.z() > bedDepth(p.x(), p.y(), false) && p.z() < m_p.height - bedDepth(p.x(), p.y(), true))) return false;
    return rho < lateralRadius(std::atan2(p.y(), p.x()), p.z());
}

std::vector<const SurfacePatch*> DrumShape::patches() const
{
    return {m_lateral.get(), m_bottom.get(), m_top.get()};
}

nlohmann::json DrumShape::drumTruth() const
{
    using nlohmann::json;
    json t;
    t["radius"] = m_p.radius;
    t["height"] = m_p.height;
    t["taper"] = m_p.taper;
    t["radiusTop"] = m_p.radius - m_p.taper;
    t["maxLateralDepth"] = maxLateralDepth();
    t["grooves"] = {{"count", m_p.grooves},        {"depth", m_p.grooves > 0 ? m_p.grooveDepth : 0.0},
                    {"phase", m_p.groovePhase},    {"pitch", m_pitch},
                    {"halfWidth", m_halfWidth},    {"filletFraction", m_p.filletFraction},
                    {"arcRadius", m_arcRadius},    {"arcCentreDistance", m_arcCentre}};
    t["clawBand"] = {{"present", m_p.clawBand}, {"vMin", m_p.clawMin}, {"vMax", m_p.clawMax},
                     {"depth", m_p.clawDepth},  {"pitch", m_p.clawPitch}};
    // The angular range may straddle θ = 0: thetaMin < 0 or thetaMax > 2π.
    t["broken"] = {{"present", m_p.broken},
                   {"thetaCentre", m_p.brokenCentre},
                   {"halfAngle", m_p.brokenHalfAngle},
                   {"thetaMin", m_p.brokenCentre - m_p.brokenHalfAngle},
                   {"thetaMax", m_p.brokenCentre + m_p.brokenHalfAngle},
                   {"zMin", m_p.brokenZMin},
                   {"zMax", m_p.brokenZMax},
                   {"centreDepth", m_p.brokenDepth},
                   {"maxDepth", m_p.brokenDepth + m_fracture.bound()}};
    t["anathyrosis"] = {{"present", m_p.anathyrosis}, {"ringWidth", m_p.ringWidth},
                        {"recess", m_p.recess}, {"maxDepth", m_p.recess + m_dressing.bound()}};
    t["anathyrosis"]["roughness"] = m_p.bedRoughness;
    return t;
}

void DrumShape::describe(nlohmann::json& truth) const
{
    const nlohmann::json drum = drumTruth();
    for (const auto& [key, value] : drum.items()) truth[key] = value;
}

} // namespace stylos::core::synth
