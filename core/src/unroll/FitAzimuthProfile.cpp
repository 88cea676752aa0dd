#include "FitAzimuthProfile.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cassert>
#include <numbers>

namespace stylos::core::unroll::detail {

namespace {

constexpr std::size_t kMinSamples = 5;
constexpr double kMinArc = 0.08; ///< of the circle (29°): the shortest arc f is estimated on

} // namespace

double FitAzimuthProfile::trueAngle(double a)
{
    double lo = 0.0, hi = 2.0 * std::numbers::pi;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (fastAngle(std::cos(mid), std::sin(mid)) < a ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double FitAzimuthProfile::estimate(int bins, const std::vector<std::pair<std::uint32_t, float>>& samples,
                                   double coverage)
{
    assert(bins >= 3 && "FitAzimuthProfile::estimate(): too few bins");
    // Counting sort by bin, then the median of each bin (the value does not depend on the order).
    std::vector<std::size_t> start(static_cast<std::size_t>(bins) + 1, 0);
    for (const auto& s : samples)
        if (s.first < std::uint32_t(bins)) ++start[s.first + 1];
    for (int b = 0; b < bins; ++b)
        start[std::size_t(b) + 1] += start[std::size_t(b)];
    std::vector<float> sorted(start.back());
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (const auto& s : samples)
        if (s.first < std::uint32_t(bins)) sorted[next[s.first]++] = s.second;
    std::vector<double> values(static_cast<std::size_t>(bins), 0.0);
    std::vector<char> filled(static_cast<std::size_t>(bins), 0);
    int count = 0;
    for (int b = 0; b < bins; ++b) {
        const auto first = sorted.begin() + std::ptrdiff_t(start[std::size_t(b)]);
        const std::size_t n = start[std::size_t(b) + 1] - start[std::size_t(b)];
        if (n < kMinSamples) continue;
        const auto middle = first + std::ptrdiff_t(n / 2);
        std::nth_element(first, middle, first + std::ptrdiff_t(n));
        double median = *middle;
        if (n % 2 == 0) median = 0.5 * (median + double(*std::max_element(first, middle)));
        values[std::size_t(b)] = median;
        filled[std::size_t(b)] = 1;
        ++count;
    }
    const std::vector<double> previous =
        m_values.size() == values.size() ? m_values : std::vector<double>(values.size(), 0.0);
    // The arc the points cover: the circle less its longest run of empty bins (a fragment's outer face
    // covers one arc of 30–90°; a drum all of it). f is kept when that arc holds at least kMinArc of
    // the circle and @p coverage of its bins hold samples.
    int longestGap = 0;
    if (count > 0) {
        int first = 0;
        while (!filled[std::size_t(first)]) ++first;
        for (int k = 1, run = 0; k <= bins; ++k) {
            const int b = (first + k) % bins;
            run = filled[std::size_t(b)] ? 0 : run + 1;
            longestGap = std::max(longestGap, run);
        }
    }
    const int arc = bins - longestGap;
    if (count == 0 || arc < kMinArc * bins || count < coverage * arc) {
        disable();
        double change = 0.0;
        for (double v : previous)
            change += v * v;
        return std::sqrt(change / double(previous.size()));
    }
    // Empty bins: linear between the nearest filled bins around the circle.
    for (int b = 0; b < bins; ++b) {
        if (filled[std::size_t(b)]) continue;
        int before = b, after = b, stepsBefore = 0, stepsAfter = 0;
        do {
            before = (before + bins - 1) % bins;
            ++stepsBefore;
        } while (!filled[std::size_t(before)]);
        do {
            after = (after + 1) % bins;
            ++stepsAfter;
        } while (!filled[std::size_t(after)]);
        const double w = double(stepsBefore) / double(stepsBefore + stepsAfter);
        values[std::size_t(b)] = (1.0 - w) * values[std::size_t(before)] + w * values[std::size_t(after)];
    }
    // Remove the mean and the first harmonics, weighted by the bins' samples: the radius is then the
    // least-squares radius of the points, and the axis their least-squares axis.
    if (m_basisBins != bins) {
        m_basis.resize(static_cast<std::size_t>(bins));
        for (int b = 0; b < bins; ++b) {
            const double centre = trueAngle((b + 0.5) * 2.0 * std::numbers::pi / bins);
            m_basis[std::size_t(b)] = Eigen::Vector3d(1.0, std::cos(centre), std::sin(centre));
        }
        m_basisBins = bins;
    }
    const std::vector<Eigen::Vector3d>& basis = m_basis;
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (int b = 0; b < bins; ++b) {
        const double weight = double(start[std::size_t(b) + 1] - start[std::size_t(b)]);
        a += weight * basis[std::size_t(b)] * basis[std::size_t(b)].transpose();
        rhs += weight * values[std::size_t(b)] * basis[std::size_t(b)];
    }
    const Eigen::Vector3d harmonics = a.ldlt().solve(rhs);
    double change = 0.0;
    for (int b = 0; b < bins; ++b) {
        values[std::size_t(b)] -= harmonics.dot(basis[std::size_t(b)]);
        change +=
            (values[std::size_t(b)] - previous[std::size_t(b)]) * (values[std::size_t(b)] - previous[std::size_t(b)]);
    }
    change = std::sqrt(change / bins);
    m_values = std::move(values);
    m_perRadian = bins / (2.0 * std::numbers::pi);
    setSlopes();
    return change;
}

void FitAzimuthProfile::setSlopes()
{
    const std::size_t n = m_values.size();
    m_slopes.resize(n);
    for (std::size_t b = 0; b < n; ++b)
        m_slopes[b] = m_values[b + 1 == n ? 0 : b + 1] - m_values[b];
}

} // namespace stylos::core::unroll::detail
