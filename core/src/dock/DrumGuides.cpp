#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/scene/SceneEigen.h"

#include "stylos/core/unroll/UnrollMap.h"

#include "FluteProfile.h"

#include "stylos/core/unroll/SurfaceFit.h"
#include "stylos/core/util/SubProgress.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace stylos::core::dock {
namespace {

static_assert(FluteProfile::Bins == DrumGuides::ProfileBins);
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr std::size_t kMaxLateral = 2'000'000;  ///< lateral points kept (fixed stride over the cloud)
constexpr std::size_t kMaxSpectrum = 200'000;   ///< of them in the frequency scan
constexpr std::size_t kMinLateral = 1000;
constexpr int kMinScan = 12, kMaxScan = 64;
constexpr double kMinStrength = 30.0;  ///< |S_N| over the noise level (generated drums 200–270, a plain one 11)
constexpr double kMinOverMedian = 8.0; ///< |S_N| over the scan's median (generated drums 70–110, a plain one 2)
constexpr std::size_t kCancelEvery = 1u << 14;
/// Smallest taper taken for a cone: the radius changes by at least this over the lateral points' height, metres.
constexpr double kMinTaper = 0.0005;

Error invalid(const cloud::PointCloud& cloud, const std::string& problem)
{
    return Error::at(ErrorCode::InvalidArgument, cloud.source, {}, problem);
}

double percentile(std::vector<double> v, double q)
{
    const auto at = v.begin() + std::ptrdiff_t(std::clamp(q, 0.0, 1.0) * double(v.size() - 1));
    std::nth_element(v.begin(), at, v.end());
    return *at;
}

struct Frame {
    Eigen::Vector3d point, d, e1, e2; // point relative to the cloud's origin
};

/** The lateral points: within ±band of the radius, inside the drum away from the beds. */
Result<LateralSamples> lateralSamples(const cloud::PointCloud& cloud, const Frame& f, double radius, double band,
                                      ProgressSink* progress)
{
    const std::size_t n = cloud.size();
    const std::size_t stride = std::max<std::size_t>(1, (n + kMaxLateral - 1) / kMaxLateral);
    std::vector<double> t, theta, rho;
    for (std::size_t i = 0; i < n; i += stride) {
        if ((i / stride) % kCancelEvery == 0 && progress) {
            if (progress->isCancelRequested()) return Error{ErrorCode::Cancelled, cloud.source + ": cancelled"};
            progress->update(double(i) / double(n));
        }
        const Eigen::Vector3d w = cloud.local(i) - f.point;
        const double x = w.dot(f.e1), y = w.dot(f.e2), r = std::hypot(x, y);
        if (std::abs(r - radius) > band) continue;
        t.push_back(w.dot(f.d));
        theta.push_back(std::atan2(y, x));
        rho.push_back(r);
    }
    if (t.size() < kMinLateral) return invalid(cloud, "too few points on the drum's lateral surface to find its flutes");
    const double lo = percentile(t, 0.01), hi = percentile(t, 0.99);
    const double margin = std::max(0.02 * (hi - lo), 0.005);
    LateralSamples s;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] > lo + margin && t[i] < hi - margin) {
            s.theta.push_back(theta[i]);
            s.rho.push_back(rho[i]);
            s.t.push_back(t[i]);
        }
    return s;
}

/** The heights of the samples above the folded profile along the axis: medians in kTaperBins bins of t and the
 *  least-squares line through them. slope = d(radius)/dt; error = its standard error from the bins' scatter. */
struct TaperLine {
    double slope = 0.0, error = 0.0, span = 0.0; ///< span: the range of t the bins cover, metres
};

