#include "stylos/core/dock/FluteSnap.h"

#include <cmath>
#include <complex>
#include <numbers>

namespace stylos::core::dock {

FluteSnap snapToFlutes(const std::vector<Eigen::Vector3d>& points, const FluteModel& model, double margin)
{
    FluteSnap snap;
    const double band = model.depth() + margin;
    double sumRho = 0.0;
    std::vector<std::pair<double, double>> kept; // (θ, ρ)
    kept.reserve(points.size());
    for (const Eigen::Vector3d& p : points) {
        const double rho = std::hypot(p.x(), p.y()) / model.scaleAt(p.z()); // at the axis point's cross-section
        if (std::abs(rho - model.meanRadius()) > band) continue;
        kept.emplace_back(std::atan2(p.y(), p.x()), rho);
        sumRho += rho;
    }
    snap.points = kept.size();
    if (kept.size() < 3) return snap;
    const double mean = sumRho / double(kept.size());
    std::complex<double> s = 0.0;
    double squares = 0.0;
    for (const auto& [theta, rho] : kept) {
        const double h = rho - mean;
        s += h * std::polar(1.0, -double(model.flutes()) * theta);
        squares += h * h;
    }
    snap.strength = squares > 0.0 ? std::abs(s) / std::sqrt(squares * double(kept.size())) : 0.0;
    double shift = (std::arg(s) - std::arg(model.fundamental())) / model.flutes();
    const double pitch = model.pitch();
    shift -= pitch * std::floor(shift / pitch + 0.5); // (−pitch/2, pitch/2]
    snap.rotation = shift;
    return snap;
}

} // namespace stylos::core::dock
