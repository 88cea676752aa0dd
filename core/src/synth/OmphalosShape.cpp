#include "stylos/core/synth/OmphalosShape.h"

#include "stylos/core/synth/Random.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stylos::core::synth {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kTableStep = 0.0002; ///< meridian table resolution, metres
constexpr int kDenseEgg = 200000;     ///< egg samples when building the table
constexpr int kProfileSamples = 241;  ///< rows of the profile table in the sidecar

} // namespace

/** @brief The revolved meridian: a = r·θ, b = arc length s along the meridian. */
class OmphalosShape::Patch final : public SurfacePatch {
public:
    explicit Patch(const OmphalosShape& shape) : m_shape(shape) { m_orientation = 1.0; }

    ParameterRange rows() const override { return {0.0, m_shape.meridianLength(), false}; }
    ParameterRange columns(double b) const override { return {0.0, kTwoPi * m_shape.meridian(b).r, true}; }
    double azimuth(double a, double b) const override
    {
        const double r = m_shape.meridian(b).r;
        return r > 0.0 ? a / r : 0.0;
    }
    double azimuthScale(double b) const override
    {
        const double r = m_shape.meridian(b).r;
        return r > 0.0 ? 1.0 / r : 0.0;
    }
    Eigen::Vector3d position(double a, double b) const override
    {
        const MeridianPoint m = m_shape.meridian(b);
        const double theta = m.r > 0.0 ? a / m.r : 0.0;
        const double h = m_shape.netHeight(theta, b);
        const double rho = m.r + h * m.nr;
        return {rho * std::cos(theta), rho * std::sin(theta), m.z + h * m.nz};
    }
    Eigen::Vector3d normal(double a, double b) const override
    {
        if (m_shape.meridian(b).r < 2.0 * m_normalStep) return Eigen::Vector3d::UnitZ(); // the apex
        return SurfacePatch::normal(a, b);
    }

private:
    const OmphalosShape& m_shape;
};

OmphalosParameters OmphalosParameters::random(Random& random)
{
    OmphalosParameters p;
    p.netPhase = random.uniform(0.0, kTwoPi / p.meshesAround);
    return p;
}

OmphalosShape::OmphalosShape(const OmphalosParameters& parameters) : m_p(parameters)
{
    // A dense polyline of the meridian: plinth side (up), plinth top (inwards), egg (up to the apex).
    std::vector<Eigen::Vector2d> dense;
    const double psiCut = std::asin(m_p.cut);
    auto egg = [&](double psi) {
        const double w = m_p.semiAxis * std::sin(psi);
        return Eigen::Vector2d(m_p.radius * std::cos(psi) * (1.0 - m_p.asymmetry * std::sin(psi)),
                               m_p.plinthHeight + w - m_p.cut * m_p.semiAxis);
    };
    dense.emplace_back(m_p.plinthRadius, 0.0);
    dense.emplace_back(m_p.plinthRadius, m_p.plinthHeight);
    for (int i = 0; i <= kDenseEgg; ++i)
        dense.push_back(egg(psiCut + (0.5 * std::numbers::pi - psiCut) * i / kDenseEgg));
    dense.back().x() = 0.0;

    std::vector<double> cumulative(dense.size(), 0.0);
    for (std::size_t i = 1; i < dense.size(); ++i)
        cumulative[i] = cumulative[i - 1] + (dense[i] - dense[i - 1]).norm();
    m_length = cumulative.back();
    m_bodyStart = cumulative[2];
    const auto entries = static_cast<std::size_t>(std::ceil(m_length / kTableStep)) + 1;
    m_step = m_length / static_cast<double>(entries - 1);
    m_table.reserve(entries);
    std::size_t j = 0;
    for (std::size_t i = 0; i < entries; ++i) {
        const double s = std::min(m_length, static_cast<double>(i) * m_step);
        while (j + 2 < dense.size() && cumulative[j + 1] < s) ++j;
        const double length = cumulative[j + 1] - cumulative[j];
        const double t = length > 0.0 ? std::clamp((s - cumulative[j]) / length, 0.0, 1.0) : 0.0;
        const Eigen::Vector2d p = dense[j] + t * (dense[j + 1] - dense[j]);
        const Eigen::Vector2d tangent = (dense[j + 1] - dense[j]).normalized();
        m_table.push_back({p.x(), p.y(), tangent.y(), -tangent.x()});
    }
    double widest = 0.0;
    for (const MeridianPoint& m : m_table) widest = std::max(widest, m.z > m_p.plinthHeight ? m.r : 0.0);
    m_meshLength = kTwoPi * widest / m_p.meshesAround;
    m_patch = std::make_unique<Patch>(*this);
}

