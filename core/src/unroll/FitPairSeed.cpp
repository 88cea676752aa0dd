#include "FitPairSeed.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace stylos::core::unroll::detail {
namespace {

constexpr std::size_t kScorePoints = 4000;
constexpr double kMinRadial = 0.8660254037844387;  ///< cos 30°: |n·e_ρ| of a normal of the surface (flute walls ≤ 24°)
constexpr double kMinPairSine = 0.2923717047227367; ///< sin 17°: two normals that far apart make a direction
constexpr std::size_t kPolished = 8;  ///< best raw candidates polished on their inliers
constexpr int kPolishRounds = 3;
constexpr double kMinTurn = 0.5; ///< normals turn with the azimuth at a rate in (0.5, 1.5) on a true arc

Eigen::Vector3d pointAt(const FitPoints& s, std::size_t i, const Eigen::Vector3d& centre)
{
    return Eigen::Vector3d(s.xyz[3 * i], s.xyz[3 * i + 1], s.xyz[3 * i + 2]) - centre;
}

Eigen::Vector3d normalAt(const FitPoints& s, std::size_t i)
{
    const Eigen::Vector3d n(s.normals[3 * i], s.normals[3 * i + 1], s.normals[3 * i + 2]);
    const double length = n.norm();
    return length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
}

/** The sample's points within the band of @p score about @p line, normal nearly ⊥ the axis (stride as scoring). */
void inliersOf(const FitPoints& sample, const Eigen::Vector3d& centre, const FitLine& line, double band,
               const AxisScore& score, std::vector<std::size_t>& out)
{
    out.clear();
    const std::size_t n = sample.size();
    const std::size_t stride = std::max<std::size_t>(1, n / kScorePoints);
    const Eigen::Vector3d d = line.direction.normalized();
    for (std::size_t i = 0; i < n; i += stride) {
        const Eigen::Vector3d w = pointAt(sample, i, centre) - line.point;
        const Eigen::Vector3d radial = w - w.dot(d) * d;
        const double r = radial.norm();
        if (std::abs(normalAt(sample, i).dot(radial)) < kMinRadial * r) continue;
        if (std::abs(r - score.radius) <= band) out.push_back(i);
    }
}

/** A local optimisation of a candidate on its inliers (LO-RANSAC): the direction least aligned with
 *  their normals, then the circle through their projections (algebraic fit), a few rounds. */
FitLine polish(const FitPoints& sample, const Eigen::Vector3d& centre, FitLine line, double band, AxisScore& score)
{
    std::vector<std::size_t> in;
    for (int round = 0; round < kPolishRounds; ++round) {
        inliersOf(sample, centre, line, band, score, in);
        if (in.size() < 10) break;
        Eigen::Matrix3d nn = Eigen::Matrix3d::Zero();
        for (std::size_t i : in) {
            const Eigen::Vector3d m = normalAt(sample, i);
            nn += m * m.transpose();
        }
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(nn);
        Eigen::Vector3d d = eigen.eigenvectors().col(0).normalized();
        if (d.dot(line.direction) < 0.0) d = -d;
        const Eigen::Vector3d u = d.unitOrthogonal(), v = d.cross(u);
        Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
        Eigen::Vector3d b = Eigen::Vector3d::Zero();
        const Eigen::Vector3d origin = line.point;
        for (std::size_t i : in) {
            const Eigen::Vector3d w = pointAt(sample, i, centre) - origin;
            const double x = w.dot(u), y = w.dot(v);
            const Eigen::Vector3d row(x, y, 1.0);
            a += row * row.transpose();
            b -= (x * x + y * y) * row;
        }
        const Eigen::Vector3d def = a.ldlt().solve(b);
        if (!def.allFinite()) break;
        const double cx = -0.5 * def[0], cy = -0.5 * def[1];
        FitLine next;
        next.direction = d;
        next.point = origin + cx * u + cy * v;
        next.point -= next.point.dot(d) * d;
        const AxisScore nextScore = scoreCylinderAxis(sample, centre, next, band);
        if (nextScore.inliers < score.inliers) break;
        line = next;
        score = nextScore;
    }
    return line;
}

} // namespace

AxisScore scoreCylinderAxis(const FitPoints& sample, const Eigen::Vector3d& centre, const FitLine& line, double band)
{
    AxisScore score;
    const std::size_t n = sample.size();
    if (n == 0 || sample.normals.size() != sample.xyz.size()) return score;
    const std::size_t stride = std::max<std::size_t>(1, n / kScorePoints);
    const Eigen::Vector3d d = line.direction.normalized();
    std::vector<double> rho;
    rho.reserve(n / stride + 1);
    for (std::size_t i = 0; i < n; i += stride) {
        const Eigen::Vector3d w = pointAt(sample, i, centre) - line.point;
        const Eigen::Vector3d radial = w - w.dot(d) * d;
        const double r = radial.norm();
        if (std::abs(normalAt(sample, i).dot(radial)) < kMinRadial * r) continue;
        rho.push_back(r);
    }
    std::sort(rho.begin(), rho.end());
    std::size_t lo = 0;
    for (std::size_t hi = 0; hi < rho.size(); ++hi) {
        while (rho[hi] - rho[lo] > 2.0 * band) ++lo;
        if (hi - lo + 1 > score.inliers) {
            score.inliers = hi - lo + 1;
            score.radius = 0.5 * (rho[hi] + rho[lo]);
        }
    }
    return score;
}

