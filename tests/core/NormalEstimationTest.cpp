// estimateNormals: known surfaces (plane, sphere, cylinder), orientation, exactness against a brute-force
// search, determinism across thread counts, degenerate inputs, cancel and bad arguments.
#include "stylos/core/normals/NeighbourhoodPca.h"
#include "stylos/core/normals/NormalEstimation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <random>
#include <vector>

using namespace stylos::core;
using namespace stylos::core::normals;

namespace {

constexpr double kPi = 3.14159265358979323846;

/** Fibonacci lattice: @p n quasi-uniform points on a sphere of @p radius around @p c. */
std::vector<double> fibonacciSphere(std::size_t n, double radius, const std::array<double, 3>& c)
{
    std::vector<double> p(3 * n);
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    for (std::size_t i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (double(i) + 0.5) / double(n);
        const double r = std::sqrt(1.0 - z * z), a = golden * double(i);
        p[3 * i] = c[0] + radius * r * std::cos(a);
        p[3 * i + 1] = c[1] + radius * r * std::sin(a);
        p[3 * i + 2] = c[2] + radius * z;
    }
    return p;
}

/** @p n uniformly random points on the unit sphere (fixed seed), optionally with radial noise. */
std::vector<double> randomSphere(std::size_t n, unsigned seed, double noise = 0.0)
{
    std::mt19937_64 random(seed);
    std::normal_distribution<double> gauss;
    std::vector<double> p(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = gauss(random), y = gauss(random), z = gauss(random);
        const double scale = (1.0 + noise * gauss(random)) / std::sqrt(x * x + y * y + z * z);
        p[3 * i] = x * scale;
        p[3 * i + 1] = y * scale;
        p[3 * i + 2] = z * scale;
    }
    return p;
}

double angleDegrees(const float* n, const std::array<double, 3>& expected)
{
    const double length = std::sqrt(expected[0] * expected[0] + expected[1] * expected[1] + expected[2] * expected[2]);
    const double cosine = (n[0] * expected[0] + n[1] * expected[1] + n[2] * expected[2]) / length;
    return std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / kPi;
}

std::vector<float> estimate(const std::vector<double>& positions, NormalOptions options = {},
                            NormalReport* report = nullptr)
{
    std::vector<float> normals(positions.size());
    auto result = estimateNormals(positions, normals, options);
    EXPECT_TRUE(result) << result.error().message;
    if (result && report) *report = *result;
    return normals;
}

} // namespace