OmphalosShape::~OmphalosShape() = default;

OmphalosShape::MeridianPoint OmphalosShape::meridian(double s) const
{
    const double x = std::clamp(s, 0.0, m_length) / m_step;
    const std::size_t i = std::min(static_cast<std::size_t>(x), m_table.size() - 2);
    const double t = x - static_cast<double>(i);
    const MeridianPoint& p = m_table[i];
    const MeridianPoint& q = m_table[i + 1];
    const double nr = p.nr + t * (q.nr - p.nr);
    const double nz = p.nz + t * (q.nz - p.nz);
    const double n = std::hypot(nr, nz);
    return {p.r + t * (q.r - p.r), p.z + t * (q.z - p.z), nr / n, nz / n};
}

double OmphalosShape::bodyRadius(double z) const
{
    const double w = z - m_p.plinthHeight + m_p.cut * m_p.semiAxis;
    if (w < m_p.cut * m_p.semiAxis || w > m_p.semiAxis) return 0.0;
    const double t = w / m_p.semiAxis;
    return m_p.radius * std::sqrt(std::max(0.0, 1.0 - t * t)) * (1.0 - m_p.asymmetry * t);
}

double OmphalosShape::netHeight(double theta, double s) const
{
    const double hw = m_p.bandHalfWidth;
    const double bottom = m_bodyStart + m_p.netBottom;
    const double top = m_length - m_p.netTop;
    if (s < bottom - hw || s > top + hw) return 0.0;
    double d = std::min(std::fabs(s - bottom), std::fabs(s - top)); // the rings closing the net
    const double r = meridian(s).r;
    if (s >= bottom && s <= top && r > 1e-3) {
        const double around = m_p.meshesAround / kTwoPi;
        const double gradient = std::hypot(around / r, 1.0 / m_meshLength);
        const double u = (theta - m_p.netPhase) * around;
        const double v = (s - bottom) / m_meshLength;
        for (const double f : {u + v, u - v}) d = std::min(d, std::fabs(f - std::nearbyint(f)) / gradient);
    }
    if (d >= hw) return 0.0;
    return m_p.bandHeight * 0.5 * (1.0 + std::cos(std::numbers::pi * d / hw));
}

std::vector<const SurfacePatch*> OmphalosShape::patches() const { return {m_patch.get()}; }

Eigen::Vector3d OmphalosShape::scanCentre() const { return {0.0, 0.0, 0.5 * height()}; }

double OmphalosShape::height() const { return m_p.plinthHeight + (1.0 - m_p.cut) * m_p.semiAxis; }

void OmphalosShape::describe(nlohmann::json& truth) const
{
    using nlohmann::json;
    const double zBase = m_p.plinthHeight;
    const double zApex = height();
    json z = json::array();
    json r = json::array();
    for (int i = 0; i < kProfileSamples; ++i) {
        const double zi = zBase + (zApex - zBase) * i / (kProfileSamples - 1);
        z.push_back(zi);
        r.push_back(bodyRadius(zi));
    }
    truth["height"] = zApex;
    truth["profile"] = {{"z", z}, {"r", r}};
    truth["plinth"] = {{"radius", m_p.plinthRadius}, {"height", m_p.plinthHeight}};
    truth["ovoid"] = {{"semiAxis", m_p.semiAxis}, {"radius", m_p.radius}, {"asymmetry", m_p.asymmetry},
                      {"cut", m_p.cut}, {"zBase", zBase}, {"zApex", zApex},
                      {"formula", "w = z - zBase + cut*semiAxis, t = w/semiAxis, "
                                  "r = radius*sqrt(1 - t^2)*(1 - asymmetry*t)"}};
    truth["net"] = {{"bandHeight", m_p.bandHeight},
                    {"bandHalfWidth", m_p.bandHalfWidth},
                    {"meshesAround", m_p.meshesAround},
                    {"meshLength", m_meshLength},
                    {"phase", m_p.netPhase},
                    {"sMin", m_bodyStart + m_p.netBottom},
                    {"sMax", m_length - m_p.netTop},
                    {"zMin", meridian(m_bodyStart + m_p.netBottom).z},
                    {"zMax", meridian(m_length - m_p.netTop).z}};
    truth["meridianLength"] = m_length;
}

} // namespace stylos::core::synth
