#include "FitMeridian.h"

#include "FitBins.h"
#include "FitCylinder.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace stylos::core::unroll::detail {

namespace {

constexpr std::size_t kChunk = 8 * 1024;
constexpr double kKappa = 3.0;
constexpr int kMaxRounds = 16;
constexpr std::size_t kPointsPerBin = 400;
constexpr int kMinBins = 16, kMaxBins = 300;
constexpr std::size_t kMinBinPoints = 10;
constexpr std::size_t kEndPoints = 20;
constexpr double kBinTaus = 4.0;
constexpr double kCapture = 3.0;       ///< the curve follows the points within this many τ...
constexpr double kStartCapture = 0.03; ///< ...once a band of this share of the scale has halved down to it
constexpr double kMaxTurn = 0.02;      ///< radians per round
constexpr double kMaxShift = 0.02;     ///< of the scale per round
constexpr double kSettledMove = 0.1;   ///< of τ: the RMS move of a settled meridian (the bins' own noise is ~5 %)
constexpr double kSettledAxis = 1e-5;  ///< radians + metres / scale: a settled axis step

int binsFor(std::size_t points)
{
    return int(std::clamp<std::size_t>(points / kPointsPerBin, kMinBins, kMaxBins));
}

double quantileOf(std::vector<float>& values, double q)
{
    const auto at = values.begin() + std::ptrdiff_t(q * double(values.size() - 1));
    std::nth_element(values.begin(), at, values.end());
    return *at;
}

/**
 * The middle of the shortest interval holding half of @p values (reordered): a location that follows
 * the densest part, so that relief standing proud on one side (a net's bands, whose flanks reach into
 * the band of inliers) does not pull it outward round after round as a median would.
 */
double shorthMidpoint(std::vector<double>& values)
{
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size(), half = n / 2;
    std::size_t best = 0;
    for (std::size_t i = 1; i + half < n; ++i)
        if (values[i + half] - values[i] < values[best + half] - values[best]) best = i;
    return 0.5 * (values[best] + values[best + half]);
}

/** The direction of travel at an end of @p vertices over its last few vertices (a steadier tangent
 *  than the last segment's, so the curve grows along a bed face or up to an apex in a round or two). */
Eigen::Vector2d endTangent(const std::vector<Eigen::Vector2d>& vertices, bool start)
{
    constexpr std::size_t kSpan = 4;
    const std::size_t n = vertices.size(), span = std::min(kSpan, n - 1);
    return start ? (vertices[span] - vertices[0]).normalized()
                 : (vertices[n - 1] - vertices[n - 1 - span]).normalized();
}

/** (v, h) of @p p beyond an end of @p vertices, along endTangent(), when it lies there. */
std::optional<MeridianCoords> alongEnds(const std::vector<Eigen::Vector2d>& vertices, double length,
                                        const Eigen::Vector2d& p)
{
    std::optional<MeridianCoords> best;
    for (const bool start : {true, false}) {
        const Eigen::Vector2d end = start ? vertices.front() : vertices.back();
        const Eigen::Vector2d tangent = endTangent(vertices, start);
        const double along = (p - end).dot(tangent) * (start ? -1.0 : 1.0);
        if (!(along > 0.0)) continue;
        const double h = (p - end).dot(Eigen::Vector2d(-tangent.y(), tangent.x()));
        if (!best || std::abs(h) < std::abs(best->h)) best = MeridianCoords{start ? -along : length + along, h};
    }
    return best;
}

/** The (t, r) at (v, h): on the meridian within [0, length], along endTangent() beyond (alongEnds()'s inverse). */
Eigen::Vector2d pointAt(const Meridian& meridian, double v, double h)
{
    const std::vector<Eigen::Vector2d>& vertices = meridian.vertices();
    if (v >= 0.0 && v <= meridian.length()) return meridian.point(v, h);
    const bool start = v < 0.0;
    const Eigen::Vector2d tangent = endTangent(vertices, start);
    const Eigen::Vector2d end = start ? vertices.front() : vertices.back();
    return end + (start ? v : v - meridian.length()) * tangent + h * Eigen::Vector2d(-tangent.y(), tangent.x());
}

} // namespace

