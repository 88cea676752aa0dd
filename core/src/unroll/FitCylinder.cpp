#include "FitCylinder.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace stylos::core::unroll::detail {

namespace {

constexpr std::size_t kChunk = 16 * 1024;
constexpr double kKappa = 3.0; ///< the threshold is this many robust σ
constexpr int kMaxRounds = 30; ///< Gauss–Newton rounds on the sample
constexpr int kMaxHalvings = 8;
constexpr int kMaxProfileUpdates = 8;
constexpr std::size_t kCoarsePoints = 250'000; ///< phase 1's share of the sample
constexpr std::size_t kGapPoints = 250'000;    ///< gap(): every k-th point of the sample, about this many
constexpr double kRefineTolerance = 1e-6;      ///< radians, or relative to the scale
constexpr std::size_t kProfilePointsPerBin = 50;
constexpr std::size_t kMinProfileBins = 64, kMaxProfileBins = 4096;

} // namespace

void perpendicularFrame(const Eigen::Vector3d& direction, Eigen::Vector3d& e1, Eigen::Vector3d& e2)
{
    const Eigen::Vector3d& d = direction;
    const Eigen::Vector3d any = std::abs(d.x()) < 0.6   ? Eigen::Vector3d::UnitX()
                                : std::abs(d.y()) < 0.6 ? Eigen::Vector3d::UnitY()
                                                        : Eigen::Vector3d::UnitZ();
    e1 = (any - any.dot(d) * d).normalized();
    e2 = d.cross(e1);
}

FitCylinder::FitCylinder(bool cone, bool axisFree, unsigned threads, const Eigen::Vector3d& centre, double scale)
    : m_cone(cone), m_axisFree(axisFree), m_threads(fitThreads(threads)), m_centre(centre), m_scale(scale)
{
    m_histograms.assign(m_threads, FitResidualHistogram(scale));
}

bool FitCylinder::pass(const float* xyz, std::size_t count, const RadialModel& model, double tau, bool equations,
                       bool histogram, bool profile, const FitStage& stage, RadialSums& sums)
{
    const Eigen::Vector3d q = model.axis.point + m_centre, d = model.axis.direction, e1 = model.reference;
    const Eigen::Vector3d e2 = d.cross(e1);
    const RadialKernel k{q.x(),
                         q.y(),
                         q.z(),
                         d.x(),
                         d.y(),
                         d.z(),
                         e1.x(),
                         e1.y(),
                         e1.z(),
                         e2.x(),
                         e2.y(),
                         e2.z(),
                         model.radius,
                         model.slope,
                         m_profile.values(),
                         m_profile.slopes(),
                         m_profile.bins(),
                         m_profile.perRadian()};
    const std::size_t chunks = chunkCount(count, kChunk);
    const RadialAccumulate run = radialAccumulate(equations, histogram, profile, m_profile.enabled(), m_cone);
    std::vector<RadialSums> partial(chunks);
    if (profile) {
        m_profileSamples.assign(chunks, {});
        for (std::size_t c = 0; c < chunks; ++c)
            m_profileSamples[c].reserve(std::min(kChunk, count - c * kChunk));
    }
    for (auto& h : m_histograms)
        h.clear();
    const bool finished = forEachChunk(
        count, kChunk, m_threads, stage, [&](std::size_t c, std::size_t begin, std::size_t end, unsigned worker) {
            run(xyz, begin, end, k, tau, &m_histograms[worker], profile ? &m_profileSamples[c] : nullptr, partial[c]);
        });
    if (!finished) return false;
    sums = RadialSums{};
    sums.minT = std::numeric_limits<double>::infinity();
    sums.maxT = -sums.minT;
    for (const RadialSums& c : partial)
        sums.add(c);
    for (std::size_t w = 1; w < m_histograms.size(); ++w)
        m_histograms[0].merge(m_histograms[w]);
    return true;
}

