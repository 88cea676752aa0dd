#include "FluteProfile.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace stylos::core::dock {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double median(std::vector<double>& v)
{
    if (v.empty()) return std::nan("");
    const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

} // namespace

FluteFrequency strongestFrequency(const LateralSamples& samples, double medianRho, int minCount, int maxCount,
                                  std::size_t maxPoints)
{
    assert(minCount >= 1 && maxCount >= minCount && "strongestFrequency(): bad range");
    const std::size_t n = samples.size();
    const std::size_t stride = std::max<std::size_t>(1, (n + maxPoints - 1) / std::max<std::size_t>(maxPoints, 1));
    const int span = maxCount - minCount + 1;
    std::vector<std::complex<double>> sums(std::size_t(span), 0.0);
    double squares = 0.0;
    std::size_t used = 0;
    for (std::size_t i = 0; i < n; i += stride) {
        const double h = samples.rho[i] - medianRho;
        const std::complex<double> step = std::polar(1.0, -samples.theta[i]);
        std::complex<double> term = std::polar(h, -double(minCount) * samples.theta[i]);
        for (int k = 0; k < span; ++k) {
            sums[std::size_t(k)] += term;
            term *= step;
        }
        squares += h * h;
        ++used;
    }
    FluteFrequency best;
    if (used == 0) return best;
    std::vector<double> amplitudes;
    for (int k = 0; k < span; ++k) {
        const double a = std::abs(sums[std::size_t(k)]) / double(used);
        amplitudes.push_back(a);
        if (a > best.amplitude) {
            best.amplitude = a;
            best.count = minCount + k;
            const double pitch = kTwoPi / best.count;
            // A flute is a dip: S_N = −|c|·e^(−iNφ₀), so arg S = π − Nφ₀.
            double phase = (std::numbers::pi - std::arg(sums[std::size_t(k)])) / best.count;
            phase -= pitch * std::floor(phase / pitch);
            best.phase = phase;
        }
    }
    best.noise = std::sqrt(squares) / double(used);
    best.medianAmplitude = median(amplitudes);
    return best;
}

FluteProfile::FluteProfile(const LateralSamples& samples, int count, double phase)
    : m_pitch(kTwoPi / count), m_phase(phase)
{
    std::vector<std::vector<double>> bins(Bins);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double phi = fold(samples.theta[i]);
        const int b = std::clamp(int((phi / m_pitch + 0.5) * Bins), 0, Bins - 1);
        bins[std::size_t(b)].push_back(samples.rho[i]);
    }
    m_median.resize(Bins);
    for (int b = 0; b < Bins; ++b) m_median[std::size_t(b)] = median(bins[std::size_t(b)]);
}

double FluteProfile::fold(double theta) const
{
    double phi = theta - m_phase;
    phi -= m_pitch * std::floor(phi / m_pitch + 0.5);
    return phi;
}

double FluteProfile::bottomOffset() const
{
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    const double width = m_pitch / Bins;
    for (int b = 0; b < Bins; ++b) {
        const double x = (-0.5 * m_pitch + (b + 0.5) * width) / m_pitch; // in pitches, for conditioning
        const double y = m_median[std::size_t(b)];
        if (std::abs(x) > 0.25 || std::isnan(y)) continue;
        const Eigen::Vector3d row(1.0, x, x * x);
        normal += row * row.transpose();
        rhs += row * y;
    }
    const Eigen::Vector3d c = normal.ldlt().solve(rhs);
    if (!(c[2] > 0.0)) return 0.0; // no dip: keep the phase
    return std::clamp(-c[1] / (2.0 * c[2]), -0.25, 0.25) * m_pitch;
}

double FluteProfile::leadingRadius() const
{
    std::vector<double> v;
    for (double m : m_median)
        if (!std::isnan(m)) v.push_back(m);
    std::sort(v.begin(), v.end(), std::greater<>());
    const std::size_t k = std::min<std::size_t>(3, v.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < k; ++i) sum += v[i];
    return k ? sum / double(k) : std::nan("");
}

double FluteProfile::bottomRadius() const { return 0.5 * (m_median[Bins / 2 - 1] + m_median[Bins / 2]); }

double FluteProfile::at(double phi) const
{
    const double x = (phi / m_pitch + 0.5) * Bins - 0.5; // in bin centres
    const double f = std::floor(x);
    const double t = x - f;
    const int b0 = ((int(f) % Bins) + Bins) % Bins, b1 = (b0 + 1) % Bins;
    return (1.0 - t) * m_median[std::size_t(b0)] + t * m_median[std::size_t(b1)];
}

} // namespace stylos::core::dock
