#include "stylos/core/unroll/Unroller.h"

#include "../shading/ParallelChunks.h"
#include "UnrollAzimuth.h"
#include "UnrollCut.h"
#include "UnrollParallel.h"
#include "UnrollRaster.h"
#include "UnrollSample.h"
#include "UnrollSpacing.h"
#include "stylos/core/shading/FieldCoverage.h"
#include "stylos/core/util/SubProgress.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <new>
#include <numbers>
#include <string>
#include <vector>

namespace stylos::core::unroll {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kDefaultBand = 0.15;      ///< × referenceRadius
constexpr double kDefaultTolerance = 2.0;  ///< × pixel size
/** The default pixel is enlarged by these factors, in turn, while its image covers less than kDefaultCoverage. */
constexpr std::array<double, 4> kDefaultPixelSteps{1.25, 1.5, 2.0, 3.0};
constexpr int kMinImagePixels = 64;          ///< a given pixel must leave at least this many pixels

std::string format(const char* pattern, double value)
{
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

/** What the first pass learns about the kept points, per worker then merged. */
struct PointStats {
    std::vector<std::uint64_t> azimuths = std::vector<std::uint64_t>(detail::kAzimuthBins, 0);
    double vMin = std::numeric_limits<double>::infinity();
    double vMax = -std::numeric_limits<double>::infinity();
    std::uint64_t kept = 0;

    void merge(const PointStats& other)
    {
        for (std::size_t b = 0; b < azimuths.size(); ++b) azimuths[b] += other.azimuths[b];
        vMin = std::min(vMin, other.vMin);
        vMax = std::max(vMax, other.vMax);
        kept += other.kept;
    }
};

class Unroller {
public:
    Unroller(const cloud::PointCloud& cloud, const Surface& surface, const UnrollOptions& options,
             ProgressSink* progress)
        : m_cloud(cloud), m_surface(surface), m_options(options), m_progress(progress),
          m_source(cloud.source.empty() ? "<memory>" : cloud.source),
          m_threads(shading::detail::resolveThreads(options.threads)),
          m_e1(defaultReferenceDir(surface.axis().direction)),
          m_probe(surface, m_e1, 0.0, 1.0, 1, 1, 0.0)
    {
    }

    Result<Unrolled> run();

private:
    Error invalid(const std::string& problem) const { return Error::at(ErrorCode::InvalidArgument, m_source, {}, problem); }
    Error cancelled() const { return Error::at(ErrorCode::Cancelled, m_source, {}, "unrolling cancelled"); }
    Status checkOptions() const;
    /** Pass 1: the band, the azimuth histogram, the v range. False when cancelled. */
    bool gatherStats(PointStats& stats, std::uint64_t& offSurface);
    /** The sampling spacing from the density of the kept points (UnrollSpacing). */
    Result<double> estimateSpacing(const PointStats& stats);
    /** A given pixel far below the spacing @p d (0: unknown, no check) would leave the image mostly empty. */
    Status checkPredictedCoverage(double pixel, double d) const;
    /** A raster of the kept points at @p pixel, holes filled, with its coverage (progress @p from → @p to). */
    struct Attempt {
        shading::HeightField field;
        UnrollMap map;
        std::uint64_t averaged = 0;
        std::uint64_t outsideArc = 0; ///< kept points beyond a fragment's arc
        double tolerance = 0.0;
        shading::FieldCoverage coverage;
    };
    Result<Attempt> rasterise(const PointStats& stats, double cut, double arc, double pixel, double spacing,
                              double from, double to);
    /** ": give a pixel size of at least D mm (the sampling spacing)", or "" when @p d is unknown. */
    static std::string workingPixel(double d);

    const cloud::PointCloud& m_cloud;
    const Surface& m_surface;
    const UnrollOptions& m_options;
    ProgressSink* m_progress;
    std::string m_source;
    unsigned m_threads;
    Eigen::Vector3d m_e1;
    UnrollMap m_probe; ///< cut 0, for the azimuths from e1 and (v, h), which do not depend on the cut
    double m_band = 0.0;
};

Status Unroller::checkOptions() const
{
    const UnrollOptions& o = m_options;
    if (o.cutAngle && !std::isfinite(*o.cutAngle)) return invalid("the cut angle must be a finite number of radians");
    if (o.pixelSize && !(std::isfinite(*o.pixelSize) && *o.pixelSize > 0.0))
        return invalid("the pixel size must be a positive number of metres, got " + format("%g", *o.pixelSize));
    if (o.band && !(std::isfinite(*o.band) && *o.band > 0.0))
        return invalid("the band must be a positive number of metres, got " + format("%g", *o.band));
    if (o.depthTolerance && !(std::isfinite(*o.depthTolerance) && *o.depthTolerance >= 0.0))
        return invalid("the depth tolerance must be a number of metres ≥ 0, got " + format("%g", *o.depthTolerance));
    if (o.fillHoles && (o.holes.maxArea == 0 || o.holes.maxDepth < 0))
        return invalid("hole filling needs a largest area ≥ 1 pixel and a depth ≥ 0");
    return {};
}

bool Unroller::gatherStats(PointStats& stats, std::uint64_t& offSurface)
{
    std::vector<PointStats> perWorker(m_threads);
    const detail::UnrollAzimuth azimuth(m_probe);
    const detail::UnrollSample sample(detail::kAzimuthSamples, m_cloud.size());
    SubProgress stage(m_progress, 0.0, 0.3);
    const bool done = detail::parallelPoints(m_cloud.size(), m_threads, &stage,
                                             [&](std::size_t begin, std::size_t end, unsigned worker) {
        PointStats& mine = perWorker[worker];
        for (std::size_t i = begin; i < end; ++i) {
            const auto point = detail::keptPoint(m_probe, m_cloud, i, m_band);
            if (!point) continue;
            if (sample.taken(i)) ++mine.azimuths[detail::azimuthBin(azimuth.approxAngle(point->x, point->y))];
            mine.vMin = std::min(mine.vMin, point->v);
            mine.vMax = std::max(mine.vMax, point->v);
            ++mine.kept;
        }
    });
    if (!done) return false;
    for (const PointStats& w : perWorker) stats.merge(w);
    offSurface = m_cloud.size() - stats.kept;
    return true;
}

Result<double> Unroller::estimateSpacing(const PointStats& stats)
{
    const detail::UnrollSpacing plan(m_probe.circumference(), stats.vMin, stats.vMax, stats.kept);
    auto tooFew = [&] {
        return invalid("cannot estimate the sampling spacing from " + std::to_string(stats.kept)
                       + " points on the surface: give a pixel size");
    };
    if (!plan.possible()) return tooFew();
    std::vector<std::vector<std::uint32_t>> counts(m_threads);
    const detail::UnrollAzimuth azimuth(m_probe);
    const double radius = m_surface.referenceRadius();
    SubProgress stage(m_progress, 0.3, 0.35);
    const bool done = detail::parallelPoints(m_cloud.size(), m_threads, &stage,
                                             [&](std::size_t begin, std::size_t end, unsigned worker) {
        auto& mine = counts[worker];
        if (mine.empty()) mine.assign(plan.cellCount(), 0);
        for (std::size_t i = begin; i < end; ++i) {
            if (!plan.sampled(i)) continue;
            const auto point = detail::keptPoint(m_probe, m_cloud, i, m_band);
            if (!point) continue;
            const std::size_t cell = plan.cellOf(radius * azimuth.approxAngle(point->x, point->y), point->v);
            if (cell < mine.size()) ++mine[cell];
        }
    });
    if (!done) return cancelled();
    std::vector<std::uint32_t> total(plan.cellCount(), 0);
    for (const auto& mine : counts)
        for (std::size_t k = 0; k < mine.size(); ++k) total[k] += mine[k];
    const auto spacing = plan.estimate(total);
    if (!spacing) return tooFew();
    return *spacing;
}

Result<Unroller::Attempt> Unroller::rasterise(const PointStats& stats, double cut, double arc, double pixel,
                                              double spacing, double from, double to)
{
    const double vTop = pixel * std::ceil(stats.vMax / pixel);
    const double width = std::ceil(m_probe.circumference() * (arc / kTwoPi) / pixel);
    const double height = std::floor((vTop - stats.vMin) / pixel) + 1.0;
    const double limit = shading::HeightField::kMaxSide;
    if (!(width <= limit) || !(height <= limit))
        return invalid("the développée would be " + format("%.0f", width) + " × " + format("%.0f", height)
                       + " pixels (pixel size " + format("%.4g", pixel * 1000.0) + " mm); the limit is "
                       + std::to_string(shading::HeightField::kMaxSide) + " a side: give a larger --pixel-size");
    UnrollMap map(m_surface, m_e1, cut, pixel, int(width), int(height), vTop);
    const double tolerance = m_options.depthTolerance.value_or(kDefaultTolerance * pixel);
    detail::UnrollRaster raster(m_cloud, map, m_band, tolerance, m_threads);
    const double split = from + 0.85 * (to - from);
    Result<shading::HeightField> field = shading::HeightField{};
    try {
        field = shading::HeightField::create(int(width), int(height), pixel);
        if (!field) return invalid(field.error().message);
        SubProgress rasterStage(m_progress, from, split);
        if (!raster.run(*field, &rasterStage)) return cancelled();
    } catch (const std::bad_alloc&) {
        return Error::at(ErrorCode::OutOfBudget, m_source, {},
                         "not enough memory for a développée of " + format("%.0f", width) + " × "
                             + format("%.0f", height) + " pixels (21 bytes a pixel while unrolling)");
    }
    if (m_options.fillHoles) {
        SubProgress fillStage(m_progress, split, to);
        auto filled = shading::fillHoles(*field, m_options.holes, &fillStage);
        if (!filled) {
            if (filled.error().code == ErrorCode::Cancelled) return cancelled();
            return invalid(filled.error().message);
        }
    }
    if (m_progress && m_progress->isCancelRequested()) return cancelled();
    const double closing = spacing > 0.0 ? std::ceil(2.0 * spacing / pixel) : 2.0;
    const int radius = int(std::clamp(closing, 1.0, 64.0));
    const auto coverage = shading::measureCoverage(*field, radius); // before the gaps are filled: the pixel rule's
    if (m_options.fillHoles) {
        // The gaps between samples inside the footprint, whatever their extent: at a pixel near the spacing they
        // join into networks larger than the holes filled above, which read as cracks.
        SubProgress gapStage(m_progress, to, to); // quick: no share of the bar, but it can be cancelled
        auto gaps = shading::fillFootprintGaps(*field, radius, m_options.holes.connectivity, &gapStage);
        if (!gaps) {
            if (gaps.error().code == ErrorCode::Cancelled) return cancelled();
            return invalid(gaps.error().message);
        }
    }
    return Attempt{std::move(*field), std::move(map), raster.pointsAveraged(), raster.pointsOutsideArc(), tolerance,
                   coverage};
}

std::string Unroller::workingPixel(double d)
{
    if (!(d > 0.0)) return "";
    return ": give a pixel size of at least " + format("%.4g", d * 1000.0) + " mm (the sampling spacing)";
}

Status Unroller::checkPredictedCoverage(double pixel, double d) const
{
    if (!(d > 0.0) || m_options.minCoverage <= 0.0) return {};
    const double perPixel = (pixel / d) * (pixel / d);
    if (perPixel >= kMinPointsPerPixel) return {};
    // Points land in about 1 − e^(−λ) of the pixels at λ points a pixel (Poisson), too few to fill from.
    const double share = 1.0 - std::exp(-perPixel);
    return invalid("a pixel of " + format("%.4g", pixel * 1000.0) + " mm would leave the développée mostly empty"
                   " (about " + format("%.1f", share * 100.0) + " % of its pixels with a point; the points are "
                   + format("%.4g", d * 1000.0) + " mm apart)" + workingPixel(d));
}

Result<Unrolled> Unroller::run()
{
    const auto start = std::chrono::steady_clock::now();
    if (auto s = checkOptions(); !s) return s.error();
    if (m_cloud.empty()) return invalid("the cloud has no points to unroll");
    const double radius = m_surface.referenceRadius();
    m_band = m_options.band.value_or(kDefaultBand * radius);

    PointStats stats;
    std::uint64_t offSurface = 0;
    if (!gatherStats(stats, offSurface)) return cancelled();
    if (stats.kept == 0)
        return invalid("none of the " + std::to_string(m_cloud.size()) + " points lies within "
                       + format("%.4g", m_band * 1000.0) + " mm of the " + surfaceKindName(m_surface.kind())
                       + " (radius " + format("%.4g", radius) + " m): is it the right surface?");

    double cut = m_options.cutAngle ? *m_options.cutAngle - kTwoPi * std::floor(*m_options.cutAngle / kTwoPi)
                                    : detail::chooseCutAngle(stats.azimuths);
    if (!(cut < kTwoPi) || cut < 0.0) cut = 0.0;
    double arc = kTwoPi; // the whole turn, unless a fragment's points leave half of it empty
    if (!m_options.cutAngle && m_options.cropToPoints)
        if (const auto occupied = detail::occupiedArc(stats.azimuths)) cut = occupied->start, arc = occupied->span;

    // The sampling spacing d from the density of the kept points: the default pixel, and the yardstick
    // of a given one.
    double spacing = 0.0;
    if (auto estimated = estimateSpacing(stats)) spacing = *estimated;
    else if (estimated.error().code == ErrorCode::Cancelled) return estimated.error();
    else if (!m_options.pixelSize && !(m_cloud.spacing > 0.0 && std::isfinite(m_cloud.spacing)))
        return estimated.error();

    double pixel = 0.0;
    if (m_options.pixelSize) {
        pixel = *m_options.pixelSize;
        if (auto s = checkPredictedCoverage(pixel, spacing); !s) return s.error();
    } else {
        const double leafEdge = m_cloud.spacing > 0.0 && std::isfinite(m_cloud.spacing) ? m_cloud.spacing : 0.0;
        pixel = std::max(spacing, kLeafEdgesPerPixel * leafEdge);
    }

    // The raster; a default pixel grows by steps until the image covers the surface well (kDefaultCoverage).
    const bool mayGrow = !m_options.pixelSize && m_options.fillHoles;
    auto attempt = rasterise(stats, cut, arc, pixel, spacing, 0.35, mayGrow ? 0.9 : 1.0);
    if (!attempt) return attempt.error();
    if (m_options.pixelSize) {
        // A pixel as large as the object gives an image of a few pixels (10 m: 1 × 2), no développée (a thin band
        // of one row is one).
        const double pixels = double(attempt->field.width()) * double(attempt->field.height());
        if (pixels < kMinImagePixels)
            return invalid("a pixel of " + format("%.4g", pixel * 1000.0) + " mm gives a développée of " +
                           std::to_string(attempt->field.width()) + " × " + std::to_string(attempt->field.height()) +
                           " pixels: give a pixel size of at most " +
                           format("%.4g", pixel * std::sqrt(std::max(pixels, 1.0) / kMinImagePixels) * 1000.0) + " mm");
    }
    if (m_options.pixelSize && attempt->coverage.fraction() < m_options.minCoverage)
        return invalid("a pixel of " + format("%.4g", pixel * 1000.0) + " mm covers only "
                       + format("%.1f", attempt->coverage.fraction() * 100.0) + " % of the surface"
                       + workingPixel(spacing));
    if (mayGrow) {
        const double base = pixel;
        for (std::size_t k = 0; k < kDefaultPixelSteps.size() && attempt->coverage.fraction() < kDefaultCoverage; ++k) {
            const double from = 0.9 + 0.1 * double(k) / double(kDefaultPixelSteps.size());
            auto larger = rasterise(stats, cut, arc, base * kDefaultPixelSteps[k], spacing, from,
                                    from + 0.1 / double(kDefaultPixelSteps.size()));
            if (!larger) return larger.error();
            attempt = std::move(larger);
        }
    }
    UnrollReport report;
    shading::HeightField& field = attempt->field;
    pixel = field.pixelSize();
    const double measured = double(field.count(shading::PixelState::Measured));
    const double filledPixels = double(field.count(shading::PixelState::Filled));
    report.points = m_cloud.size();
    report.pointsUsed = stats.kept - attempt->outsideArc;
    report.pointsOffSurface = offSurface + attempt->outsideArc;
    report.pointsHidden = report.pointsUsed - attempt->averaged;
    report.cutAngle = cut;
    report.arc = arc;
    report.pixelSize = pixel;
    report.band = m_band;
    report.depthTolerance = attempt->tolerance;
    report.samplingSpacing = spacing;
    report.coverage = attempt->coverage.fraction();
    report.filledFraction = measured + filledPixels > 0.0 ? filledPixels / (measured + filledPixels) : 0.0;
    if (m_progress) m_progress->update(1.0);
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return Unrolled{std::move(field), std::move(attempt->map), report};
}

} // namespace

Result<Unrolled> unrollCloud(const cloud::PointCloud& cloud, const Surface& surface, const UnrollOptions& options,
                             ProgressSink* progress)
{
    return Unroller(cloud, surface, options, progress).run();
}

} // namespace stylos::core::unroll