double FitCylinder::updateProfile()
{
    std::size_t total = 0;
    for (const auto& chunk : m_profileSamples)
        total += chunk.size();
    // As many bins as give ~50 inliers each at first, halved until 98 % of them hold points (a scan's
    // columns can be coarser than the bins); then kept, so that successive profiles compare, as long
    // as 90 % stay filled.
    int bins = m_profileBins > 0
                   ? m_profileBins
                   : int(std::clamp<std::size_t>(total / kProfilePointsPerBin, kMinProfileBins, kMaxProfileBins));
    std::vector<std::pair<std::uint32_t, float>> samples(total);
    for (;;) {
        std::size_t k = 0;
        const double perUnit = bins / (2.0 * std::numbers::pi) * 0x1p-28;
        for (const auto& chunk : m_profileSamples)
            for (const auto& [angle, value] : chunk)
                samples[k++] = {std::min(std::uint32_t(double(angle) * perUnit), std::uint32_t(bins - 1)), value};
        const double change = m_profile.estimate(bins, samples, m_profileBins > 0 ? 0.9 : 0.98);
        if (m_profile.enabled() || m_profileBins > 0 || bins / 2 < int(kMinProfileBins)) {
            if (m_profile.enabled()) m_profileBins = bins;
            m_profileSamples.clear();
            return change;
        }
        bins /= 2;
    }
}

std::array<double, 6> FitCylinder::solve(const RadialSums& sums) const
{
    int active[6], n = 0;
    if (m_axisFree)
        for (int i = 0; i < 4; ++i)
            active[n++] = i;
    active[n++] = 4;
    if (m_cone) active[n++] = 5;
    Eigen::MatrixXd a(n, n);
    Eigen::VectorXd b(n);
    auto entry = [&](int r, int c) { return r >= c ? sums.jtj[r * (r + 1) / 2 + c] : sums.jtj[c * (c + 1) / 2 + r]; };
    double largest = 0.0;
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c)
            a(r, c) = entry(active[r], active[c]);
        b(r) = -sums.jtr[active[r]];
        largest = std::max(largest, a(r, r));
    }
    a.diagonal().array() += 1e-12 * largest + 1e-300;
    const Eigen::VectorXd x = a.ldlt().solve(b);
    std::array<double, 6> step{};
    if (!x.allFinite()) return step;
    for (int r = 0; r < n; ++r)
        step[active[r]] = x(r);
    return step;
}

RadialModel FitCylinder::apply(const RadialModel& model, const std::array<double, 6>& step, double fraction) const
{
    const Eigen::Vector3d e1 = model.reference, e2 = model.axis.direction.cross(e1);
    RadialModel next = model;
    if (m_axisFree) { // (a given axis stays bit for bit as given)
        next.axis.direction = (model.axis.direction + fraction * (step[0] * e1 + step[1] * e2)).normalized();
        next.axis.point = model.axis.point + fraction * (step[2] * e1 + step[3] * e2);
    }
    next.radius = model.radius + fraction * step[4];
    next.slope = model.slope + fraction * step[5];
    // Carry e1 along (azimuth 0 of the profile stays put) and keep the point at the foot of the fit
    // centre (the origin of the fit frame): well conditioned.
    next.reference = (e1 - e1.dot(next.axis.direction) * next.axis.direction).normalized();
    const double shift = next.axis.point.dot(next.axis.direction);
    next.axis.point -= shift * next.axis.direction;
    next.radius -= next.slope * shift;
    return next;
}

bool FitCylinder::negligible(const std::array<double, 6>& step) const
{
    const double tolerance = kRefineTolerance;
    return std::abs(step[0]) < tolerance && std::abs(step[1]) < tolerance && std::abs(step[2]) < tolerance * m_scale &&
           std::abs(step[3]) < tolerance * m_scale && std::abs(step[4]) < tolerance * m_scale &&
           std::abs(step[5]) < tolerance;
}

bool FitCylinder::runaway(const RadialModel& model) const
{
    return !std::isfinite(model.radius) || !std::isfinite(model.slope) || !model.axis.point.allFinite() ||
           !model.axis.direction.allFinite() || std::abs(model.radius) > 1e3 * m_scale || std::abs(model.slope) > 100.0;
}

