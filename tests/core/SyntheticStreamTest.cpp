// SyntheticStream: the procedural drum — determinism, offsets, exact counts, points on the surface with
// outward unit normals, areas against independent formulas, uniformity by area, the scan-like order,
// noise, and errors for bad options.
#include "stylos/core/synth/SyntheticStream.h"

#include "stylos/core/synth/DrumShape.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

using namespace stylos::core;
using synth::SyntheticStreamOptions;

namespace {

constexpr double kPi = std::numbers::pi;

io::PointBatch readStream(const SyntheticStreamOptions& o, std::size_t batch = 10000)
{
    auto reader = synth::openSyntheticStream(o);
    EXPECT_TRUE(reader.ok()) << (reader.ok() ? "" : reader.error().message);
    if (!reader.ok()) return {};
    auto all = stylos::test::readAllPoints(**reader, batch);
    EXPECT_TRUE(all.ok());
    return all.ok() ? std::move(*all) : io::PointBatch{};
}

bool sameBytes(const io::PointBatch& a, const io::PointBatch& b)
{
    return a.positions.size() == b.positions.size() && a.normals.size() == b.normals.size() &&
           std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(double)) == 0 &&
           std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(float)) == 0;
}

/** The flute outline of DrumShape with the same parameters (groove 0 at azimuth 0), as a reference. */
std::unique_ptr<synth::DrumShape> referenceShape(const SyntheticStreamOptions& o)
{
    synth::DrumParameters p;
    p.radius = o.radius;
    p.height = o.height;
    p.grooves = o.grooves;
    p.grooveDepth = o.grooveDepth;
    p.filletFraction = o.filletFraction;
    p.groovePhase = 0.0;
    p.clawBand = p.broken = p.anathyrosis = false;
    return std::make_unique<synth::DrumShape>(p);
}

/** Checks that every point lies on the drum and its normal is unit and points outward. */
void expectOnSurface(const io::PointBatch& b, const SyntheticStreamOptions& o, std::uint64_t& bedPoints)
{
    const auto shape = referenceShape(o);
    bedPoints = 0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        const double x = b.positions[3 * i], y = b.positions[3 * i + 1], z = b.positions[3 * i + 2];
        const float nx = b.normals[3 * i], ny = b.normals[3 * i + 1], nz = b.normals[3 * i + 2];
        ASSERT_NEAR(std::sqrt(nx * nx + ny * ny + nz * nz), 1.0, 1e-6) << i;
        const double theta = std::atan2(y, x), rho = std::hypot(x, y);
        if (nz != 0) {
            ++bedPoints;
            ASSERT_EQ(std::fabs(nz), 1.0f) << i;
            ASSERT_EQ(z, nz > 0 ? o.height : 0.0) << i;
            ASSERT_LE(rho, shape->fluteRadius(theta) + 1e-12) << i;
            continue;
        }
        ASSERT_GE(z, 0.0);
        ASSERT_LE(z, o.height);
        ASSERT_NEAR(rho, shape->fluteRadius(theta), 1e-12) << i;
        // Outward: a step along the normal leaves the drum, a step against it enters.
        const double e = 1e-5;
        const double xo = x + e * nx, yo = y + e * ny, xi = x - e * nx, yi = y - e * ny;
        ASSERT_GT(std::hypot(xo, yo), shape->fluteRadius(std::atan2(yo, xo))) << i;
        ASSERT_LT(std::hypot(xi, yi), shape->fluteRadius(std::atan2(yi, xi))) << i;
    }
}

SyntheticStreamOptions small(std::uint64_t points, bool shuffled = true)
{
    SyntheticStreamOptions o;
    o.points = points;
    o.seed = 11;
    o.shuffled = shuffled;
    return o;
}

} // namespace

TEST(SyntheticStream, SameOptionsSameBytesOtherSeedOtherPoints)
{
    const auto a = readStream(small(50000)), b = readStream(small(50000), 777);
    EXPECT_TRUE(sameBytes(a, b));
    auto other = small(50000);
    other.seed = 12;
    EXPECT_FALSE(sameBytes(a, readStream(other)));
    // Ordered too, and the two orders differ.
    const auto o1 = readStream(small(50000, false)), o2 = readStream(small(50000, false), 4096);
    EXPECT_TRUE(sameBytes(o1, o2));
    EXPECT_FALSE(sameBytes(a, o1));
}