TEST(NormalEstimation, TiltedPlaneFacesTheViewpointExactly)
{
    // A jittered grid on a tilted plane, the viewpoint on one side: every normal is the plane normal,
    // turned toward the viewpoint, to float precision.
    const std::array<double, 3> a{0.6, 0.8, 0.0}, b{-0.48, 0.36, 0.8}, origin{1000.0, -2000.0, 50.0};
    const std::array<double, 3> normal{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    std::vector<double> positions;
    for (int i = 0; i < 60; ++i)
        for (int j = 0; j < 60; ++j) {
            const double u = 0.01 * (i + jitter(random)), v = 0.01 * (j + jitter(random));
            for (int d = 0; d < 3; ++d) positions.push_back(origin[d] + u * a[d] + v * b[d]);
        }
    for (double side : {1.0, -1.0}) {
        NormalOptions options;
        options.orientation = NormalOrientation::TowardViewpoint;
        for (int d = 0; d < 3; ++d) options.viewpoint[d] = origin[d] + 0.3 * a[d] + 0.3 * b[d] + side * 2.0 * normal[d];
        std::vector<float> quality(positions.size() / 3);
        std::vector<float> normals(positions.size());
        auto report = estimateNormals(positions, normals, options, nullptr, quality);
        ASSERT_TRUE(report) << report.error().message;
        EXPECT_EQ(report->points, 3600u);
        EXPECT_EQ(report->degenerate, 0u);
        for (std::size_t i = 0; i < quality.size(); ++i) {
            for (int d = 0; d < 3; ++d) ASSERT_NEAR(normals[3 * i + d], side * normal[d], 2e-6) << "point " << i;
            ASSERT_LT(quality[i], 1e-9f);
        }
    }
}

TEST(NormalEstimation, SphereNormalsAreRadialAndOutward)
{
    const std::array<double, 3> centre{12.5, -3.0, 400.0};
    const auto positions = fibonacciSphere(40000, 2.0, centre);
    NormalReport report;
    const auto normals = estimate(positions, {}, &report);
    double worst = 0;
    for (std::size_t i = 0; i < positions.size() / 3; ++i) {
        const std::array<double, 3> radial{positions[3 * i] - centre[0], positions[3 * i + 1] - centre[1],
                                           positions[3 * i + 2] - centre[2]};
        worst = std::max(worst, angleDegrees(&normals[3 * i], radial));
    }
    EXPECT_LT(worst, 1.0) << "largest angle to the radius, degrees";
    EXPECT_EQ(report.degenerate, 0u);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(report.centre[d], centre[d], 1e-6);
}

TEST(NormalEstimation, NoisyRandomSphereIsStillOutward)
{
    const auto positions = randomSphere(30000, 3, 0.002);
    const auto normals = estimate(positions);
    std::size_t inward = 0;
    double sum = 0;
    for (std::size_t i = 0; i < positions.size() / 3; ++i) {
        const std::array<double, 3> radial{positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
        const double angle = angleDegrees(&normals[3 * i], radial);
        inward += angle > 90.0;
        sum += angle;
    }
    EXPECT_EQ(inward, 0u);
    EXPECT_LT(sum / double(positions.size() / 3), 5.0) << "mean angle, degrees";
}

TEST(NormalEstimation, CylinderNormalsAreRadialAndOutward)
{
    // An open cylinder (radius 0.5 m, height 1.2 m) along a tilted axis: normals ⟂ axis, pointing away from it.
    const std::array<double, 3> axis{0.0, 0.6, 0.8}, u{1.0, 0.0, 0.0}, w{0.0, 0.8, -0.6}, base{3.0, 4.0, 5.0};
    std::vector<double> positions;
    for (int ring = 0; ring < 120; ++ring)
        for (int k = 0; k < 300; ++k) {
            const double h = 0.01 * ring, a = 2.0 * kPi * (k + 0.5 * (ring % 2)) / 300.0;
            for (int d = 0; d < 3; ++d)
                positions.push_back(base[d] + h * axis[d] + 0.5 * (std::cos(a) * u[d] + std::sin(a) * w[d]));
        }
    const auto normals = estimate(positions);
    double worst = 0;
    for (std::size_t i = 0; i < positions.size() / 3; ++i) {
        std::array<double, 3> r{};
        for (int d = 0; d < 3; ++d) r[d] = positions[3 * i + d] - base[d];
        const double along = r[0] * axis[0] + r[1] * axis[1] + r[2] * axis[2];
        for (int d = 0; d < 3; ++d) r[d] -= along * axis[d];
        worst = std::max(worst, angleDegrees(&normals[3 * i], r));
    }
    EXPECT_LT(worst, 1.0);
}

TEST(NormalEstimation, AgreesWithBruteForceNeighbours)
{
    // Clustered random points (several trees with 2 threads): each normal equals PCA over the k nearest
    // points found by brute force, oriented away from the centroid.
    std::mt19937_64 random(11);
    std::normal_distribution<double> gauss;
    std::vector<double> positions;
    for (int cluster = 0; cluster < 8; ++cluster) {
        const double cx = 10 * gauss(random), cy = 10 * gauss(random), cz = 10 * gauss(random);
        for (int i = 0; i < 1500; ++i)
            positions.insert(positions.end(), {cx + gauss(random), cy + 0.3 * gauss(random), cz + 0.05 * gauss(random)});
    }
    const std::size_t n = positions.size() / 3, k = 12;
    NormalOptions options;
    options.neighbours = k;
    options.threads = 2;
    NormalReport report;
    const auto normals = estimate(positions, options, &report);

    std::vector<std::size_t> order(n);
    std::vector<double> distance(n), gathered(3 * k);
    for (std::size_t q = 0; q < n; q += 7) {
        for (std::size_t i = 0; i < n; ++i) {
            double d2 = 0;
            for (int d = 0; d < 3; ++d) d2 += (positions[3 * i + d] - positions[3 * q + d]) * (positions[3 * i + d] - positions[3 * q + d]);
            distance[i] = d2;
        }
        std::iota(order.begin(), order.end(), 0);
        std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(k), order.end(),
                          [&](std::size_t x, std::size_t y) { return distance[x] < distance[y]; });
        for (std::size_t j = 0; j < k; ++j)
            for (int d = 0; d < 3; ++d) gathered[3 * j + d] = positions[3 * order[j] + d];
        const PlaneFit fit = fitPlane(neighbourhoodCovariance(gathered, k), k);
        double sign = 0;
        for (int d = 0; d < 3; ++d) sign += fit.normal[d] * (positions[3 * q + d] - report.centre[d]);
        for (int d = 0; d < 3; ++d)
            ASSERT_NEAR(normals[3 * q + d], (sign < 0 ? -1 : 1) * fit.normal[d], 1e-5) << "point " << q;
    }
}

TEST(NormalEstimation, BitwiseIdenticalWhateverTheThreadCount)
{
    const auto positions = randomSphere(60000, 5, 0.001);
    std::vector<std::vector<float>> results;
    for (unsigned threads : {1u, 2u, 3u}) {
        NormalOptions options;
        options.threads = threads;
        results.push_back(estimate(positions, options));
    }
    EXPECT_EQ(std::memcmp(results[0].data(), results[1].data(), results[0].size() * sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(results[0].data(), results[2].data(), results[0].size() * sizeof(float)), 0);
}

TEST(NormalEstimation, EmptyAndTinyCloudsGetTheFallback)
{
    NormalReport report;
    EXPECT_TRUE(estimate({}, {}, &report).empty());
    EXPECT_EQ(report.points, 0u);

    // One point: it is the centroid, so the direction from the centroid is zero: +Z.
    auto normals = estimate({5.0, 6.0, 7.0}, {}, &report);
    EXPECT_EQ(normals, (std::vector<float>{0, 0, 1}));
    EXPECT_EQ(report.degenerate, 1u);

    // Two points: each gets the direction away from their centroid.
    normals = estimate({0, 0, 0, 2, 0, 0}, {}, &report);
    EXPECT_EQ(normals, (std::vector<float>{-1, 0, 0, 1, 0, 0}));
    EXPECT_EQ(report.degenerate, 2u);

    // Toward a viewpoint instead.
    NormalOptions toward;
    toward.orientation = NormalOrientation::TowardViewpoint;
    toward.viewpoint = {0, 3, 4};
    normals = estimate({0, 0, 0, 0, 0, 0}, toward, &report);
    EXPECT_EQ(normals, (std::vector<float>{0, 0.6f, 0.8f, 0, 0.6f, 0.8f}));
}

TEST(NormalEstimation, IdenticalPointsGetTheFallback)
{
    std::vector<double> positions;
    for (int i = 0; i < 50; ++i) positions.insert(positions.end(), {0.1, 0.2, 0.3});
    positions.insert(positions.end(), {1.1, 0.2, 0.3}); // one point off the pile
    std::vector<float> quality(51);
    std::vector<float> normals(positions.size());
    auto report = estimateNormals(positions, normals, {}, nullptr, quality);
    ASSERT_TRUE(report);
    EXPECT_EQ(report->degenerate, 51u); // the pile is coincident; the last point sees a line (2 positions)
    for (int i = 0; i < 50; ++i) {
        // Away from the centroid (0.1 + 1/51, 0.2, 0.3): −X.
        EXPECT_EQ(normals[3 * i], -1.0f);
        EXPECT_NEAR(normals[3 * i + 1], 0.0f, 1e-6);
        EXPECT_NEAR(normals[3 * i + 2], 0.0f, 1e-6);
        EXPECT_EQ(quality[i], 1.0f);
    }
    // The last point's neighbourhood is a line along X, parallel to the direction from the centroid:
    // some unit vector perpendicular to the line.
    EXPECT_NEAR(normals[150], 0.0f, 1e-6);
    EXPECT_NEAR(normals[151] * normals[151] + normals[152] * normals[152], 1.0f, 1e-6);
}

TEST(NormalEstimation, CollinearPointsGetAPerpendicularFacingTheViewpoint)
{
    std::vector<double> positions;
    for (int i = 0; i < 100; ++i) positions.insert(positions.end(), {0.01 * i, 0.0, 0.0});
    NormalOptions options;
    options.orientation = NormalOrientation::TowardViewpoint;
    options.viewpoint = {0.5, 0.0, 3.0};
    NormalReport report;
    const auto normals = estimate(positions, options, &report);
    EXPECT_EQ(report.degenerate, 100u);
    for (std::size_t i = 0; i < 100; ++i) {
        EXPECT_NEAR(normals[3 * i], 0.0f, 1e-6);
        EXPECT_NEAR(normals[3 * i + 1], 0.0f, 1e-6);
        EXPECT_NEAR(normals[3 * i + 2], 1.0f, 1e-6);
    }
}

TEST(NormalEstimation, ExplicitCentreDecidesOrientation)
{
    // Sphere points with the centre given far above the sphere: every normal now satisfies n·(p − c) ≥ 0,
    // so the upper cap's normals face down, toward the sphere's middle.
    const auto positions = fibonacciSphere(5000, 1.0, {0, 0, 0});
    NormalOptions options;
    options.centre = std::array<double, 3>{0, 0, 10};
    const auto normals = estimate(positions, options);
    for (std::size_t i = 0; i < 5000; ++i) {
        double dot = 0;
        for (int d = 0; d < 3; ++d) dot += normals[3 * i + d] * (positions[3 * i + d] - (*options.centre)[d]);
        ASSERT_GE(dot, 0.0) << "point " << i;
    }
}

TEST(NormalEstimation, CancelReturnsCancelled)
{
    const auto positions = randomSphere(20000, 9);
    std::vector<float> normals(positions.size());
    SilentProgress progress;
    progress.cancel();
    auto result = estimateNormals(positions, normals, {}, &progress);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().code, ErrorCode::Cancelled);

    // Cancelled while working, from the progress callback.
    struct CancelMidway final : ProgressSink {
        std::atomic<bool> cancel{false};
        void update(double fraction) override
        {
            if (fraction > 0.3) cancel = true;
        }
        bool isCancelRequested() const override { return cancel; }
    } midway;
    result = estimateNormals(positions, normals, {}, &midway);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().code, ErrorCode::Cancelled);
}

TEST(NormalEstimation, ProgressReachesOne)
{
    const auto positions = randomSphere(20000, 4);
    std::vector<float> normals(positions.size());
    SilentProgress progress;
    ASSERT_TRUE(estimateNormals(positions, normals, {}, &progress));
    EXPECT_EQ(progress.last(), 1.0);
}

TEST(NormalEstimation, BadArgumentsAreRefused)
{
    std::vector<double> positions{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    std::vector<float> normals(positions.size()), shortNormals(3), quality(3);
    EXPECT_EQ(estimateNormals(positions, shortNormals).error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(estimateNormals(positions, normals, {}, nullptr, quality).error().code, ErrorCode::InvalidArgument);
    NormalOptions options;
    options.neighbours = 2;
    EXPECT_EQ(estimateNormals(positions, normals, options).error().code, ErrorCode::InvalidArgument);
    options.neighbours = 257;
    EXPECT_EQ(estimateNormals(positions, normals, options).error().code, ErrorCode::InvalidArgument);
    positions[4] = std::nan("");
    auto result = estimateNormals(positions, normals);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(result.error().message.find("point 1"), std::string::npos) << result.error().message;
}
