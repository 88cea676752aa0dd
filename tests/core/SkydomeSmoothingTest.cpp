// The 3D skydome's smoothing over neighbouring leaves (core/ao/SkydomeSmoothing.h): hand-computed weighted means,
// a uniform field kept, a crease whose sides keep their values, radius 0 and a cancel (at once or half-way)
// leaving the values alone, and the same result whatever the threads.
#include "stylos/core/ao/SkydomeSmoothing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
#include <random>

using namespace stylos::core::ao;

namespace {

void add(AoReceivers& r, std::array<float, 3> p, std::array<float, 3> n)
{
    r.positions.push_back(p);
    r.normals.push_back(n);
}

class CancelAtOnce : public stylos::core::ProgressSink {
public:
    void update(double) override {}
    bool isCancelRequested() const override { return true; }
};

/** Cancels from the (checks + 1)-th question on: the work before it has been done. */
class CancelAfter : public stylos::core::ProgressSink {
public:
    explicit CancelAfter(int checks) : left_(checks) {}
    void update(double) override {}
    bool isCancelRequested() const override { return left_.fetch_sub(1) <= 0; }

private:
    mutable std::atomic<int> left_;
};

} // namespace

TEST(SkydomeSmoothing, TakesTheWeightedMeanWithinTheRadius)
{
    // Three receivers on a line, normals up; radius 2: weights (1 − d²/4)².
    AoReceivers r;
    add(r, {10.0f, 10.0f, 10.0f}, {0, 0, 1});
    add(r, {11.0f, 10.0f, 10.0f}, {0, 0, 1}); // 1 from the first: weight 0.5625
    add(r, {13.0f, 10.0f, 10.0f}, {0, 0, 1}); // 3 from the first (outside), 2 from the second (the edge: 0)
    std::vector<float> values{0.2f, 0.6f, 1.0f};
    SkydomeSmoothing options;
    options.radius = 2.0;
    options.threads = 1;
    ASSERT_TRUE(smoothSkydome(r, values, options));
    EXPECT_NEAR(values[0], (0.2 + 0.5625 * 0.6) / 1.5625, 1e-6);
    EXPECT_NEAR(values[1], (0.6 + 0.5625 * 0.2) / 1.5625, 1e-6);
    EXPECT_FLOAT_EQ(values[2], 1.0f); // no neighbour within the radius: unchanged
}

TEST(SkydomeSmoothing, KeepsAUniformFieldAndTheTwoSidesOfACrease)
{
    // Two perpendicular faces of a grid meeting along x = 0: the floor (z = 0, values 0.9) and a wall
    // (x = 0, z > 0, values 0.3); their normals are 90° apart, so neither side reads the other.
    AoReceivers r;
    std::vector<float> values;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j) {
            add(r, {float(i) * 0.5f + 0.25f, float(j) * 0.5f, 0.0f}, {0, 0, 1});
            values.push_back(0.9f);
            add(r, {0.0f, float(j) * 0.5f, float(i) * 0.5f + 0.25f}, {1, 0, 0});
            values.push_back(0.3f);
        }
    SkydomeSmoothing options;
    options.radius = 1.5;
    ASSERT_TRUE(smoothSkydome(r, values, options));
    for (std::size_t i = 0; i < values.size(); ++i) EXPECT_NEAR(values[i], i % 2 == 0 ? 0.9f : 0.3f, 1e-6f) << i;
}

TEST(SkydomeSmoothing, ANormalTurnedOverStillCountsAsTheSameSurface)
{
    AoReceivers r;
    add(r, {5.0f, 5.0f, 5.0f}, {0, 0, 1});
    add(r, {5.0f, 5.5f, 5.0f}, {0, 0, -1}); // measured two-sided and turned: the same plane
    std::vector<float> values{0.0f, 1.0f};
    SkydomeSmoothing options;
    options.radius = 1.0;
    ASSERT_TRUE(smoothSkydome(r, values, options));
    EXPECT_NEAR(values[0], 0.5625 / 1.5625, 1e-6); // weight (1 − 0.25)² = 0.5625
    EXPECT_NEAR(values[1], 1.0 / 1.5625, 1e-6);
}

TEST(SkydomeSmoothing, ReducesNoiseAndGivesTheSameValuesWhateverTheThreads)
{
    AoReceivers r;
    std::vector<float> values;
    std::mt19937 random(3);
    std::uniform_real_distribution<float> jitter(-0.1f, 0.1f), noise(-0.05f, 0.05f);
    // 360,000 receivers in a shuffled order: enough for the parallel sort to merge several runs (2, 3, 4 threads).
    std::vector<int> order(600 * 600);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), random);
    for (const int k : order) {
        add(r, {float(k / 600) + jitter(random), float(k % 600) + jitter(random), 7.0f + jitter(random)}, {0, 0, 1});
        values.push_back(0.8f + noise(random));
    }
    auto spread = [](const std::vector<float>& v) {
        double mean = 0, square = 0;
        for (float x : v) mean += x;
        mean /= double(v.size());
        for (float x : v) square += (x - mean) * (x - mean);
        return std::sqrt(square / double(v.size()));
    };
    std::vector<float> one = values, two = values;
    SkydomeSmoothing options;
    options.radius = 2.0;
    options.threads = 1;
    ASSERT_TRUE(smoothSkydome(r, one, options));
    for (const unsigned threads : {2u, 3u, 4u}) {
        two = values;
        options.threads = threads;
        ASSERT_TRUE(smoothSkydome(r, two, options));
        EXPECT_EQ(one, two) << threads << " threads";
    }
    EXPECT_LT(spread(one), spread(values) / 2.0);
}