TaperLine taperLine(const LateralSamples& s, const FluteProfile& profile)
{
    constexpr int kTaperBins = 16;
    constexpr std::size_t kMinPerBin = 50;
    const auto [lo, hi] = std::minmax_element(s.t.begin(), s.t.end());
    const double t0 = *lo, width = (*hi - *lo) / kTaperBins;
    std::vector<std::vector<double>> bins(kTaperBins);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double h = s.rho[i] - profile.at(profile.fold(s.theta[i]));
        if (!std::isfinite(h) || !(width > 0.0)) continue;
        bins[std::size_t(std::clamp(int((s.t[i] - t0) / width), 0, kTaperBins - 1))].push_back(h);
    }
    std::vector<double> x, y;
    for (int b = 0; b < kTaperBins; ++b)
        if (bins[std::size_t(b)].size() >= kMinPerBin) {
            x.push_back(t0 + (b + 0.5) * width);
            y.push_back(percentile(bins[std::size_t(b)], 0.5));
        }
    TaperLine line;
    if (x.size() < 4) return line;
    const double n = double(x.size());
    double mx = 0.0, my = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
    double sxx = 0.0, sxy = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k) sxx += (x[k] - mx) * (x[k] - mx), sxy += (x[k] - mx) * (y[k] - my);
    line.slope = sxy / sxx;
    double ss = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k) {
        const double e = y[k] - my - line.slope * (x[k] - mx);
        ss += e * e;
    }
    line.error = std::sqrt(ss / (n - 2.0) / sxx);
    line.span = x.back() - x.front() + width;
    return line;
}

} // namespace

void placeFluteLines(DrumGuides& g)
{
    g.fluteLines.clear();
    if (g.flutes < 1) return;
    const Eigen::Vector3d e2 = g.axis.direction.cross(g.reference);
    const double pitch = kTwoPi / g.flutes;
    const double bottom = g.radius - g.fluteDepth;
    for (int k = 0; k < g.flutes; ++k) {
        const double a = g.phase + k * pitch;
        const Eigen::Vector3d radial = std::cos(a) * g.reference + std::sin(a) * e2;
        // On a cone the bottom runs along a generator: its distance from the axis changes by bottom·slope/R a metre.
        const Eigen::Vector3d direction =
            g.slope == 0.0 ? g.axis.direction : Eigen::Vector3d((g.axis.direction + (bottom * g.slope / g.radius) * radial).normalized());
        g.fluteLines.push_back({g.axis.point + bottom * radial, direction});
    }
}