FitMeridian::FitMeridian(bool axisFree, unsigned threads, const Eigen::Vector3d& centre, double scale)
    : m_axisFree(axisFree), m_threads(fitThreads(threads)), m_centre(centre), m_scale(scale)
{
    m_histograms.assign(m_threads, FitResidualHistogram(scale));
}

std::vector<Eigen::Vector2d> FitMeridian::resample(const std::vector<Eigen::Vector2d>& polyline, int count)
{
    std::vector<double> arc(polyline.size(), 0.0);
    for (std::size_t i = 1; i < polyline.size(); ++i)
        arc[i] = arc[i - 1] + (polyline[i] - polyline[i - 1]).norm();
    std::vector<Eigen::Vector2d> out;
    const double length = arc.back();
    if (!(length > 0.0) || count < 2) return out;
    std::size_t k = 0;
    for (int i = 0; i < count; ++i) {
        const double s = length * double(i) / double(count - 1);
        while (k + 2 < polyline.size() && arc[k + 1] < s)
            ++k;
        const double span = arc[k + 1] - arc[k];
        const double lambda = span > 0.0 ? std::clamp((s - arc[k]) / span, 0.0, 1.0) : 0.0;
        const Eigen::Vector2d p = polyline[k] + lambda * (polyline[k + 1] - polyline[k]);
        if (out.empty() || p != out.back()) out.push_back(p);
    }
    return out;
}

void FitMeridian::startVertices(const FitPoints& sample)
{
    std::vector<double> t, r;
    axialCoordinates(sample, m_centre, m_axis, t, r);
    const int bins = binsFor(sample.size());
    std::vector<Eigen::Vector2d> polyline;
    for (const FitBin& bin : medianRadiusByT(t, r, bins))
        polyline.emplace_back(bin.t, bin.r);
    m_vertices = polyline.size() >= 2 ? resample(polyline, bins) : std::vector<Eigen::Vector2d>{};
}

std::optional<Meridian> FitMeridian::makeMeridian(double reach) const
{
    auto meridian = Meridian::create(m_vertices, reach);
    if (!meridian) return std::nullopt;
    return std::move(meridian).value();
}

bool FitMeridian::project(const float* xyz, std::size_t count, const Meridian& meridian, bool keep, bool equations,
                          const FitStage& stage, Sums& sums)
{
    Eigen::Vector3d e1, e2;
    perpendicularFrame(m_axis.direction, e1, e2);
    const Eigen::Vector3d q = m_axis.point + m_centre, d = m_axis.direction;
    const double tau = m_tau;
    std::vector<Sums> chunks(chunkCount(count, kChunk));
    for (auto& h : m_histograms)
        h.clear();
    const bool finished = forEachChunk(
        count, kChunk, m_threads, stage, [&](std::size_t c, std::size_t begin, std::size_t end, unsigned worker) {
            Sums& s = chunks[c];
            FitResidualHistogram& histogram = m_histograms[worker];
            for (std::size_t i = begin; i < end; ++i) {
                const Eigen::Vector3d w(static_cast<double>(xyz[3 * i]) - q.x(),
                                        static_cast<double>(xyz[3 * i + 1]) - q.y(),
                                        static_cast<double>(xyz[3 * i + 2]) - q.z());
                const double t = w.dot(d);
                const double r = (w - t * d).norm();
                std::optional<MeridianCoords> coords = meridian.project(t, r);
                if (!coords && std::isfinite(r)) coords = alongEnds(meridian.vertices(), meridian.length(), {t, r});
                ++s.points;
                if (keep) {
                    m_v[i] = coords ? float(coords->v) : std::numeric_limits<float>::quiet_NaN();
                    m_h[i] = coords ? float(coords->h) : std::numeric_limits<float>::quiet_NaN();
                }
                if (!coords) {
                    histogram.add(std::numeric_limits<double>::infinity());
                    continue;
                }
                const double h = coords->h;
                histogram.add(std::abs(h));
                if (!(std::abs(h) <= tau)) continue;
                ++s.inliers;
                s.sumSquares += h * h;
                s.sumT += t;
                s.sumTT += t * t;
                s.sumR += r;
                s.sumRR += r * r;
                if (equations && r > 0.0) {
                    const Eigen::Vector2d n = meridian.normalAt(coords->v);
                    const double we1 = w.dot(e1), we2 = w.dot(e2);
                    const double a = we1 / r, b = we2 / r;
                    const Eigen::Vector4d j(n.x() * we1 - n.y() * t * a, n.x() * we2 - n.y() * t * b, -n.y() * a,
                                            -n.y() * b);
                    s.jtj.selfadjointView<Eigen::Lower>().rankUpdate(j);
                    s.jtr += j * h;
                }
            }
        });
    if (!finished) return false;
    sums = Sums{};
    for (const Sums& c : chunks) {
        sums.jtj += c.jtj;
        sums.jtr += c.jtr;
        sums.sumSquares += c.sumSquares;
        sums.sumT += c.sumT;
        sums.sumTT += c.sumTT;
        sums.sumR += c.sumR;
        sums.sumRR += c.sumRR;
        sums.inliers += c.inliers;
        sums.points += c.points;
    }
    for (std::size_t w = 1; w < m_histograms.size(); ++w)
        m_histograms[0].merge(m_histograms[w]);
    return true;
}

