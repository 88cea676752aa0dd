#include "stylos/core/normals/NeighbourhoodPca.h"

#include <algorithm>
#include <cmath>

namespace stylos::core::normals {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double squaredNorm(const Vec3& a) { return a[0] * a[0] + a[1] * a[1] + a[2] * a[2]; }

/**
 * Unit eigenvector of the symmetric @p m (rows r0 r1 r2 = m − λI given) for an eigenvalue λ of
 * multiplicity one: the longest cross product of two rows. If all are ~zero (λ is a double root), any
 * unit vector orthogonal to the longest row.
 */
Vec3 nullVector(const Vec3& r0, const Vec3& r1, const Vec3& r2)
{
    const Vec3 c[3] = {cross(r0, r1), cross(r0, r2), cross(r1, r2)};
    const double n[3] = {squaredNorm(c[0]), squaredNorm(c[1]), squaredNorm(c[2])};
    const int best = n[0] >= n[1] ? (n[0] >= n[2] ? 0 : 2) : (n[1] >= n[2] ? 1 : 2);
    const double rows[3] = {squaredNorm(r0), squaredNorm(r1), squaredNorm(r2)};
    const double scale = std::max({rows[0], rows[1], rows[2]});
    if (n[best] > 1e-24 * scale * scale) {
        const double inverse = 1.0 / std::sqrt(n[best]);
        return {c[best][0] * inverse, c[best][1] * inverse, c[best][2] * inverse};
    }
    // Double root: the eigenspace is the plane orthogonal to the (parallel) rows.
    const Vec3& r = rows[0] >= rows[1] ? (rows[0] >= rows[2] ? r0 : r2) : (rows[1] >= rows[2] ? r1 : r2);
    const Vec3 helper = std::abs(r[0]) <= std::abs(r[1]) && std::abs(r[0]) <= std::abs(r[2]) ? Vec3{1, 0, 0}
                        : std::abs(r[1]) <= std::abs(r[2])                                   ? Vec3{0, 1, 0}
                                                                                             : Vec3{0, 0, 1};
    const Vec3 v = scale > 0 ? cross(r, helper) : Vec3{0, 0, 1};
    const double length = std::sqrt(squaredNorm(v));
    return length > 0 ? Vec3{v[0] / length, v[1] / length, v[2] / length} : Vec3{0, 0, 1};
}

/** Smallest eigenvalue of the symmetric matrix with trace 1 (Smith's trigonometric closed form). */
double smallestEigenvalueClosedForm(double xx, double xy, double xz, double yy, double yz, double zz)
{
    constexpr double third = 1.0 / 3.0, twoPiThirds = 2.0943951023931954923;
    const double offDiagonal = xy * xy + xz * xz + yz * yz;
    const double dx = xx - third, dy = yy - third, dz = zz - third;
    const double p = std::sqrt((dx * dx + dy * dy + dz * dz + 2.0 * offDiagonal) / 6.0);
    if (!(p > 0.0)) return third; // isotropic
    const double inverse = 1.0 / p;
    const double bxx = dx * inverse, byy = dy * inverse, bzz = dz * inverse;
    const double bxy = xy * inverse, bxz = xz * inverse, byz = yz * inverse;
    const double det = bxx * (byy * bzz - byz * byz) - bxy * (bxy * bzz - byz * bxz) + bxz * (bxy * byz - byy * bxz);
    const double phi = std::acos(std::clamp(0.5 * det, -1.0, 1.0)) * third;
    return std::max(0.0, third + 2.0 * p * std::cos(phi + twoPiThirds));
}

} // namespace

Covariance3 neighbourhoodCovariance(std::span<const double> xyz, std::size_t count)
{
    CovarianceAccumulator accumulator;
    for (std::size_t j = 0; j < count; ++j) accumulator.add(xyz[3 * j], xyz[3 * j + 1], xyz[3 * j + 2]);
    return accumulator.covariance();
}

PlaneFit fitPlane(const Covariance3& c, std::size_t points)
{
    PlaneFit fit;
    const double trace = c.xx + c.yy + c.zz;
    if (points < 3 || !(trace > 0.0)) return fit; // too few, or all points identical

    // Scaled so that the eigenvalues sum to 1: the characteristic polynomial is
    // q(x) = x³ − x² + c1·x − c0, with c1 the sum of the principal 2×2 minors and c0 the determinant.
    const double s = 1.0 / trace;
    const double xx = c.xx * s, xy = c.xy * s, xz = c.xz * s, yy = c.yy * s, yz = c.yz * s, zz = c.zz * s;
    const double c1 = std::max(0.0, (xx * yy - xy * xy) + (xx * zz - xz * xz) + (yy * zz - yz * yz));
    const double c0 = std::max(0.0, xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * xz) + xz * (xy * yz - yy * xz));

    // Smallest root by Newton's method from 0: all roots are real and ≥ 0, so the iterates rise
    // monotonically to λ0 without overshooting, in 2–4 steps on a surface (λ0 ≪ λ1). Convergence is
    // only linear when λ0 ≈ λ1 (a blob, not a surface): then the trigonometric closed form.
    double l0 = 0.0;
    if (c1 > 0.0) {
        bool converged = false;
        for (int iteration = 0; iteration < 8 && !converged; ++iteration) {
            const double value = ((l0 - 1.0) * l0 + c1) * l0 - c0;
            const double slope = (3.0 * l0 - 2.0) * l0 + c1;
            const double step = slope > 0.0 ? -value / slope : 0.0;
            if (step > 0.0) l0 += step;
            converged = !(step > 1e-15); // eigenvalues are ≤ 1 here: 1e-15 is at rounding level
        }
        if (!converged) l0 = smallestEigenvalueClosedForm(xx, xy, xz, yy, yz, zz);
    }
    // The two others from their sum (1 − λ0) and product (c1 − λ0·(1 − λ0)).
    const double sum = 1.0 - l0, product = std::max(0.0, c1 - l0 * sum);
    const double l2 = 0.5 * (sum + std::sqrt(std::max(0.0, sum * sum - 4.0 * product)));
    const double l1 = l2 > 0.0 ? product / l2 : 0.0;
    fit.eigenvalues = {l0 * trace, l1 * trace, l2 * trace};

    fit.normal = nullVector({xx - l0, xy, xz}, {xy, yy - l0, yz}, {xz, yz, zz - l0});
    if (l1 <= 1e-6 * l2) { // points on a line (spread across under 1/1000 of the length)
        fit.axis = nullVector({xx - l2, xy, xz}, {xy, yy - l2, yz}, {xz, yz, zz - l2});
        fit.shape = NeighbourhoodShape::Collinear;
        return fit;
    }
    fit.shape = NeighbourhoodShape::Surface;
    fit.surfaceVariation = l0;
    return fit;
}

} // namespace stylos::core::normals
