#include "stylos/core/dock/FluteModel.h"

#include "stylos/core/unroll/UnrollMap.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stylos::core::dock {

DrumFrame::DrumFrame(const DrumGuides& guides)
{
    const Eigen::Vector3d d = guides.axis.direction.normalized();
    Eigen::Vector3d e1 = guides.reference - guides.reference.dot(d) * d;
    if (!(e1.norm() > 1e-9)) e1 = unroll::defaultReferenceDir(d);
    e1.normalize();
    origin = guides.axis.point;
    rows.row(0) = e1.transpose();
    rows.row(1) = d.cross(e1).transpose();
    rows.row(2) = d.transpose();
}

DrumFrame::DrumFrame(const unroll::Axis& axis)
{
    DrumGuides guides;
    guides.axis = axis;
    guides.reference = unroll::defaultReferenceDir(axis.direction.normalized());
    *this = DrumFrame(guides);
}

Result<FluteModel> FluteModel::fromGuides(const DrumGuides& g)
{
    const int bins = int(g.profile.size());
    if (g.flutes < 3 || bins < 2 * Harmonics + 2)
        return Error{ErrorCode::InvalidArgument, "the guides have no flute profile (" + std::to_string(g.flutes) +
                                                     " flutes, " + std::to_string(bins) + " profile bins)"};
    for (double v : g.profile)
        if (!std::isfinite(v) || v <= 0.0) return Error{ErrorCode::InvalidArgument, "the guides' flute profile is not a list of positive radii"};
    FluteModel m;
    m.m_flutes = g.flutes;
    m.m_pitch = 2.0 * std::numbers::pi / g.flutes;
    m.m_phase = g.phase;
    m.m_taper = g.radius > 0.0 ? g.slope / g.radius : 0.0;
    // The DFT of the bins; bin b's centre at x_b = (b + ½ − bins/2)/bins of a pitch from the bottom.
    double sum = 0.0;
    for (double v : g.profile) sum += v;
    m.m_mean = sum / bins;
    m.m_coefficients.resize(Harmonics);
    for (int k = 1; k <= Harmonics; ++k) {
        std::complex<double> c = 0.0;
        for (int b = 0; b < bins; ++b) {
            const double x = (b + 0.5 - 0.5 * bins) / bins;
            c += g.profile[std::size_t(b)] * std::polar(1.0, -2.0 * std::numbers::pi * k * x);
        }
        m.m_coefficients[std::size_t(k - 1)] = c / double(bins);
    }
    double lo = 1e300, hi = -1e300;
    std::complex<double> fundamental = 0.0;
    constexpr int kSamples = 256;
    for (int s = 0; s < kSamples; ++s) {
        const double phi = m.m_phase + (s + 0.5) * m.m_pitch / kSamples;
        const double r = m.radius(phi);
        lo = std::min(lo, r), hi = std::max(hi, r);
        fundamental += (r - m.m_mean) * std::polar(1.0, -double(m.m_flutes) * phi);
    }
    m.m_depth = hi - lo;
    m.m_fundamental = fundamental / double(kSamples);
    return m;
}

double FluteModel::radius(double phi, double* slope) const
{
    const double u = m_flutes * (phi - m_phase); // 2π per pitch
    double r = m_mean, dr = 0.0;
    const std::complex<double> step = std::polar(1.0, u);
    std::complex<double> e = step;
    for (int k = 1; k <= Harmonics; ++k, e *= step) {
        const std::complex<double> term = m_coefficients[std::size_t(k - 1)] * e;
        r += 2.0 * term.real();
        dr -= 2.0 * k * m_flutes * term.imag();
    }
    if (slope) *slope = dr;
    return r;
}

double FluteModel::distance(const Eigen::Vector3d& p, Eigen::Vector3d* normal) const
{
    const double rho = std::max(std::hypot(p.x(), p.y()), 1e-12);
    double slope = 0.0;
    const double r = radius(std::atan2(p.y(), p.x()), &slope);
    const double s = scaleAt(p.z());
    // F = ρ − s(z)·P(φ); ∇F = e_r − (s·P′(φ) / ρ)·e_φ − τ·P(φ)·e_z.
    const double kPhi = s * slope / rho, kZ = m_taper * r, g = std::sqrt(1.0 + kPhi * kPhi + kZ * kZ);
    if (normal) {
        const Eigen::Vector3d er(p.x() / rho, p.y() / rho, 0.0), ephi(-p.y() / rho, p.x() / rho, 0.0);
        *normal = (er - kPhi * ephi - Eigen::Vector3d(0.0, 0.0, kZ)) / g;
    }
    return (rho - s * r) / g;
}

} // namespace stylos::core::dock
