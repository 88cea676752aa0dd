#include "stylos/core/developpee/Developpee.h"

#include "stylos/core/util/Stopwatch.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/shading/ContrastStretch.h"
#include "stylos/core/shading/HeightNoise.h"
#include "stylos/core/shading/SkydomeShading.h"
#include "stylos/core/util/SubProgress.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <utility>

namespace stylos::core::developpee {

namespace {


/** Where each step ends in [0, 1] of the caller's progress. */
struct Split {
    double fit, unroll, shade;
};

/** The surface about the given axis at the given unrolling radius: a cylinder as it is (its RMS over the robust
 *  band of the lateral surface, as the fitter reports it), a cone or a revolution fitted, then measured at @p radius. */
Result<unroll::FitReport> givenSurface(const cloud::PointCloud& cloud, const unroll::FitOptions& fitOptions,
                                       double radius, double slope, ProgressSink* progress)
{
    if (fitOptions.kind != unroll::SurfaceKind::Cylinder) {
        auto fit = unroll::fitSurface(cloud, fitOptions, progress);
        if (!fit) return fit;
        const unroll::Surface& s = fit->surface;
        auto surface = s.kind() == unroll::SurfaceKind::Cone ? unroll::Surface::cone(s.axis(), s.radius(), s.slope(), radius)
                                                             : unroll::Surface::revolution(s.axis(), *s.meridian(), radius);
        if (!surface) return surface.error();
        fit->surface = std::move(surface).value();
        return fit;
    }
    const auto start = Clock::now();
    auto surface = slope == 0.0 ? unroll::Surface::cylinder(*fitOptions.axis, radius)
                                : unroll::Surface::cone(*fitOptions.axis, radius, slope, radius);
    if (!surface) return surface.error();
    unroll::FitReport report{.surface = std::move(surface).value()};
    const unroll::Axis& axis = *fitOptions.axis;
    // Residuals h = ρ − r(t) (R, or R + slope·t on a tapering drum's cone), then the fitter's robust band (SurfaceFit.h): the fixed point of
    // τ = 3 × 1.4826 × median{|h| ≤ τ}, from the unroller's band 0.15 R. The RMS is over that band, so the bed
    // faces and the fracture surfaces (far from the cylinder) do not count as misfit of the lateral surface.
    std::vector<double> h(cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const Eigen::Vector3d d = cloud.world(i) - axis.point;
        const double t = d.dot(axis.direction);
        h[i] = std::abs((d - t * axis.direction).norm() - (radius + slope * t));
    }
    double tau = 0.15 * radius;
    std::vector<double> within;
    for (int round = 0; round < 30; ++round) {
        within.clear();
        for (const double v : h)
            if (v <= tau) within.push_back(v);
        if (within.empty()) break;
        const auto mid = within.begin() + std::ptrdiff_t(within.size() / 2);
        std::nth_element(within.begin(), mid, within.end());
        const double next = 3.0 * 1.4826 * *mid;
        if (!(next > 0.0) || std::abs(next - tau) <= 1e-3 * tau) {
            tau = next > 0.0 ? next : tau;
            break;
        }
        tau = next;
    }
    double sum = 0.0;
    std::size_t kept = 0;
    for (const double v : h)
        if (v <= tau) sum += v * v, ++kept;
    const std::size_t n = cloud.size();
    report.rmsResidual = kept > 0 ? std::sqrt(sum / double(kept)) : 0.0;
    report.inlierFraction = n > 0 ? double(kept) / double(n) : 0.0;
    report.points = n;
    report.seconds = secondsSince(start);
    if (progress) progress->update(1.0);
    return report;
}

/**
 * Fit, unroll, shade @p cloud; @p release is called once the points are no longer needed (the file
 * version frees them before shading). @p timings.load is the caller's.
 */
Result<Developpee> develop(const cloud::PointCloud& cloud, const DeveloppeeOptions& options, ProgressSink* progress,
                           double from, const Split& split, DeveloppeeTimings timings, const std::function<void()>& release,
                           Clock::time_point start)
{
    unroll::FitOptions fitOptions;
    fitOptions.kind = options.surface;
    fitOptions.threads = options.threads;
    if (options.axis) {
        unroll::Axis axis = *options.axis;
        axis.direction.normalize();
        fitOptions.axis = axis;
    }
    SubProgress fitStep(progress, from, split.fit);
    auto fit = fitOptions.axis && options.radius ? givenSurface(cloud, fitOptions, *options.radius, options.radiusSlope.value_or(0.0), &fitStep)
                                                 : unroll::fitSurface(cloud, fitOptions, &fitStep);
    if (!fit) return fit.error();
    timings.fit = fit->seconds;

    unroll::UnrollOptions unrollOptions;
    unrollOptions.pixelSize = options.pixelSize;
    unrollOptions.cutAngle = options.cutAngle;
    unrollOptions.cropToPoints = options.cropToPoints;
    unrollOptions.fillHoles = options.fillHoles;
    unrollOptions.threads = options.threads;
    SubProgress unrollStep(progress, split.fit, split.unroll);
    auto unrolled = unroll::unrollCloud(cloud, fit->surface, unrollOptions, &unrollStep);
    if (!unrolled) return unrolled.error();
    release();
    timings.unroll = unrolled->report.seconds;

    const auto shadingStart = Clock::now();
    SubProgress shadeStep(progress, split.unroll, split.shade);
    ShadingReport shadingReport;
    auto shaded = shadeField(unrolled->field, options, &shadeStep, &shadingReport);
    if (!shaded) return shaded.error();
    timings.shading = secondsSince(shadingStart);
    timings.total = secondsSince(start);
    if (progress) progress->update(1.0);
    return Developpee{std::move(unrolled->field), std::move(shaded).value(), std::move(unrolled->map), *fit,
                      unrolled->report, timings, shadingReport.heightNoise, shadingReport.smoothing};
}

} // namespace

Status DeveloppeeOptions::check(const std::string& source) const
{
    const auto invalid = [&](const std::string& problem) {
        return Error::at(ErrorCode::InvalidArgument, source, {}, problem);
    };
    if (directions < kMinDirections || directions > kMaxDirections)
        return invalid("the number of skydome directions must be between " + std::to_string(kMinDirections) + " and "
                       + std::to_string(kMaxDirections) + ", got " + std::to_string(directions));
    if (pixelSize && !(std::isfinite(*pixelSize) && *pixelSize > 0.0))
        return invalid("the pixel size must be a positive length in metres");
    if (cutAngle && !std::isfinite(*cutAngle)) return invalid("the cut angle must be a finite number of radians");
    if (!std::isfinite(light.azimuth)) return invalid("the light azimuth must be a finite number of degrees");
    if (!(light.elevation >= 0.0 && light.elevation <= 0.5 * std::numbers::pi))
        return invalid("the light elevation must be between 0 and 90 degrees");
    if (axis && (!axis->point.allFinite() || !axis->direction.allFinite() || axis->direction.norm() < 1e-12))
        return invalid("the axis needs a finite point and a non-zero direction");
    if (radius && !(std::isfinite(*radius) && *radius > 0.0)) return invalid("the unrolling radius must be a positive length in metres");
    if (smoothing && !(std::isfinite(*smoothing) && *smoothing >= 0.0))
        return invalid("the skydome smoothing must be a length of 0 or more metres");
    return {};
}

Result<shading::ShadedImage> shadeField(const shading::HeightField& field, const DeveloppeeOptions& options,
                                        ProgressSink* progress, ShadingReport* report)
{
    if (report) *report = {};
    switch (options.shading) {
    case Shading::Height: return shading::shadeHeight(field, options.height);
    case Shading::Light: return shading::shadeLight(field, options.light);
    case Shading::Skydome: break;
    }
    // Scanner noise read as relief is salt and pepper: the horizon sweeps smoothed heights (HeightNoise.h).
    const double noise = shading::estimateHeightNoise(field);
    const double sigma = options.smoothing.value_or(shading::noiseSmoothingSigma(noise, field.pixelSize()));
    if (report) *report = {noise, sigma};
    std::optional<shading::HeightField> smoothed;
    if (sigma > 0.0) {
        auto s = shading::smoothHeights(field, sigma, options.threads);
        if (!s) return s.error();
        smoothed = std::move(s).value();
    }
    shading::SkydomeOptions sky;
    sky.directions = options.directions;
    sky.threads = options.threads;
    auto shaded = shading::shadeSkydome(smoothed ? *smoothed : field, sky, progress);
    if (shaded && options.stretch) {
        if (auto range = shading::stretchContrast(*shaded); !range) return range.error();
    }
    return shaded;
}

Result<Developpee> computeDeveloppee(const std::filesystem::path& input, const DeveloppeeOptions& options,
                                     ProgressSink* progress)
{
    const auto start = Clock::now();
    if (auto s = options.check(input.string()); !s) return s.error();
    cloud::PointCloud cloud;
    {
        SubProgress step(progress, 0.0, 0.15);
        cloud::CloudLoadOptions load;
        load.read = options.read;
        auto loaded = cloud::loadPointCloud(input, load, &step);
        if (!loaded) return loaded.error();
        cloud = std::move(loaded).value();
    }
    DeveloppeeTimings timings;
    timings.load = secondsSince(start);
    return develop(cloud, options, progress, 0.15, {0.4, 0.7, 0.98}, timings, [&cloud] { cloud = {}; }, start);
}

Result<Developpee> computeDeveloppee(const cloud::PointCloud& cloud, const DeveloppeeOptions& options,
                                     ProgressSink* progress)
{
    const auto start = Clock::now();
    if (auto s = options.check(cloud.source.empty() ? "<memory>" : cloud.source); !s) return s.error();
    return develop(cloud, options, progress, 0.0, {0.3, 0.65, 0.98}, {}, [] {}, start);
}

} // namespace stylos::core::developpee