TEST(SyntheticStream, HeaderCountsAndOffsets)
{
    auto o = small(123457);
    auto reader = synth::openSyntheticStream(o);
    ASSERT_TRUE(reader.ok());
    const auto& h = (*reader)->header();
    EXPECT_EQ(h.format, "synthetic-drum");
    EXPECT_EQ(h.declaredPoints, 123457u);
    EXPECT_TRUE(h.schema.hasNormals);
    EXPECT_FALSE(h.schema.hasColors);
    EXPECT_EQ((*reader)->fileBytes(), 123457u * 36);
    io::PointBatch batch;
    std::uint64_t total = 0;
    for (;;) {
        auto got = (*reader)->read(batch, 65536);
        ASSERT_TRUE(got.ok());
        if (*got == 0) break;
        EXPECT_EQ(batch.size(), *got);
        total += *got;
    }
    EXPECT_EQ(total, 123457u);
    EXPECT_EQ((*reader)->pointsRead(), 123457u);
    EXPECT_EQ((*reader)->bytesConsumed(), (*reader)->fileBytes());
    EXPECT_EQ((*reader)->read(batch, 10).value(), 0u); // stays at the end

    for (bool shuffled : {true, false}) {
        // Opening at an offset yields exactly the tail of the whole stream.
        auto whole = small(20000, shuffled);
        const auto all = readStream(whole);
        whole.offset = 12345;
        const auto tail = readStream(whole, 999);
        ASSERT_EQ(tail.size(), 20000u - 12345u);
        EXPECT_EQ(std::memcmp(tail.positions.data(), all.positions.data() + 3 * 12345,
                              tail.positions.size() * sizeof(double)), 0);
        EXPECT_EQ(std::memcmp(tail.normals.data(), all.normals.data() + 3 * 12345,
                              tail.normals.size() * sizeof(float)), 0);
    }
}

TEST(SyntheticStream, PointsLieOnTheSurfaceWithOutwardNormals)
{
    for (bool shuffled : {true, false}) {
        const auto o = small(200000, shuffled);
        const auto b = readStream(o);
        ASSERT_EQ(b.size(), 200000u);
        std::uint64_t bed = 0;
        expectOnSurface(b, o, bed);
        EXPECT_GT(bed, 0u);
        // Bounds: within the cylinder, and reaching its extremes.
        double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
        for (std::size_t i = 0; i < b.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                lo[c] = std::min(lo[c], b.positions[3 * i + c]);
                hi[c] = std::max(hi[c], b.positions[3 * i + c]);
            }
        for (int c = 0; c < 2; ++c) {
            EXPECT_GE(lo[c], -o.radius);
            EXPECT_LE(hi[c], o.radius);
            EXPECT_LT(lo[c], -o.radius + 1e-3);
            EXPECT_GT(hi[c], o.radius - 1e-3);
        }
        EXPECT_EQ(lo[2], 0.0);
        EXPECT_EQ(hi[2], o.height);
    }
    // Other shapes: a plain cylinder, sharp arrises, few deep flutes.
    for (auto [grooves, depth, fillet] : {std::tuple{0, 0.0, 0.1}, std::tuple{20, 0.01, 0.0}, std::tuple{3, 0.1, 0.5}}) {
        auto o = small(30000);
        o.grooves = grooves;
        o.grooveDepth = depth;
        o.filletFraction = fillet;
        std::uint64_t bed = 0;
        expectOnSurface(readStream(o), o, bed);
    }
}

