// NeighbourhoodPca.h (suite NormalPca): covariance and plane fit against exact cases and against Eigen's iterative solver.
#include "stylos/core/normals/NeighbourhoodPca.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace stylos::core::normals;

namespace {

double absDot(const std::array<double, 3>& a, const Eigen::Vector3d& b)
{
    return std::abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

} // namespace

TEST(NormalPca, CovarianceOfKnownPoints)
{
    // Four corners of a 2 × 4 rectangle in the plane z = 1e6 (large coordinates lose nothing).
    const std::vector<double> xyz{1e6, 1e6, 1e6, 1e6 + 2, 1e6, 1e6, 1e6, 1e6 + 4, 1e6, 1e6 + 2, 1e6 + 4, 1e6};
    const Covariance3 c = neighbourhoodCovariance(xyz, 4);
    EXPECT_DOUBLE_EQ(c.xx, 1.0);
    EXPECT_DOUBLE_EQ(c.yy, 4.0);
    EXPECT_EQ(c.zz, 0.0);
    EXPECT_EQ(c.xy, 0.0);
    const PlaneFit fit = fitPlane(c, 4);
    EXPECT_EQ(fit.shape, NeighbourhoodShape::Surface);
    EXPECT_EQ(std::abs(fit.normal[2]), 1.0);
    EXPECT_EQ(fit.surfaceVariation, 0.0);
    EXPECT_NEAR(fit.eigenvalues[1], 1.0, 1e-12);
    EXPECT_NEAR(fit.eigenvalues[2], 4.0, 1e-12);
}

TEST(NormalPca, IdenticalPointsGiveExactlyZero)
{
    const std::vector<double> xyz{0.1, 0.2, 0.3, 0.1, 0.2, 0.3, 0.1, 0.2, 0.3, 0.1, 0.2, 0.3};
    const Covariance3 c = neighbourhoodCovariance(xyz, 4);
    EXPECT_EQ(c.xx + c.yy + c.zz + std::abs(c.xy) + std::abs(c.xz) + std::abs(c.yz), 0.0);
    EXPECT_EQ(fitPlane(c, 4).shape, NeighbourhoodShape::Coincident);
    EXPECT_EQ(fitPlane(c, 4).surfaceVariation, 1.0);
}

TEST(NormalPca, FewerThanThreePointsAreCoincident)
{
    const std::vector<double> xyz{0, 0, 0, 1, 1, 1};
    EXPECT_EQ(fitPlane(neighbourhoodCovariance(xyz, 2), 2).shape, NeighbourhoodShape::Coincident);
    EXPECT_EQ(fitPlane(neighbourhoodCovariance(xyz, 0), 0).shape, NeighbourhoodShape::Coincident);
}

TEST(NormalPca, PointsOnALineAreCollinear)
{
    std::vector<double> xyz;
    for (int i = 0; i < 16; ++i) xyz.insert(xyz.end(), {0.3 * i, -0.6 * i, 0.2 * i + 5});
    const PlaneFit fit = fitPlane(neighbourhoodCovariance(xyz, 16), 16);
    EXPECT_EQ(fit.shape, NeighbourhoodShape::Collinear);
    const double length = std::sqrt(0.09 + 0.36 + 0.04);
    EXPECT_NEAR(std::abs(fit.axis[0] * 0.3 - fit.axis[1] * 0.6 + fit.axis[2] * 0.2), length, 1e-9);
}

TEST(NormalPca, AgreesWithEigensIterativeSolver)
{
    // Random neighbourhoods from flat (surfaces) to round (blobs), randomly rotated.
    std::mt19937_64 random(3);
    std::normal_distribution<double> gauss;
    for (int trial = 0; trial < 2000; ++trial) {
        const double flatness = std::pow(10.0, -6.0 * (trial % 7) / 6.0); // 1 … 1e-6
        const Eigen::Matrix3d rotation = Eigen::Quaterniond(gauss(random), gauss(random), gauss(random), gauss(random))
                                             .normalized()
                                             .toRotationMatrix();
        std::vector<double> xyz;
        for (int j = 0; j < 16; ++j) {
            const Eigen::Vector3d p =
                rotation * Eigen::Vector3d(gauss(random), 0.5 * gauss(random), flatness * gauss(random)) +
                Eigen::Vector3d(100, -200, 300);
            xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
        }
        const Covariance3 c = neighbourhoodCovariance(xyz, 16);
        Eigen::Matrix3d m;
        m << c.xx, c.xy, c.xz, c.xy, c.yy, c.yz, c.xz, c.yz, c.zz;
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> reference(m);
        const PlaneFit fit = fitPlane(c, 16);
        ASSERT_EQ(fit.shape, NeighbourhoodShape::Surface) << "trial " << trial;
        const Eigen::Vector3d values = reference.eigenvalues();
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(fit.eigenvalues[i], values[i], 1e-12 * values[2]) << "trial " << trial;
        // The normal is well defined when λ0 is well below λ1 (always here but for the roundest blobs).
        if (values[0] < 0.5 * values[1]) {
            EXPECT_GT(absDot(fit.normal, reference.eigenvectors().col(0)), 1.0 - 1e-9) << "trial " << trial;
        }
        EXPECT_NEAR(fit.surfaceVariation, values[0] / values.sum(), 1e-12) << "trial " << trial;
    }
}
