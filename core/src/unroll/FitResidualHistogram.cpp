#include "FitResidualHistogram.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace stylos::core::unroll::detail {

FitResidualHistogram::FitResidualHistogram(double scale)
    : m_scale(scale), m_inverseScale(1.0 / scale), m_counts(kBins, 0), m_cumulative(kBins + 1, 0.0)
{
    assert(scale > 0.0 && std::isfinite(scale) && "FitResidualHistogram::FitResidualHistogram(): bad scale");
}

void FitResidualHistogram::merge(const FitResidualHistogram& other)
{
    for (int b = 0; b < kBins; ++b)
        m_counts[b] += other.m_counts[b];
    m_dirty = true;
}

void FitResidualHistogram::clear()
{
    std::fill(m_counts.begin(), m_counts.end(), 0);
    m_dirty = true;
}

std::uint64_t FitResidualHistogram::total() const
{
    std::uint64_t sum = 0;
    for (std::uint64_t c : m_counts)
        sum += c;
    return sum;
}

double FitResidualHistogram::binLow(int bin) const
{
    if (bin <= 0) return 0.0;
    if (bin >= kBins - 1) return 256.0;
    return double(std::bit_cast<float>(kLowBits + (std::uint32_t(bin - 1) << kShift)));
}

double FitResidualHistogram::binHigh(int bin) const
{
    if (bin >= kBins - 1) return 256.0;
    return binLow(bin + 1);
}

void FitResidualHistogram::cumulate() const
{
    if (!m_dirty) return;
    m_cumulative[0] = 0.0;
    for (int b = 0; b < kBins; ++b)
        m_cumulative[b + 1] = m_cumulative[b] + double(m_counts[b]);
    m_dirty = false;
}

double FitResidualHistogram::countBelow(double x) const
{
    cumulate();
    const double v = x * m_inverseScale;
    if (!(v > 0.0)) return 0.0;
    if (v >= 256.0) return m_cumulative[kBins - 1]; // the overflow bin counts as beyond any threshold
    const float f = static_cast<float>(v);
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
    const int bin = bits < kLowBits ? 0 : int((bits - kLowBits) >> kShift) + 1;
    const double lo = binLow(bin), hi = binHigh(bin);
    const double within = std::clamp((v - lo) / (hi - lo), 0.0, 1.0);
    return m_cumulative[bin] + within * double(m_counts[bin]);
}

double FitResidualHistogram::valueAtCount(double count) const
{
    cumulate();
    if (count <= 0.0) return 0.0;
    // The first bin whose cumulative end reaches count.
    const auto it = std::lower_bound(m_cumulative.begin() + 1, m_cumulative.end(), count);
    if (it == m_cumulative.end()) return 256.0 * m_scale;
    const int bin = int(it - m_cumulative.begin()) - 1;
    const double inBin = double(m_counts[bin]);
    const double within = inBin > 0.0 ? std::clamp((count - m_cumulative[bin]) / inBin, 0.0, 1.0) : 1.0;
    return (binLow(bin) + within * (binHigh(bin) - binLow(bin))) * m_scale;
}

double FitResidualHistogram::trimThreshold(double start, double kappa, double floor) const
{
    constexpr double kMadToSigma = 1.482602218505602; // 1 / Φ⁻¹(3/4)
    double tau = start;
    for (int iteration = 0; iteration < 500; ++iteration) {
        const double kept = countBelow(tau);
        if (kept < 1.0) return tau;
        const double next = std::max(kappa * kMadToSigma * valueAtCount(0.5 * kept), floor);
        if (std::abs(next - tau) <= 1e-6 * tau) return next;
        tau = next;
    }
    return tau;
}

} // namespace stylos::core::unroll::detail