TEST(SyntheticStream, AreasMatchIndependentFormulas)
{
    const SyntheticStreamOptions o;
    auto areas = synth::syntheticDrumAreas(o);
    ASSERT_TRUE(areas.ok());
    // Perimeter and polar area of the outline by numerical integration of DrumShape's flute radius.
    const auto shape = referenceShape(o);
    const int steps = 2'000'000;
    double perimeter = 0, area = 0;
    double prevX = shape->fluteRadius(0), prevY = 0;
    for (int s = 1; s <= steps; ++s) {
        const double t = 2 * kPi * s / steps, r = shape->fluteRadius(t);
        const double x = r * std::cos(t), y = r * std::sin(t);
        perimeter += std::hypot(x - prevX, y - prevY);
        area += 0.5 * (prevX * y - prevY * x);
        prevX = x;
        prevY = y;
    }
    // (The polyline cuts the 96 corners between flutes and fillets: about 3e-8 m each.)
    EXPECT_NEAR(areas->perimeter, perimeter, 1e-5);
    EXPECT_NEAR(areas->bed, area, 1e-7);
    EXPECT_NEAR(areas->lateral, perimeter * o.height, 0.5e-5);
    EXPECT_LT(areas->bed, kPi * o.radius * o.radius);
    auto plain = o;
    plain.grooves = 0;
    auto cylinder = synth::syntheticDrumAreas(plain);
    ASSERT_TRUE(cylinder.ok());
    EXPECT_NEAR(cylinder->bed, kPi * o.radius * o.radius, 1e-12);
    EXPECT_NEAR(cylinder->lateral, 2 * kPi * o.radius * o.height, 1e-12);
}

TEST(SyntheticStream, UniformByArea)
{
    // Shuffled: the share of each surface and, on the bed faces, of the inner half radius and of each
    // eighth of the flute pitch (phase of the azimuth within a period, gathered over all the flutes:
    // this checks the inversion of a flute's swept area).
    const auto o = small(1'000'000);
    const auto b = readStream(o, 65536);
    const auto areas = synth::syntheticDrumAreas(o).value();
    const double total = areas.lateral + 2 * areas.bed;
    const auto shape = referenceShape(o);
    constexpr int phases = 8;
    const double pitch = 2 * kPi / o.grooves;
    std::vector<double> phaseArea(phases, 0.0), phaseLength(phases, 0.0);
    for (int w = 0; w < phases; ++w)
        for (int s = 0; s < 20000; ++s) {
            const double t0 = pitch * ((w + s / 20000.0) / phases - 0.5), t1 = t0 + pitch / phases / 20000;
            const double r0 = shape->fluteRadius(t0), r1 = shape->fluteRadius(t1), tm = 0.5 * (t0 + t1);
            phaseArea[w] += o.grooves * 0.5 * std::pow(shape->fluteRadius(tm), 2) * (t1 - t0);
            phaseLength[w] += o.grooves * std::hypot(r1 * std::cos(t1) - r0 * std::cos(t0), r1 * std::sin(t1) - r0 * std::sin(t0));
        }
    std::vector<std::uint64_t> phaseCount(phases, 0), lateralPhaseCount(phases, 0);
    auto phaseOf = [&](double x, double y) {
        const double phase = std::remainder(std::atan2(y, x), pitch) / pitch + 0.5; // [0, 1]
        return std::min<std::size_t>(phases - 1, static_cast<std::size_t>(phase * phases));
    };
    std::uint64_t bed = 0, inner = 0, lowHalf = 0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        const double x = b.positions[3 * i], y = b.positions[3 * i + 1];
        if (b.normals[3 * i + 2] == 0) {
            lowHalf += b.positions[3 * i + 2] < 0.5 * o.height;
            ++lateralPhaseCount[phaseOf(x, y)];
            continue;
        }
        ++bed;
        inner += std::hypot(x, y) < 0.5 * o.radius;
        ++phaseCount[phaseOf(x, y)];
    }
    const double n = static_cast<double>(b.size());
    auto expectShare = [](double count, double trials, double p, const char* what) {
        EXPECT_NEAR(count, trials * p, 5 * std::sqrt(trials * p * (1 - p)) + 1) << what;
    };
    expectShare(static_cast<double>(bed), n, 2 * areas.bed / total, "bed faces");
    expectShare(static_cast<double>(lowHalf), n - bed, 0.5, "lower half of the lateral surface");
    expectShare(static_cast<double>(inner), static_cast<double>(bed), kPi * o.radius * o.radius / 4 / areas.bed,
                "inner half radius");
    for (int w = 0; w < phases; ++w) {
        expectShare(static_cast<double>(phaseCount[w]), static_cast<double>(bed), phaseArea[w] / areas.bed, "bed phase");
        expectShare(static_cast<double>(lateralPhaseCount[w]), n - bed, phaseLength[w] / areas.perimeter, "lateral phase");
    }
}

