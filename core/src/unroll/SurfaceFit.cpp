#include "stylos/core/unroll/SurfaceFit.h"

#include "FitBins.h"
#include "FitCylinder.h"
#include "FitMeridian.h"
#include "FitPairSeed.h"
#include "FitParallel.h"
#include "FitSample.h"
#include "FitSeed.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace stylos::core::unroll {

namespace {

using namespace detail;

constexpr std::size_t kMinPoints = 100;
constexpr std::size_t kSeedPoints = 100'000;     ///< the line-complex seed's sample
constexpr std::size_t kRefinePoints = 1'000'000; ///< the cylinder / cone Gauss–Newton sample
constexpr std::size_t kMeridianPoints = 200'000; ///< the principal-curve sample
constexpr std::uint64_t kSeedStream = 1, kRefineStream = 2, kPairStream = 3;
constexpr int kPairTrials = 400;           ///< candidate axes from pairs of normals (cylinder, cone)
constexpr double kPairBandOfSize = 0.03;   ///< their inlier band, ± this share of the cloud's size
constexpr double kPairOverComplex = 1.2;   ///< the pair seed replaces the line complex's with this many times its inliers
// Refusal: the RMS residual over the inliers against the (mean) radius and against the size of the
// cloud (RMS distance of its points from their centroid); the measurements behind the values are in
// SurfaceFit.h.
constexpr double kMaxRmsOverRadius = 0.3;          ///< cylinder, cone
constexpr double kMaxRmsOverSize = 0.2;            ///< cylinder, cone
constexpr double kMaxRmsOverRadiusMeridian = 0.15; ///< revolution
constexpr double kMaxRmsOverSizeMeridian = 0.1;    ///< revolution
/// A free axis whose radius exceeds this many times the cloud's size: the points are nearly flat (an
/// arc of under ~6° of its circle), e.g. a terrain, which any huge cylinder fits.
constexpr double kMaxRadiusOverSize = 10.0;
/// A free axis whose arc bulges over the cloud by less than this many RMS residuals: the curvature is noise.
constexpr double kMinSagittaOverRms = 3.0;
constexpr double kMaxGap = 0.2;                    ///< of the extent: the longest stretch without inliers
constexpr double kMinThickness = 0.02;             ///< revolution: spread of the inliers along / across the axis
constexpr double kMinInlierFraction = 0.05;        ///< a thin drum slab still has 15 % on its side
constexpr double kMeridianReachShare = 0.05;       ///< the final meridian's reach, of its size

std::string sourceOf(const cloud::PointCloud& cloud)
{
    return cloud.source.empty() ? "<memory>" : cloud.source;
}

Error invalid(const std::string& source, const std::string& problem)
{
    return Error::at(ErrorCode::InvalidArgument, source, {}, problem);
}

Error cancelled(const std::string& source)
{
    return Error::at(ErrorCode::Cancelled, source, {}, "surface fit cancelled");
}

std::string fixed(double value, int decimals)
{
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

/** "not a cylinder: RMS residual 212.4 mm for radius 0.35 m (inliers 31 %)" */
std::string refusal(const char* what, double rms, const char* radiusName, double radius, double inliers)
{
    return std::string("not ") + what + ": RMS residual " + fixed(rms * 1e3, 1) + " mm for " + radiusName + " " +
           fixed(radius, radius < 0.1 ? 4 : 2) + " m (inliers " + fixed(inliers * 100.0, 0) + " %)";
}

/** The report of a fitted @p surface from the statistics of its final pass (RadialStats or MeridianStats). */
template <class Stats> FitReport reportFor(Surface surface, const Stats& s, std::uint64_t points, int iterations)
{
    FitReport report;
    report.surface = std::move(surface);
    report.rmsResidual = s.rms;
    report.inlierFraction = s.inlierFraction();
    report.points = points;
    report.iterations = iterations;
    return report;
}

/** The fit frame: cloud-local coordinates less the centroid of the seed sample; scale = RMS distance. */
struct Frame {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double scale = 0.0;
};

Frame frameOf(const FitPoints& sample)
{
    Frame frame;
    const std::size_t n = sample.size();
    for (std::size_t i = 0; i < n; ++i)
        frame.centre += Eigen::Vector3d(sample.xyz[3 * i], sample.xyz[3 * i + 1], sample.xyz[3 * i + 2]);
    frame.centre /= double(n);
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        sum += (Eigen::Vector3d(sample.xyz[3 * i], sample.xyz[3 * i + 1], sample.xyz[3 * i + 2]) - frame.centre)
                   .squaredNorm();
    frame.scale = std::sqrt(sum / double(n));
    return frame;
}

/** Sign convention for an axis nothing else orients: its largest world component is positive. */
bool pointsDown(const Eigen::Vector3d& direction)
{
    int largest = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(direction[i]) > std::abs(direction[largest])) largest = i;
    return direction[largest] < 0.0;
}

/** Everything the kinds share. */
struct Context {
    const cloud::PointCloud& cloud;
    const FitOptions& options;
    std::string source;
    Frame frame;
    FitLine axis; ///< seed or given, fit frame
    bool axisFree = true;
    unsigned threads = 1;
    FitStage stage;
    FitPoints seedSample = {}; ///< ≤ 100 k points, with normals when they were needed for the seed
};

Result<FitReport> fitRadial(Context& c, bool cone)
{
    const std::size_t n = c.cloud.size();
    const FitPoints sample =
        gatherPoints(c.cloud, stratifiedSample(n, kRefinePoints, c.options.seed, kRefineStream), false);
    if (sample.size() < kMinPoints) return invalid(c.source, "fewer than 100 finite points");
    // The starting profile: a robust line through the median radii of axial slices.
    FitLine axis = c.axis;
    axis.point -= axis.point.dot(axis.direction) * axis.direction;
    std::vector<double> t, r;
    axialCoordinates(c.seedSample, c.frame.centre, axis, t, r);
    const int bins = int(std::clamp<std::size_t>(t.size() / 1000, 8, 128));
    FitProfileLine line = robustProfileLine(medianRadiusByT(t, r, bins), cone);
    // Moved onto the densest band of radii about it: the surface, where bed faces, fracture faces and
    // clutter spread out (a fragment's outer face may hold a quarter of its points).
    line.intercept += densestOffset(t, r, line, 0.5 * std::abs(line.intercept));
    RadialModel start;
    start.axis = axis;
    start.radius = line.intercept;
    start.slope = line.slope;
    const double tau0 = std::max(0.05 * std::abs(line.intercept), 0.01 * c.frame.scale);

    FitCylinder fit(cone, c.axisFree, c.threads, c.frame.centre, c.frame.scale);
    const bool whole = sample.size() == n;
    if (!fit.refine(sample, start, tau0, c.stage.part(0.2, whole ? 1.0 : 0.6))) return cancelled(c.source);
    // Orientation: a cone's wider end at the bottom (columns taper upward) when its ends differ by
    // more than 5 %; otherwise (and for a cylinder) the largest world component of the direction positive.
    if (c.axisFree && !fit.degenerate()) {
        const RadialModel& m = fit.model();
        const RadialStats& s = fit.stats();
        const double span = std::abs(m.slope) * (s.maxT - s.minT);
        const double mean = std::abs(m.radius + m.slope * s.meanT);
        const bool tapered = cone && span > 0.05 * mean;
        if (tapered ? m.slope > 0.0 : pointsDown(m.axis.direction)) fit.reverse();
    }
    const double gap = fit.degenerate() ? 0.0 : fit.gap(sample);
    const double span = fit.stats().maxT - fit.stats().minT;
    if (!whole && !fit.degenerate() && !fit.polish(c.cloud.positions.data(), n, c.stage.part(0.6, 1.0)))
        return cancelled(c.source);

    const RadialModel& m = fit.model();
    const RadialStats& s = fit.stats();
    const double meanRadius = m.radius + m.slope * s.meanT;
    const char* what = cone ? "a cone" : "a cylinder";
    const char* radiusName = cone ? "mean radius" : "radius";
    if (fit.degenerate() || s.inliers < kMinPoints)
        return invalid(c.source, std::string("not ") + what + ": the fit runs away (a flat or scattered cloud)" +
                                     " (inliers " + fixed(s.inlierFraction() * 100.0, 0) + " %)");
    if (!(meanRadius > 0.0) || s.rms > kMaxRmsOverRadius * meanRadius || s.rms > kMaxRmsOverSize * c.frame.scale ||
        s.inlierFraction() < kMinInlierFraction)
        return invalid(c.source, refusal(what, s.rms, radiusName, std::abs(meanRadius), s.inlierFraction()));
    // Nearly flat: the radius dwarfs the cloud, or the arc's sagitta over the cloud (about 0.75 scale² / R
    // for a patch whose RMS distance to its centre is the scale) is lost in the residual.
    const double sagitta = 0.75 * c.frame.scale * c.frame.scale / std::abs(meanRadius);
    if (c.axisFree && (std::abs(meanRadius) > kMaxRadiusOverSize * c.frame.scale || sagitta < kMinSagittaOverRms * s.rms))
        return invalid(c.source, std::string("not ") + what + ": the " + radiusName + " " +
                                     fixed(std::abs(meanRadius), 2) + " m is " +
                                     fixed(std::abs(meanRadius) / c.frame.scale, 1) + " times the cloud's size (" +
                                     fixed(c.frame.scale, 2) + " m) and its arc bulges " + fixed(sagitta * 1000.0, 1) +
                                     " mm for an RMS residual of " + fixed(s.rms * 1000.0, 1) +
                                     " mm: the points are nearly flat (give the axis if they are a shallow arc of a"
                                     " large drum)");
    if (gap > kMaxGap * span)
        return invalid(c.source, std::string("not ") + what +
                                     ": the points form separate groups along the axis (a gap of " + fixed(gap, 3) +
                                     " m in " + fixed(span, 3) + " m)");

    Axis world;
    world.direction = m.axis.direction.normalized();
    world.point = c.cloud.origin + c.frame.centre + m.axis.point + s.minT * world.direction;
    const double bottomRadius = m.radius + m.slope * s.minT;
    Result<Surface> surface =
        cone ? Surface::cone(world, bottomRadius, m.slope, meanRadius) : Surface::cylinder(world, bottomRadius);
    if (!surface) return invalid(c.source, std::string("not ") + what + ": " + surface.error().message);
    return reportFor(std::move(surface).value(), s, n, fit.iterations());
}

/** Arc-length-weighted mean radius of a polyline. */
double meanRadius(const std::vector<Eigen::Vector2d>& vertices)
{
    double sum = 0.0, length = 0.0;
    for (std::size_t i = 1; i < vertices.size(); ++i) {
        const double l = (vertices[i] - vertices[i - 1]).norm();
        sum += l * 0.5 * (vertices[i].y() + vertices[i - 1].y());
        length += l;
    }
    return length > 0.0 ? sum / length : 0.0;
}

/** Arc-length-weighted mean radius of the part of the meridian in the lowest (or highest) quarter of its t range. */
double endRadius(const std::vector<Eigen::Vector2d>& vertices, bool top)
{
    double lo = vertices.front().x(), hi = lo;
    for (const auto& v : vertices) {
        lo = std::min(lo, v.x());
        hi = std::max(hi, v.x());
    }
    const double cut = top ? hi - 0.25 * (hi - lo) : lo + 0.25 * (hi - lo);
    double sum = 0.0, length = 0.0;
    for (std::size_t i = 1; i < vertices.size(); ++i) {
        const double mid = 0.5 * (vertices[i].x() + vertices[i - 1].x());
        if (top ? mid < cut : mid > cut) continue;
        const double l = (vertices[i] - vertices[i - 1]).norm();
        sum += l * 0.5 * (vertices[i].y() + vertices[i - 1].y());
        length += l;
    }
    return length > 0.0 ? sum / length : 0.0;
}

Result<FitReport> fitRevolution(Context& c)
{
    const std::size_t n = c.cloud.size();
    const FitPoints sample =
        gatherPoints(c.cloud, stratifiedSample(n, kMeridianPoints, c.options.seed, kRefineStream), false);
    if (sample.size() < kMinPoints) return invalid(c.source, "fewer than 100 finite points");
    FitMeridian fit(c.axisFree, c.threads, c.frame.centre, c.frame.scale);
    if (!fit.fit(sample, c.axis, c.stage.part(0.2, 1.0))) return cancelled(c.source);
    if (fit.failed()) return invalid(c.source, "not a surface of revolution: no meridian fits the points");
    // Orientation: the wider end at the bottom (an omphalos on its plinth, a statue on its base) when the
    // lowest and highest quarters differ by more than 10 %; otherwise the largest world component positive.
    if (c.axisFree) {
        const double bottom = endRadius(fit.vertices(), false), top = endRadius(fit.vertices(), true);
        const bool distinct = std::abs(bottom - top) > 0.1 * std::max(bottom, top);
        if (distinct ? top > bottom : pointsDown(fit.axis().direction)) fit.reverse();
    }
    // The statistics are the sample's (projecting 30 M points on a meridian would take seconds for
    // figures the sample gives to within a percent; the unroller projects every point anyway).

    const MeridianStats& s = fit.stats();
    std::vector<Eigen::Vector2d> vertices = fit.vertices();
    const double reference = meanRadius(vertices);
    if (s.inliers < kMinPoints || !(reference > 0.0) || s.rms > kMaxRmsOverRadiusMeridian * reference ||
        s.rms > kMaxRmsOverSizeMeridian * c.frame.scale || s.inlierFraction() < kMinInlierFraction)
        return invalid(c.source,
                       refusal("a surface of revolution", s.rms, "mean radius", reference, s.inlierFraction()));
    const double length = meridianLength(vertices);
    if (fit.gap() > kMaxGap * length)
        return invalid(c.source, "not a surface of revolution: the points form separate pieces (a gap of " +
                                     fixed(fit.gap(), 3) + " m along a meridian of " + fixed(length, 3) + " m)");
    if (s.tSpread < kMinThickness * s.rSpread)
        return invalid(c.source, "not a surface of revolution: the points lie in a plane (spread " +
                                     fixed(s.tSpread * 1e3, 1) + " mm along the axis, " + fixed(s.rSpread * 1e3, 0) +
                                     " mm across)");
    double lowest = vertices.front().x(), size = 0.0;
    for (const auto& v : vertices)
        lowest = std::min(lowest, v.x());
    for (auto& v : vertices) {
        v.x() -= lowest;
        size = std::max({size, v.x(), v.y()});
    }
    Axis world;
    world.direction = fit.axis().direction.normalized();
    world.point = c.cloud.origin + c.frame.centre + fit.axis().point + lowest * world.direction;
    const double reach = std::max(8.0 * fit.threshold(), kMeridianReachShare * size);
    auto meridian = Meridian::create(std::move(vertices), reach);
    if (!meridian) return invalid(c.source, "not a surface of revolution: " + meridian.error().message);
    auto surface = Surface::revolution(world, std::move(meridian).value(), reference);
    if (!surface) return invalid(c.source, "not a surface of revolution: " + surface.error().message);
    return reportFor(std::move(surface).value(), s, n, fit.iterations());
}

} // namespace