void FitCylinder::setStats(const RadialSums& sums)
{
    m_stats.points = sums.points;
    m_stats.inliers = sums.inliers;
    m_stats.rms = sums.inliers ? std::sqrt(sums.sumTrueSquares / double(sums.inliers)) : 0.0;
    m_stats.minT = sums.inliers ? sums.minT : 0.0;
    m_stats.maxT = sums.inliers ? sums.maxT : 0.0;
    m_stats.meanT = sums.inliers ? sums.sumT / double(sums.inliers) : 0.0;
}

bool FitCylinder::refine(const FitPoints& sample, const RadialModel& start, double tau0, const FitStage& stage)
{
    // Phase 1 runs on every k-th point of the sample (a quarter million are plenty to find the axis
    // roughly and the band of inliers); phase 2, whose profile needs many points per bin, on all.
    FitPoints coarse;
    const std::size_t stride = (sample.size() + kCoarsePoints - 1) / kCoarsePoints;
    if (stride > 1) {
        coarse.xyz.reserve(3 * (sample.size() / stride + 1));
        for (std::size_t i = 0; i < sample.size(); i += stride)
            coarse.xyz.insert(coarse.xyz.end(), &sample.xyz[3 * i], &sample.xyz[3 * i + 3]);
    }
    const FitPoints* points = stride > 1 ? &coarse : &sample;
    const double floor = 1e-7 * m_scale;
    m_model = start;
    Eigen::Vector3d e1, e2;
    perpendicularFrame(m_model.axis.direction, e1, e2);
    m_model.reference = e1;
    m_profile.disable();
    m_profileBins = 0;
    m_degenerate = runaway(m_model);
    RadialSums sums, trial;
    auto run = [&](const RadialModel& model, bool equations, bool histogram, bool collect, const FitStage& part,
                   RadialSums& out) {
        return pass(points->xyz.data(), points->size(), model, m_tau, equations, histogram, collect, part, out);
    };
    m_tau = tau0;
    if (!run(m_model, false, true, false, stage.part(0.0, 0.05), sums)) return false;
    m_tau = m_histograms[0].trimThreshold(tau0, kKappa, floor);
    bool fresh = false;     // sums, the histogram and the profile samples belong to (m_model, m_tau, f)
    bool profiling = false; // phase 2: with the azimuthal profile
    bool phaseTwoTried = false;
    int profileUpdates = 0;
    double tauPlain = 0.0; // the threshold at the end of phase 1
    for (int round = 0; round < kMaxRounds && !m_degenerate; ++round) {
        const FitStage part = stage.part(0.05 + 0.9 * round / kMaxRounds, 0.05 + 0.9 * (round + 1) / kMaxRounds);
        if (!fresh && !run(m_model, true, true, true, part, sums)) return false;
        fresh = true;
        const std::array<double, 6> step = solve(sums);
        bool moved = false;
        if (!negligible(step)) {
            // Halve the step until the truncated cost does not grow; the accepted trial pass is the
            // next round's pass.
            double fraction = 1.0;
            for (int halving = 0; halving < kMaxHalvings; ++halving, fraction *= 0.5) {
                const RadialModel candidate = apply(m_model, step, fraction);
                if (!run(candidate, true, true, true, part, trial)) return false;
                if (trial.cost <= sums.cost * (1.0 + 1e-12)) {
                    m_model = candidate;
                    sums = trial;
                    moved = true;
                    break;
                }
                fresh = false; // the histogram and the samples are the rejected candidate's
            }
            if (!moved && !fresh && !run(m_model, true, true, true, part, sums)) return false;
            fresh = true;
        }
        ++m_iterations;
        if (runaway(m_model)) {
            m_degenerate = true;
            break;
        }
        // τ and f from the pass at the current model; stale sums when either moved.
        const double tau = m_histograms[0].trimThreshold(m_tau, kKappa, floor);
        bool changed = std::abs(tau - m_tau) > 1e-3 * m_tau;
        m_tau = tau;
        // (No pass since the last update — the step was negligible at a fresh pass — nothing new for f.)
        if (profiling && profileUpdates < kMaxProfileUpdates && !m_profileSamples.empty()) {
            ++profileUpdates;
            const double change = updateProfile();
            if (!m_profile.enabled()) { // coverage lost: back to the threshold of phase 1, without f
                profiling = false;
                m_tau = tauPlain;
                changed = true;
            } else {
                // One point more or less moves a bin's median by ~1 % of τ: settle at 2 % RMS.
                changed = changed || change > 0.02 * m_tau;
            }
        }
        if (changed) fresh = false;
        if (moved || changed) continue;
        if (profiling || phaseTwoTried) break;
        // Phase 1 has settled: on the whole sample, estimate f from the inliers and go on with it, τ
        // coming down from where it is.
        phaseTwoTried = true;
        tauPlain = m_tau;
        points = &sample;
        if (!run(m_model, false, true, true, part, trial)) return false;
        m_tau = m_histograms[0].trimThreshold(m_tau, kKappa, floor);
        updateProfile();
        if (!m_profile.enabled()) {
            fresh = false; // the sums were the coarse sample's: phase 1 finishes on the whole one
            continue;
        }
        profiling = true;
        if (!run(m_model, false, true, false, part, trial)) return false;
        m_tau = m_histograms[0].trimThreshold(m_tau, kKappa, floor);
        fresh = false;
    }
    points = &sample;
    if (!run(m_model, false, false, false, stage.part(0.95, 1.0), sums)) return false;
    setStats(sums);
    return true;
}