TEST(SkydomeSmoothing, EqualsABruteForceSearchOnRandomPositionsAndRadii)
{
    // Positions and radii that are not binary fractions, so that the bins' edges round (a margin of one bin
    // below the lowest receiver could round to a coordinate 0, whose lower neighbours' keys would wrap), and
    // values and normals at random: every receiver against every other one, in double.
    std::mt19937 random(11);
    for (const double radius : {0.1, 0.37, 1.3, 0.0715}) {
        std::uniform_real_distribution<float> where(0.9f, 4.1f), normal(-1.0f, 1.0f), value(0.0f, 1.0f);
        AoReceivers r;
        std::vector<float> values;
        for (int i = 0; i < 1500; ++i) {
            // Half on a plane z = 1.0 (the lowest: its bins sit on the margin), half anywhere.
            const float z = i % 2 == 0 ? 1.0f : where(random);
            std::array<float, 3> n{normal(random), normal(random), normal(random)};
            const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (length < 0.1f) n = {0, 0, 1};
            else n = {n[0] / length, n[1] / length, n[2] / length};
            if (i % 2 == 0) n = {0.1f * normal(random), 0.1f * normal(random), 1.0f};
            add(r, {where(random) / 3.0f + 1.0f, where(random) / 3.0f + 1.0f, z}, n);
            values.push_back(value(random));
        }
        SkydomeSmoothing options;
        options.radius = radius;
        std::vector<float> got = values;
        ASSERT_TRUE(smoothSkydome(r, got, options));
        std::size_t changed = 0;
        for (std::size_t i = 0; i < r.size(); ++i) {
            double sum = 0.0, weights = 0.0;
            const auto& p = r.positions[i];
            const auto& m = r.normals[i];
            for (std::size_t j = 0; j < r.size(); ++j) {
                const auto& q = r.positions[j];
                const auto& o = r.normals[j];
                const float dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2];
                const float d2 = dx * dx + dy * dy + dz * dz;
                const float r2 = float(radius * radius);
                if (!(d2 < r2) || !(std::abs(m[0] * o[0] + m[1] * o[1] + m[2] * o[2]) >= options.minCos)) continue;
                const double t = 1.0 - double(d2) * double(1.0f / r2);
                sum += t * t * values[j];
                weights += t * t;
            }
            const double expected = weights > 0.0 ? sum / weights : values[i];
            ASSERT_NEAR(got[i], expected, 2e-5) << "receiver " << i << ", radius " << radius;
            changed += got[i] != values[i];
        }
        EXPECT_GT(changed, r.size() / 4) << radius; // neighbours were found
    }
}

TEST(SkydomeSmoothing, RadiusZeroAndCancelLeaveTheValuesAlone)
{
    AoReceivers r;
    add(r, {0.0f, 0.0f, 0.0f}, {0, 0, 1});
    add(r, {0.5f, 0.0f, 0.0f}, {0, 0, 1});
    std::vector<float> values{0.1f, 0.9f};
    SkydomeSmoothing options;
    ASSERT_TRUE(smoothSkydome(r, values, options)); // radius 0
    EXPECT_EQ(values, (std::vector<float>{0.1f, 0.9f}));
    options.radius = 1.0;
    CancelAtOnce cancel;
    const auto status = smoothSkydome(r, values, options, &cancel);
    ASSERT_FALSE(status);
    EXPECT_EQ(status.error().code, stylos::core::ErrorCode::Cancelled);
    EXPECT_EQ(values, (std::vector<float>{0.1f, 0.9f}));
}

TEST(SkydomeSmoothing, ACancelHalfWayLeavesTheValuesAsTheyWere)
{
    // 40 × 40 receivers on a plane, values alternating: the smoothing changes every one. One thread, 256 bins
    // a chunk: the first chunks are smoothed (their results written) before the cancel.
    AoReceivers r;
    std::vector<float> values;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            add(r, {float(i), float(j), 0.0f}, {0, 0, 1});
            values.push_back((i + j) % 2 == 0 ? 0.25f : 0.75f);
        }
    SkydomeSmoothing options;
    options.radius = 1.5;
    options.threads = 1;
    std::vector<float> whole = values;
    ASSERT_TRUE(smoothSkydome(r, whole, options));
    for (std::size_t i = 0; i < values.size(); ++i) ASSERT_NE(whole[i], values[i]) << i;
    for (const int checks : {1, 2}) {
        std::vector<float> got = values;
        CancelAfter cancel(checks);
        const auto status = smoothSkydome(r, got, options, &cancel);
        ASSERT_FALSE(status) << checks;
        EXPECT_EQ(status.error().code, stylos::core::ErrorCode::Cancelled);
        EXPECT_EQ(got, values) << "cancelled after " << checks << " chunks";
    }
}