Result<FitReport> fitSurface(const cloud::PointCloud& cloud, const FitOptions& options, ProgressSink* progress)
{
    const auto started = std::chrono::steady_clock::now();
    const std::string source = sourceOf(cloud);
    const std::size_t n = cloud.size();
    if (n < kMinPoints) return invalid(source, std::to_string(n) + " points: too few to fit a surface (at least 100)");
    if (cloud.hasNormals() && cloud.normals.size() != cloud.positions.size())
        return invalid(source, "the normals do not match the points in number");
    if (options.axis && (!options.axis->point.allFinite() || !options.axis->direction.allFinite() ||
                         !(options.axis->direction.norm() > 1e-12)))
        return invalid(source, "the given axis is not a finite line with a non-zero direction");

    std::optional<FitMonotonicSink> monotonic;
    if (progress) monotonic.emplace(progress);
    Context c{cloud,
              options,
              source,
              {},
              {},
              !options.axis.has_value(),
              fitThreads(options.threads),
              FitStage{progress ? &*monotonic : nullptr, 0.0, 1.0}};
    FitPoints& seed = c.seedSample;
    seed = gatherPoints(cloud, stratifiedSample(n, kSeedPoints, options.seed, kSeedStream), true);
    if (seed.size() < kMinPoints) return invalid(source, "fewer than 100 finite points");
    c.frame = frameOf(seed);
    if (!(c.frame.scale > 0.0)) return invalid(source, "all points coincide");
    if (options.axis) {
        c.axis.direction = options.axis->direction.normalized();
        c.axis.point = options.axis->point - cloud.origin - c.frame.centre;
    } else {
        if (seed.normals.empty()) {
            if (Status s = estimateSampleNormals(seed, c.frame.centre, c.threads, c.stage.part(0.0, 0.15), source); !s)
                return s.error();
        }
        c.axis = lineComplexAxis(seed, c.frame.centre, c.frame.scale);
        if (options.kind != SurfaceKind::Revolution) {
            // A fragment's outer face is a minority of its normals: the line complex leans towards its
            // fracture planes. Candidates from pairs of normals, scored by inliers, win when clearly better.
            const double band = kPairBandOfSize * c.frame.scale;
            AxisScore complexScore;
            polishAxis(seed, c.frame.centre, c.axis, band, complexScore); // its score only: the axis stays the complex's
            AxisScore pairScore;
            const FitLine pair = pairSeedAxis(seed, c.frame.centre, band, kPairTrials,
                                              splitMix64(options.seed, kPairStream), pairScore);
            if (double(pairScore.inliers) > kPairOverComplex * double(complexScore.inliers) &&
                normalsTurnWithTheArc(seed, c.frame.centre, pair, band, pairScore))
                c.axis = pair;
        }
    }
    if (c.stage.cancelled()) return cancelled(source);
    c.stage.update(0.2);

    Result<FitReport> report =
        options.kind == SurfaceKind::Revolution ? fitRevolution(c) : fitRadial(c, options.kind == SurfaceKind::Cone);
    if (!report) return report;
    report->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (progress) monotonic->update(1.0);
    return report;
}

} // namespace stylos::core::unroll
