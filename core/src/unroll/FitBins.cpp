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
    std::sort(sorted.begin(), sorted.end());
    const double lo = sorted[std::size_t(0.001 * double(sorted.size() - 1))];
    const double hi = sorted[std::size_t(0.999 * double(sorted.size() - 1))];
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
    for (int b = 0; b < bins; ++b) {
        std::vector<double>& values = radii[std::size_t(b)];
        if (values.size() < 5) continue;
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
    for (const FitBin& bin : bins) intercepts.push_back(bin.r - line.slope * bin.t);
    line.intercept = medianOf(intercepts);
    return line;
}

} // namespace stylos::core::unroll::detail