bool FitCylinder::polish(const float* xyz, std::size_t count, const FitStage& stage)
{
    // One Gauss–Newton step over every point from the sample's solution (statistically within a few
    // µm of it: the step is the all-points correction); the statistics come from the same pass.
    RadialSums sums;
    if (!pass(xyz, count, m_model, m_tau, true, false, false, stage, sums)) return false;
    setStats(sums);
    const RadialModel next = apply(m_model, solve(sums), 1.0);
    if (runaway(next)) {
        m_degenerate = true;
        return true;
    }
    m_model = next;
    ++m_iterations;
    return true;
}

double FitCylinder::gap(const FitPoints& sample) const
{
    // The axial coordinates of the sample's inliers in 200 slices between the extreme inliers.
    constexpr int kGapBins = 200;
    const RadialModel& m = m_model;
    const Eigen::Vector3d q = m.axis.point + m_centre, d = m.axis.direction, e1 = m.reference, e2 = d.cross(e1);
    std::vector<double> t;
    const std::size_t stride = std::max<std::size_t>(1, sample.size() / kGapPoints);
    t.reserve(sample.size() / stride + 1);
    for (std::size_t i = 0; i < sample.size(); i += stride) {
        const Eigen::Vector3d w(static_cast<double>(sample.xyz[3 * i]) - q.x(),
                                static_cast<double>(sample.xyz[3 * i + 1]) - q.y(),
                                static_cast<double>(sample.xyz[3 * i + 2]) - q.z());
        const double ti = w.dot(d);
        const double h = (w - ti * d).norm() - (m.radius + m.slope * ti) -
                         m_profile.value(FitAzimuthProfile::fastAngle(w.dot(e1), w.dot(e2)));
        if (std::abs(h) <= m_tau) t.push_back(ti);
    }
    if (t.size() < 2) return 0.0;
    const auto [lo, hi] = std::minmax_element(t.begin(), t.end());
    const double span = *hi - *lo;
    if (!(span > 0.0)) return 0.0;
    std::vector<std::uint32_t> occupied(kGapBins, 0);
    for (double ti : t)
        ++occupied[std::size_t(std::min(kGapBins - 1, int((ti - *lo) / span * kGapBins)))];
    int run = 0, longest = 0;
    for (int b = 0; b < kGapBins; ++b) {
        run = occupied[std::size_t(b)] < 3 ? run + 1 : 0;
        longest = std::max(longest, run);
    }
    return span * longest / kGapBins;
}

void FitCylinder::reverse()
{
    m_model.axis.direction = -m_model.axis.direction;
    m_model.slope = -m_model.slope;
    m_profile.mirror(); // e2 = d × e1 turned round: the azimuth runs the other way
    const double minT = m_stats.minT;
    m_stats.minT = -m_stats.maxT;
    m_stats.maxT = -minT;
    m_stats.meanT = -m_stats.meanT;
}

} // namespace stylos::core::unroll::detail