bool FitMeridian::updateVertices(const Meridian& meridian)
{
    std::vector<float> kept;
    kept.reserve(m_v.size());
    for (std::size_t i = 0; i < m_v.size(); ++i)
        if (std::abs(m_h[i]) <= m_capture) kept.push_back(m_v[i]);
    if (kept.size() < 2 * kMinBinPoints) return false;
    // The range of v: all but the kEndPoints lowest and highest inliers (a few strays along an end's
    // tangent must not stretch the curve; a fixed count, not a share, so an apex's small cap stays)...
    const double ends = std::min(double(kEndPoints), 0.001 * double(kept.size()));
    double lo = quantileOf(kept, ends / double(kept.size() - 1));
    double hi = quantileOf(kept, 1.0 - ends / double(kept.size() - 1));
    // ...in bins of at least kBinTaus τ: a meridian cannot have detail finer than the scatter of its
    // points (else it wanders through a thick cloud, a statue or clutter, and the residual means nothing).
    const int bins =
        std::clamp(std::min(binsFor(kept.size()), int((hi - lo) / (kBinTaus * m_tau))), kMinBins, kMaxBins);
    // ...where the bins are occupied (≥ 10 points and 2 % of the median bin's): beyond the current
    // ends only as far as they are without a break (clutter that happens to lie along an end's tangent
    // must not draw the curve out across empty space), and sparse bins at the ends are let go.
    {
        const double width = (hi - lo) / bins;
        if (!(width > 0.0)) return false;
        std::vector<std::size_t> counts(static_cast<std::size_t>(bins), 0);
        for (float v : kept) {
            const double x = (v - lo) / width;
            if (x >= 0.0 && x < bins) ++counts[std::size_t(x)];
        }
        std::vector<std::size_t> nonEmpty;
        for (std::size_t c : counts)
            if (c > 0) nonEmpty.push_back(c);
        std::nth_element(nonEmpty.begin(), nonEmpty.begin() + std::ptrdiff_t(nonEmpty.size() / 2), nonEmpty.end());
        const std::size_t enough = std::max(kMinBinPoints, nonEmpty[nonEmpty.size() / 2] / 50);
        auto occupied = [&](int b) { return counts[std::size_t(b)] >= enough; };
        int from = std::clamp(int((0.0 - lo) / width), 0, bins - 1);
        int to = std::clamp(int((meridian.length() - lo) / width), from, bins - 1);
        while (from > 0 && occupied(from - 1))
            --from;
        while (to + 1 < bins && occupied(to + 1))
            ++to;
        while (from < to && !occupied(from))
            ++from;
        while (to > from && !occupied(to))
            --to;
        const double qlo = lo;
        lo = qlo + from * width;
        hi = qlo + (to + 1) * width;
    }
    const double width = (hi - lo) / bins;
    if (!(width > 0.0)) return false;
    std::vector<std::vector<double>> heights(static_cast<std::size_t>(bins));
    for (std::size_t i = 0; i < m_v.size(); ++i) {
        if (!(std::abs(m_h[i]) <= m_capture)) continue;
        const double x = (m_v[i] - lo) / width;
        if (x < 0.0 || x >= bins) continue;
        heights[std::size_t(x)].push_back(m_h[i]);
    }
    // The shorth midpoint of h in each bin (a bin with too few points keeps its place: skipping it
    // would cut a chord across a gap and lose the points there for good), smoothed by (1, 2, 1) / 4
    // along the meridian (the move is smoothed, not the curve, so nothing shrinks from round to round).
    std::vector<double> move(static_cast<std::size_t>(bins), 0.0);
    for (int b = 0; b < bins; ++b) {
        std::vector<double>& values = heights[std::size_t(b)];
        if (values.size() >= kMinBinPoints) move[std::size_t(b)] = shorthMidpoint(values);
    }
    std::vector<double> smooth = move;
    for (std::size_t i = 1; i + 1 < move.size(); ++i)
        smooth[i] = 0.25 * (move[i - 1] + 2.0 * move[i] + move[i + 1]);
    // The polyline spans the inliers' whole range: the end bins' moves carry to lo and hi.
    std::vector<Eigen::Vector2d> next;
    auto add = [&](const Eigen::Vector2d& p) {
        const Eigen::Vector2d q(p.x(), std::max(p.y(), 0.0));
        if (next.empty() || (q - next.back()).norm() > 1e-9 * m_scale) next.push_back(q);
    };
    add(pointAt(meridian, lo, smooth.front()));
    m_moved = 0.0;
    for (int b = 0; b < bins; ++b) {
        add(pointAt(meridian, lo + (b + 0.5) * width, smooth[std::size_t(b)]));
        m_moved += smooth[std::size_t(b)] * smooth[std::size_t(b)];
    }
    m_moved = std::sqrt(m_moved / bins);
    add(pointAt(meridian, hi, smooth.back()));
    if (next.size() < 2) return false;
    m_endMoved = m_vertices.size() >= 2
                     ? std::max((next.front() - m_vertices.front()).norm(), (next.back() - m_vertices.back()).norm())
                     : 0.0;
    m_vertices = std::move(next);
    return true;
}