TEST(SyntheticStream, OrderedStreamSweepsByAzimuth)
{
    const auto o = small(300000, false);
    const auto b = readStream(o);
    const auto areas = synth::syntheticDrumAreas(o).value();
    const double total = areas.lateral + 2 * areas.bed;
    const auto bottom = static_cast<std::uint64_t>(std::llround(300000 * areas.bed / total));
    const auto lateral = static_cast<std::uint64_t>(std::llround(300000 * areas.lateral / total));
    double sweep = 0, step = 0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        const float nz = b.normals[3 * i + 2];
        ASSERT_EQ(nz, i < bottom ? -1.0f : i < bottom + lateral ? 0.0f : 1.0f) << i;
        if (i == 0) continue;
        step += std::hypot(b.positions[3 * i] - b.positions[3 * i - 3], b.positions[3 * i + 1] - b.positions[3 * i - 2]);
        if (i > bottom && i < bottom + lateral) {
            // Azimuth never goes back along the lateral surface, and sweeps one full turn.
            const double t1 = std::atan2(b.positions[3 * i + 1], b.positions[3 * i]);
            const double t0 = std::atan2(b.positions[3 * i - 2], b.positions[3 * i - 3]);
            const double d = std::remainder(t1 - t0, 2 * kPi);
            ASSERT_GE(d, -1e-12) << i;
            sweep += d;
        }
    }
    EXPECT_NEAR(sweep, 2 * kPi, 0.01);
    // Coherent: consecutive points are close (a column is about a sample spacing wide).
    EXPECT_LT(step / static_cast<double>(b.size()), 0.05 * o.radius);
}

TEST(SyntheticStream, NoiseMovesPointsAlongTheirNormals)
{
    auto o = small(100000);
    const auto clean = readStream(o);
    o.noise = 0.001;
    const auto noisy = readStream(o);
    ASSERT_EQ(noisy.size(), clean.size());
    EXPECT_EQ(noisy.normals, clean.normals);
    double sum = 0, sum2 = 0;
    for (std::size_t i = 0; i < clean.size(); ++i) {
        double along = 0, off = 0;
        for (int c = 0; c < 3; ++c) {
            const double d = noisy.positions[3 * i + c] - clean.positions[3 * i + c];
            along += d * clean.normals[3 * i + c];
            off += d * d;
        }
        EXPECT_NEAR(off, along * along, 1e-6 * off) << i; // only along the (float) normal
        sum += along;
        sum2 += along * along;
    }
    const double n = static_cast<double>(clean.size());
    EXPECT_NEAR(sum / n, 0.0, 5 * 0.001 / std::sqrt(n));
    EXPECT_NEAR(std::sqrt(sum2 / n), 0.001, 0.00002);
}

TEST(SyntheticStream, BadOptionsAreRefused)
{
    std::vector<SyntheticStreamOptions> bad(10, small(1000));
    bad[0].points = 0;
    bad[1].offset = 1001;
    bad[2].radius = 0;
    bad[3].height = std::nan("");
    bad[4].noise = -1e-3;
    bad[5].grooves = 2;
    bad[6].grooveDepth = 0.5;      // deeper than a quarter of the radius
    bad[7].grooveDepth = 0.0001;   // shallower than a flat flute
    bad[8].filletFraction = 1.0;
    bad[9].radius = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < bad.size(); ++i) {
        auto r = synth::openSyntheticStream(bad[i]);
        ASSERT_FALSE(r.ok()) << i;
        EXPECT_EQ(r.error().code, ErrorCode::InvalidArgument) << i;
        EXPECT_EQ(r.error().message.rfind("synthetic-drum: ", 0), 0u) << r.error().message;
    }
    auto end = small(1000);
    end.offset = 1000; // an empty tail is allowed
    auto r = synth::openSyntheticStream(end);
    ASSERT_TRUE(r.ok());
    io::PointBatch batch;
    EXPECT_EQ((*r)->read(batch, 100).value(), 0u);
}