Result<DrumGuides> fitDrumGuides(const cloud::PointCloud& cloud, const GuideOptions& options, ProgressSink* progress)
{
    const auto start = std::chrono::steady_clock::now();
    if (options.flutes != 0 && (options.flutes < 3 || options.flutes > 1000))
        return invalid(cloud, "flute count " + std::to_string(options.flutes) + " outside 3..1000");
    unroll::FitOptions fit;
    fit.kind = unroll::SurfaceKind::Cylinder;
    fit.axis = options.axis;
    fit.threads = options.threads;
    fit.seed = options.seed;
    SubProgress fitProgress(progress, 0.0, 0.8);
    auto report = unroll::fitSurface(cloud, fit, progress ? &fitProgress : nullptr);
    if (!report) return report.error();

    DrumGuides g;
    g.axis = report->surface.axis();
    g.fitRms = report->rmsResidual;
    const double fitted = report->surface.radius();

    // The flutes about an axis: the lateral points, the flute frequency (found, or the count once known), the
    // phase, and the taper. Done about the cylinder's axis; when the drum tapers and no axis was given, done
    // again about the cone's (a cylinder fitted to a cone whose scan is not symmetric tilts by a few 0.01°).
    LateralSamples s, scaled;
    double phase = 0.0, slope = 0.0;
    for (int attempt = 0; attempt < 2; ++attempt) {
        Frame f{g.axis.point - cloud.origin, g.axis.direction, unroll::defaultReferenceDir(g.axis.direction), {}};
        f.e2 = f.d.cross(f.e1);
        g.reference = f.e1;

        SubProgress lateralProgress(progress, attempt == 0 ? 0.8 : 0.9, attempt == 0 ? 0.85 : 0.95);
        auto lateral = lateralSamples(cloud, f, fitted, std::max(0.03 * fitted, 4.0 * g.fitRms),
                                      progress ? &lateralProgress : nullptr);
        if (!lateral) return lateral.error();
        if (lateral->size() < kMinLateral)
            return invalid(cloud, "too few points on the drum's lateral surface to find its flutes");
        s = std::move(lateral).value();
        g.lateralPoints = s.size();

        const double medianRho = percentile(s.rho, 0.5);
        const int given = attempt == 0 ? options.flutes : g.flutes;
        const int lo = given ? given : kMinScan, hi = given ? given : kMaxScan;
        const FluteFrequency freq = strongestFrequency(s, medianRho, lo, hi, kMaxSpectrum);
        g.strength = freq.noise > 0.0 ? freq.amplitude / freq.noise : 0.0;
        const bool scanned = given == 0;
        if (!scanned && attempt == 0) {
            // A given count that is a multiple of the drum's: the flutes' sharp fillets put a harmonic at 2N, 3N…
            // strong enough to pass, and guides at that count dock nothing. The count it is a multiple of stands out
            // far more (a true N-flute drum has nothing at N / k): refused, naming it.
            // Counts of the scan's range only (a drum's ovality or a partial scan puts energy at 2, 3… flutes).
            for (int k = given / kMinScan; k >= 2; --k) {
                if (given % k != 0) continue;
                const int divisor = given / k;
                const FluteFrequency lower = strongestFrequency(s, medianRho, divisor, divisor, kMaxSpectrum);
                if (lower.amplitude > freq.amplitude && lower.noise > 0.0 && lower.amplitude / lower.noise >= kMinStrength) {
                    char text[260];
                    std::snprintf(text, sizeof text,
                                  "%d flutes stand %.1f times over the noise, but %d stand %.1f times: %d is a multiple "
                                  "of the drum's %d flutes (give --flutes %d)",
                                  given, g.strength, divisor, lower.amplitude / lower.noise, given, divisor, divisor);
                    return invalid(cloud, text);
                }
            }
        }
        if (g.strength < kMinStrength || (scanned && freq.amplitude < kMinOverMedian * freq.medianAmplitude)) {
            char text[200];
            if (scanned)
                std::snprintf(text, sizeof text,
                              "no flutes found: the strongest of %d..%d flutes stands %.1f times over the noise and "
                              "%.1f times over the median of the others (at least %.0f and %.0f needed)",
                              lo, hi, g.strength, freq.amplitude / std::max(freq.medianAmplitude, 1e-300),
                              kMinStrength, kMinOverMedian);
            else {
                std::snprintf(text, sizeof text, "no flutes found: %d flutes stand %.1f times over the noise (at least %.0f needed)",
                              lo, g.strength, kMinStrength);
                // A count the drum has not (24 or 16 on 48 flutes): the one it has, when the scan finds it.
                const FluteFrequency found = strongestFrequency(s, medianRho, kMinScan, kMaxScan, kMaxSpectrum);
                const double strength = found.noise > 0.0 ? found.amplitude / found.noise : 0.0;
                if (strength >= kMinStrength && found.amplitude >= kMinOverMedian * found.medianAmplitude) {
                    char hint[160];
                    std::snprintf(hint, sizeof hint, "; %d flutes stand %.1f times over it (give --flutes %d)",
                                  found.count, strength, found.count);
                    return invalid(cloud, std::string(text) + hint);
                }
            }
            return invalid(cloud, text);
        }
        if (progress && progress->isCancelRequested()) return Error{ErrorCode::Cancelled, cloud.source + ": cancelled"};

        g.flutes = freq.count;
        const double pitch = kTwoPi / g.flutes;
        phase = freq.phase;
        const auto refinePhase = [&](const LateralSamples& samples) {
            for (int round = 0; round < 2; ++round) phase += FluteProfile(samples, g.flutes, phase).bottomOffset();
            phase -= pitch * std::floor(phase / pitch);
        };
        refinePhase(s);
        // A tapering drum: its cross-section at t is the one at the axis point scaled by 1 + (slope / R)·t. The
        // heights above the folded profile rise or fall along the axis; while that line is significant, the
        // samples are scaled back to the axis point's cross-section and the profile made again.
        scaled = s;
        slope = 0.0;
        for (int round = 0; round < 3; ++round) {
            const FluteProfile current(scaled, g.flutes, phase);
            const TaperLine line = taperLine(scaled, current);
            const bool significant = std::abs(line.slope) * line.span >= kMinTaper && std::abs(line.slope) >= 4.0 * line.error;
            if (round == 0 && !significant) break;
            slope += line.slope;
            const double relative = slope / current.leadingRadius();
            for (std::size_t i = 0; i < s.size(); ++i) scaled.rho[i] = s.rho[i] / (1.0 + relative * s.t[i]);
            refinePhase(scaled);
        }
        if (attempt == 1 || slope == 0.0 || options.axis) break;
        unroll::FitOptions coneFit = fit;
        coneFit.kind = unroll::SurfaceKind::Cone;
        auto cone = unroll::fitSurface(cloud, coneFit); // no progress: the cylinder's share already went by
        if (!cone) break;                               // keep the cylinder's axis
        unroll::Axis axis = cone->surface.axis();
        if (axis.direction.dot(g.axis.direction) < 0.0) axis.direction = -axis.direction;
        // The same origin along the axis as the cylinder's (the lower end of its points): the foot of that point.
        axis.point += (g.axis.point - axis.point).dot(axis.direction) * axis.direction;
        g.axis = axis;
    }
    const FluteProfile profile(scaled, g.flutes, phase);
    g.phase = phase;
    g.radius = profile.leadingRadius();
    g.slope = slope;
    g.fluteDepth = g.radius - profile.bottomRadius();
    if (!std::isfinite(g.radius) || !(g.fluteDepth > 0.0))
        return invalid(cloud, "the flute profile has no depth (too few points per flute)");

    g.profile = profile.medians();
    for (int b = 0; b < DrumGuides::ProfileBins; ++b) // an empty bin (a sparse scan): its neighbours' mean
        if (std::isnan(g.profile[std::size_t(b)])) {
            const double before = profile.medians()[std::size_t((b + DrumGuides::ProfileBins - 1) % DrumGuides::ProfileBins)];
            const double after = profile.medians()[std::size_t((b + 1) % DrumGuides::ProfileBins)];
            g.profile[std::size_t(b)] = std::isnan(before) ? after : std::isnan(after) ? before : 0.5 * (before + after);
        }
    for (double v : g.profile)
        if (std::isnan(v)) return invalid(cloud, "the flute profile has empty stretches (too few points per flute)");

    std::vector<double> residual;
    residual.reserve(s.size());
    for (std::size_t i = 0; i < scaled.size(); ++i) {
        const double r = scaled.rho[i] - profile.at(profile.fold(scaled.theta[i]));
        if (std::isfinite(r)) residual.push_back(r);
    }
    std::vector<double> absolute(residual.size());
    std::transform(residual.begin(), residual.end(), absolute.begin(), [](double r) { return std::abs(r); });
    const double limit = 5.0 * 1.4826 * percentile(absolute, 0.5);
    double sum = 0.0;
    std::size_t kept = 0;
    for (double r : residual)
        if (std::abs(r) <= limit) sum += r * r, ++kept;
    g.rms = kept ? std::sqrt(sum / double(kept)) : 0.0;

    placeFluteLines(g);
    if (progress) progress->update(1.0);
    g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return g;
}

std::optional<GuideOptions> guideOptionsFor(const scene::Fragment& drum)
{
    const auto axis = scene::firstGuide(drum, scene::GuideKind::Axis);
    const auto grooves = std::count_if(drum.guides.begin(), drum.guides.end(),
                                       [](const scene::Guide& g) { return g.kind == scene::GuideKind::Groove; });
    if (!axis || grooves < 3 || !(axis->direction.norm() > 0.0)) return std::nullopt;
    GuideOptions options;
    options.axis = unroll::Axis{axis->origin, axis->direction.normalized()};
    options.flutes = int(grooves);
    return options;
}

} // namespace stylos::core::dock
