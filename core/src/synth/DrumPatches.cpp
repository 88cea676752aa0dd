#include "stylos/core/synth/DrumPatches.h"

#include "stylos/core/synth/DrumShape.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace stylos::core::synth {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

bool fullCircle(const DrumPatchRange& range) { return range.thetaMax == range.thetaMin; }

} // namespace

DrumLateralPatch::DrumLateralPatch(const DrumShape& drum, DrumPatchRange range, Eigen::Vector2d scanCentre,
                                   PointClip clip)
    : m_drum(drum), m_range(range), m_scanCentre(scanCentre), m_centred(scanCentre.isZero()),
      m_clip(std::move(clip)), m_radius(drum.parameters().radius)
{
    m_orientation = 1.0; // ∂p/∂a × ∂p/∂b = e_θ × e_z = e_r, outward
}

ParameterRange DrumLateralPatch::columns(double) const
{
    if (fullCircle(m_range)) return {0.0, kTwoPi * m_radius, true};
    return {m_range.thetaMin * m_radius, m_range.thetaMax * m_radius, false};
}

double DrumLateralPatch::azimuth(double a, double) const
{
    const double theta = a / m_radius;
    if (m_centred) return theta;
    return std::atan2(m_radius * std::sin(theta) - m_scanCentre.y(),
                      m_radius * std::cos(theta) - m_scanCentre.x());
}

Eigen::Vector3d DrumLateralPatch::position(double a, double b) const
{
    const double theta = a / m_radius;
    const double r = m_drum.lateralRadius(theta, b);
    return {r * std::cos(theta), r * std::sin(theta), b};
}

bool DrumLateralPatch::contains(double, double, const Eigen::Vector3d& p) const
{
    return !m_clip || m_clip(p);
}

DrumBedPatch::DrumBedPatch(const DrumShape& drum, bool top, DrumPatchRange range, Eigen::Vector2d scanCentre,
                           PointClip clip)
    : m_drum(drum), m_top(top), m_range(range), m_scanCentre(scanCentre), m_centred(scanCentre.isZero()),
      m_clip(std::move(clip)),
      m_clear((drum.parameters().radius - drum.maxLateralDepth()) *
              std::min(drum.scaleAt(0.0), drum.scaleAt(drum.parameters().height)))
{
    // ∂p/∂a × ∂p/∂b = e_θ × e_ρ = -e_z: outward for the lower bed, inward for the upper one.
    m_orientation = top ? -1.0 : 1.0;
}

ParameterRange DrumBedPatch::columns(double b) const
{
    if (fullCircle(m_range)) return {0.0, kTwoPi * b, true};
    return {m_range.thetaMin * b, m_range.thetaMax * b, false};
}

double DrumBedPatch::azimuth(double a, double b) const
{
    const double theta = b > 0.0 ? a / b : 0.0;
    if (m_centred) return theta;
    return std::atan2(b * std::sin(theta) - m_scanCentre.y(), b * std::cos(theta) - m_scanCentre.x());
}

Eigen::Vector3d DrumBedPatch::position(double a, double b) const
{
    const double theta = b > 0.0 ? a / b : 0.0;
    const double x = b * std::cos(theta);
    const double y = b * std::sin(theta);
    const double depth = m_drum.bedDepth(x, y, m_top);
    return {x, y, m_top ? m_drum.parameters().height - depth : depth};
}

bool DrumBedPatch::contains(double a, double b, const Eigen::Vector3d& p) const
{
    // Clipped by the lateral surface, which never comes nearer the axis than m_clear.
    if (b > m_clear && b > m_drum.lateralRadius(b > 0.0 ? a / b : 0.0, p.z())) return false;
    return !m_clip || m_clip(p);
}

Eigen::Vector3d DrumBedPatch::normal(double a, double b) const
{
    // Central differences need both sides of the row; at the centre the face is flat anyway.
    if (b < 2.0 * m_normalStep) return {0.0, 0.0, m_top ? 1.0 : -1.0};
    return SurfacePatch::normal(a, b);
}

} // namespace stylos::core::synth