void FitMeridian::moveAxis(const Sums& sums)
{
    Eigen::Matrix4d a = sums.jtj.selfadjointView<Eigen::Lower>();
    a.diagonal().array() += 1e-12 * a.diagonal().maxCoeff() + 1e-300;
    Eigen::Vector4d step = a.ldlt().solve(-sums.jtr);
    if (!step.allFinite()) step.setZero();
    const double turn = step.head<2>().norm(), shift = step.tail<2>().norm();
    if (turn > kMaxTurn) step.head<2>() *= kMaxTurn / turn;
    if (shift > kMaxShift * m_scale) step.tail<2>() *= kMaxShift * m_scale / shift;
    m_axisStep = step.head<2>().norm() + step.tail<2>().norm() / m_scale;
    Eigen::Vector3d e1, e2;
    perpendicularFrame(m_axis.direction, e1, e2);
    m_axis.direction = (m_axis.direction + step[0] * e1 + step[1] * e2).normalized();
    m_axis.point += step[2] * e1 + step[3] * e2;
    const double c = m_axis.point.dot(m_axis.direction);
    m_axis.point -= c * m_axis.direction;
    for (Eigen::Vector2d& v : m_vertices)
        v.x() += c;
}

bool FitMeridian::fit(const FitPoints& sample, const FitLine& axis, const FitStage& stage)
{
    m_axis = axis;
    const double c = m_axis.point.dot(m_axis.direction);
    m_axis.point -= c * m_axis.direction;
    startVertices(sample);
    if (m_vertices.size() < 2) {
        m_failed = true;
        return true;
    }
    // The first band: kStartCapture of the scale (the start's error at a ledge or a corner); τ
    // comes down (or up) from a third of it.
    m_capture = 2.0 * kStartCapture * m_scale;
    m_tau = kStartCapture * m_scale / kCapture;
    const double floor = 1e-7 * m_scale;
    const std::size_t n = sample.size();
    m_v.assign(n, 0.0f);
    m_h.assign(n, 0.0f);
    Sums sums;
    for (int round = 0; round < kMaxRounds; ++round) {
        const double segment = meridianLength(m_vertices) / double(m_vertices.size() - 1);
        m_capture = std::max(kCapture * m_tau, 0.5 * m_capture);
        const auto meridian = makeMeridian(std::max(m_capture, 2.0 * segment));
        if (!meridian) {
            m_failed = true;
            return true;
        }
        const FitStage part = stage.part(double(round) / kMaxRounds, double(round + 1) / kMaxRounds);
        if (!project(sample.xyz.data(), n, *meridian, true, m_axisFree, part, sums)) return false;
        const double tau = m_histograms[0].trimThreshold(m_tau, kKappa, floor);
        const bool settled = std::abs(tau - m_tau) <= 0.02 * m_tau;
        m_tau = tau;
        if (!updateVertices(*meridian)) {
            m_failed = true;
            return true;
        }
        m_axisStep = 0.0;
        if (m_axisFree && round >= 1) moveAxis(sums);
        ++m_iterations;
        const bool narrowed = m_capture <= kCapture * m_tau * 1.001;
        if (round >= 2 && settled && narrowed && m_moved < kSettledMove * m_tau && m_endMoved < m_tau &&
            m_axisStep < kSettledAxis)
            break;
    }
    // Statistics, and the largest stretch of the meridian without inliers, at the final curve.
    const double segment = meridianLength(m_vertices) / double(m_vertices.size() - 1);
    const auto meridian = makeMeridian(std::max(kCapture * m_tau, 2.0 * segment));
    if (!meridian) {
        m_failed = true;
        return true;
    }
    if (!project(sample.xyz.data(), n, *meridian, true, false, stage.part(0.98, 1.0), sums)) return false;
    setStats(sums);
    constexpr int kGapBins = 200;
    const double length = meridian->length();
    std::vector<std::uint32_t> occupied(kGapBins, 0);
    for (std::size_t i = 0; i < n; ++i)
        if (std::abs(m_h[i]) <= m_tau && m_v[i] >= 0.0 && m_v[i] < length)
            ++occupied[std::min(kGapBins - 1, int(m_v[i] / length * kGapBins))];
    int run = 0, longest = 0;
    for (int b = 0; b < kGapBins; ++b) {
        run = occupied[std::size_t(b)] < 3 ? run + 1 : 0;
        longest = std::max(longest, run);
    }
    m_gap = length * longest / kGapBins;
    return true;
}

void FitMeridian::setStats(const Sums& sums)
{
    m_stats.points = sums.points;
    m_stats.inliers = sums.inliers;
    const double n = double(std::max<std::uint64_t>(1, sums.inliers));
    m_stats.rms = std::sqrt(sums.sumSquares / n);
    m_stats.tSpread = std::sqrt(std::max(0.0, sums.sumTT / n - (sums.sumT / n) * (sums.sumT / n)));
    m_stats.rSpread = std::sqrt(std::max(0.0, sums.sumRR / n - (sums.sumR / n) * (sums.sumR / n)));
}

void FitMeridian::reverse()
{
    m_axis.direction = -m_axis.direction;
    std::reverse(m_vertices.begin(), m_vertices.end());
    for (Eigen::Vector2d& v : m_vertices)
        v.x() = -v.x();
}

double meridianLength(const std::vector<Eigen::Vector2d>& vertices)
{
    double length = 0.0;
    for (std::size_t i = 1; i < vertices.size(); ++i)
        length += (vertices[i] - vertices[i - 1]).norm();
    return length;
}

} // namespace stylos::core::unroll::detail
