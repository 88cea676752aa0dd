#include "FitBins.h"

#include <algorithm>
#include <cmath>

namespace stylos::core::unroll::detail {

double medianOf(std::vector<double>& values)
{
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

void axialCoordinates(const FitPoints& sample, const Eigen::Vector3d& centre, const FitLine& axis,
                      std::vector<double>& t, std::vector<double>& r)
{
    const std::size_t n = sample.size();
    t.resize(n);
    r.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d w(static_cast<double>(sample.xyz[3 * i]) - centre.x() - axis.point.x(),
                                static_cast<double>(sample.xyz[3 * i + 1]) - centre.y() - axis.point.y(),
                                static_cast<double>(sample.xyz[3 * i + 2]) - centre.z() - axis.point.z());
        t[i] = w.dot(axis.direction);
        r[i] = (w - t[i] * axis.direction).norm();
    }
}

std::vector<FitBin> medianRadiusByT(const std::vector<double>& t, const std::vector<double>& r, int bins)
{
    std::vector<FitBin> result;
    if (t.empty() || bins < 1) return result;
    std::vector<double> sorted = t;
    const auto at = [&](double q) {
        const auto k = sorted.begin() + std::ptrdiff_t(q * double(sorted.size() - 1));
        std::nth_element(sorted.begin(), k, sorted.end());
        return *k;
    };
    const double lo = at(0.001), hi = at(0.999);
    const double width = (hi - lo) / bins;
    if (!(width > 0.0)) {
        std::vector<double> all = r;
        result.push_back({lo, medianOf(all), all.size()});
        return result;
    }
    std::vector<std::vector<double>> radii(static_cast<std::size_t>(bins));
    for (std::size_t i = 0; i < t.size(); ++i) {
        const double x = (t[i] - lo) / width;
        if (x < 0.0 || x >= bins) continue;
        radii[std::size_t(x)].push_back(r[i]);
    }
    // A slice counts with 5 points and a tenth of the median slice's (sparse clutter beyond the
    // object's ends does not).
    std::vector<std::size_t> sizes;
    for (const auto& values : radii)
        if (!values.empty()) sizes.push_back(values.size());
    if (sizes.empty()) return result;
    std::nth_element(sizes.begin(), sizes.begin() + std::ptrdiff_t(sizes.size() / 2), sizes.end());
    const std::size_t enough = std::max<std::size_t>(5, sizes[sizes.size() / 2] / 10);
    for (int b = 0; b < bins; ++b) {
        std::vector<double>& values = radii[std::size_t(b)];
        if (values.size() < enough) continue;
        result.push_back({lo + (b + 0.5) * width, medianOf(values), values.size()});
    }
    return result;
}

FitProfileLine robustProfileLine(const std::vector<FitBin>& bins, bool withSlope)
{
    FitProfileLine line;
    if (bins.empty()) return line;
    if (withSlope && bins.size() >= 2) {
        std::vector<double> slopes;
        slopes.reserve(bins.size() * (bins.size() - 1) / 2);
        for (std::size_t i = 0; i < bins.size(); ++i)
            for (std::size_t j = i + 1; j < bins.size(); ++j)
                slopes.push_back((bins[j].r - bins[i].r) / (bins[j].t - bins[i].t));
        line.slope = medianOf(slopes);
    }
    std::vector<double> intercepts;
    intercepts.reserve(bins.size());
    for (const FitBin& bin : bins)
        intercepts.push_back(bin.r - line.slope * bin.t);
    line.intercept = medianOf(intercepts);
    return line;
}

double densestOffset(const std::vector<double>& t, const std::vector<double>& r, const FitProfileLine& line,
                     double range)
{
    constexpr int kBins = 200;
    if (!(range > 0.0)) return 0.0;
    std::vector<double> counts(kBins, 0.0);
    for (std::size_t i = 0; i < t.size(); ++i) {
        const double x = (r[i] - line.intercept - line.slope * t[i] + range) / (2.0 * range) * kBins;
        if (x >= 0.0 && x < kBins) counts[std::size_t(x)] += 1.0;
    }
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<double> smooth = counts;
        for (int b = 1; b + 1 < kBins; ++b)
            smooth[std::size_t(b)] =
                0.25 * (counts[std::size_t(b - 1)] + 2.0 * counts[std::size_t(b)] + counts[std::size_t(b + 1)]);
        counts = std::move(smooth);
    }
    const auto peak = std::max_element(counts.begin(), counts.end());
    if (*peak <= 0.0) return 0.0;
    return -range + (double(peak - counts.begin()) + 0.5) * (2.0 * range / kBins);
}

} // namespace stylos::core::unroll::detail
