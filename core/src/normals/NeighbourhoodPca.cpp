#include "stylos/core/normals/NeighbourhoodPca.h"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace stylos::core::normals {

Covariance3 neighbourhoodCovariance(std::span<const double> xyz, std::size_t count)
{
    Covariance3 c;
    if (count == 0) return c;
    const double x0 = xyz[0], y0 = xyz[1], z0 = xyz[2];
    double mx = 0, my = 0, mz = 0;
    for (std::size_t j = 0; j < count; ++j) {
        mx += xyz[3 * j] - x0;
        my += xyz[3 * j + 1] - y0;
        mz += xyz[3 * j + 2] - z0;
    }
    const double inverse = 1.0 / static_cast<double>(count);
    mx *= inverse;
    my *= inverse;
    mz *= inverse;
    for (std::size_t j = 0; j < count; ++j) {
        const double dx = xyz[3 * j] - x0 - mx, dy = xyz[3 * j + 1] - y0 - my, dz = xyz[3 * j + 2] - z0 - mz;
        c.xx += dx * dx;
        c.xy += dx * dy;
        c.xz += dx * dz;
        c.yy += dy * dy;
        c.yz += dy * dz;
        c.zz += dz * dz;
    }
    c.xx *= inverse;
    c.xy *= inverse;
    c.xz *= inverse;
    c.yy *= inverse;
    c.yz *= inverse;
    c.zz *= inverse;
    return c;
}

PlaneFit fitPlane(const Covariance3& c, std::size_t points)
{
    PlaneFit fit;
    if (points < 3) return fit;
    Eigen::Matrix3d m;
    m << c.xx, c.xy, c.xz, c.xy, c.yy, c.yz, c.xz, c.yz, c.zz;
    if (m.cwiseAbs().maxCoeff() == 0.0) return fit; // all points identical
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(m);
    const Eigen::Vector3d values = solver.eigenvalues().cwiseMax(0.0);
    const Eigen::Matrix3d& vectors = solver.eigenvectors();
    for (int i = 0; i < 3; ++i) {
        fit.eigenvalues[i] = values[i];
        fit.normal[i] = vectors(i, 0);
        fit.axis[i] = vectors(i, 2);
    }
    if (values[2] <= 0.0) return fit; // numerically identical
    if (values[1] <= 1e-6 * values[2]) { // computeDirect is only ~1e-8·λ2 accurate near a double root
        fit.shape = NeighbourhoodShape::Collinear;
        return fit;
    }
    fit.shape = NeighbourhoodShape::Surface;
    fit.surfaceVariation = values[0] / (values[0] + values[1] + values[2]);
    return fit;
}

} // namespace stylos::core::normals