FitLine pairSeedAxis(const FitPoints& sample, const Eigen::Vector3d& centre, double band, int trials,
                     std::uint64_t seed, AxisScore& best)
{
    best = {};
    const std::size_t n = sample.size();
    if (n < 2 || sample.normals.size() != sample.xyz.size()) return {};
    std::vector<std::pair<AxisScore, FitLine>> raw;
    for (int t = 0; t < trials; ++t) {
        const std::size_t i = splitMix64(seed, 2 * std::uint64_t(t)) % n;
        const std::size_t j = splitMix64(seed, 2 * std::uint64_t(t) + 1) % n;
        const Eigen::Vector3d ni = normalAt(sample, i), nj = normalAt(sample, j);
        Eigen::Vector3d d = ni.cross(nj);
        if (!(d.norm() > kMinPairSine)) continue;
        d.normalize();
        // The normal lines projected on the plane ⊥ d: pᵢ + a·mᵢ and pⱼ + b·mⱼ; their crossing.
        const Eigen::Vector3d pi = pointAt(sample, i, centre), pj = pointAt(sample, j, centre);
        const Eigen::Vector3d mi = ni - ni.dot(d) * d, mj = nj - nj.dot(d) * d;
        const Eigen::Vector3d delta = pj - pi;
        Eigen::Matrix2d a;
        a << mi.dot(mi), -mi.dot(mj), mi.dot(mj), -mj.dot(mj);
        const Eigen::Vector2d rhs(delta.dot(mi), delta.dot(mj));
        if (!(std::abs(a.determinant()) > 1e-12)) continue;
        const Eigen::Vector2d ab = a.partialPivLu().solve(rhs);
        FitLine line;
        line.direction = d;
        line.point = pi + ab[0] * mi;
        line.point -= line.point.dot(d) * d;
        if (!line.point.allFinite()) continue;
        raw.emplace_back(scoreCylinderAxis(sample, centre, line, band), line);
    }
    // The best raw candidates (ties by trial order: deterministic), each polished on its inliers.
    std::stable_sort(raw.begin(), raw.end(),
                     [](const auto& a, const auto& b) { return a.first.inliers > b.first.inliers; });
    FitLine bestLine;
    for (std::size_t k = 0; k < std::min(raw.size(), kPolished); ++k) {
        AxisScore score = raw[k].first;
        const FitLine line = polish(sample, centre, raw[k].second, band, score);
        if (score.inliers > best.inliers) {
            best = score;
            bestLine = line;
        }
    }
    return bestLine;
}

bool normalsTurnWithTheArc(const FitPoints& sample, const Eigen::Vector3d& centre, const FitLine& line, double band,
                           const AxisScore& score)
{
    std::vector<std::size_t> in;
    inliersOf(sample, centre, line, band, score, in);
    if (in.size() < 10) return false;
    const Eigen::Vector3d d = line.direction.normalized();
    // Azimuths measured from the inliers' mean radial direction, so that the arc does not wrap.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (std::size_t i : in) {
        const Eigen::Vector3d w = pointAt(sample, i, centre) - line.point;
        mean += (w - w.dot(d) * d).normalized();
    }
    if (!(mean.norm() > 0.0)) return false;
    const Eigen::Vector3d u = mean.normalized(), v = d.cross(u);
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i : in) {
        const Eigen::Vector3d w = pointAt(sample, i, centre) - line.point;
        Eigen::Vector3d m = normalAt(sample, i);
        if (m.dot(w - w.dot(d) * d) < 0.0) m = -m; // outward
        const double phi = std::atan2(w.dot(v), w.dot(u)), psi = std::atan2(m.dot(v), m.dot(u));
        sx += phi, sy += psi, sxx += phi * phi, sxy += phi * psi;
    }
    const double count = double(in.size());
    const double varPhi = sxx / count - (sx / count) * (sx / count);
    if (!(varPhi > 0.0)) return false;
    const double slope = (sxy / count - (sx / count) * (sy / count)) / varPhi;
    return slope > kMinTurn && slope < 2.0 - kMinTurn;
}

FitLine polishAxis(const FitPoints& sample, const Eigen::Vector3d& centre, const FitLine& line, double band,
                   AxisScore& score)
{
    score = scoreCylinderAxis(sample, centre, line, band);
    return polish(sample, centre, line, band, score);
}

} // namespace stylos::core::unroll::detail
