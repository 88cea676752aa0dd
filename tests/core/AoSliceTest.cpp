// The Slices kernel (the paper's method, sparse): hand-checked tiny configurations run through the kernel
// for one chosen direction whose drift per slice is an exact ½ (the 9-part split: centre 1, sides ¼,
// corners 1/16 of a widened footprint), an occluder above a cell, the bias, a slab and a hole in it,
// partial opacity, no blur as a shadow travels; through computeAmbientOcclusion: a flat floor (and a 45°
// plane) see the whole sky in front of them, cancel, the same bits for the same thread count, and
// agreement with the brute-force reference on a generated drum.
#include "../../core/src/ao/SliceKernel.h"
#include "stylos/core/ao/AmbientOcclusion.h"
#include "stylos/core/ao/ReferenceAo.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/synth/SyntheticStream.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numeric>

using namespace stylos::core;
using namespace stylos::core::ao;
using Coords = std::array<std::uint32_t, 3>;

namespace {

constexpr std::array<float, 3> Up{0.0f, 0.0f, 1.0f};
constexpr std::array<float, 3> Down{0.0f, 0.0f, -1.0f};

struct Builder {
    AoCells cells;
    Builder() { cells.level = 8; }
    Builder& add(Coords c, std::array<float, 3> normal = Up, float opacity = 1.0f)
    {
        cells.coords.push_back(c);
        cells.normals.push_back(normal);
        cells.opacity.push_back(opacity);
        return *this;
    }
    /** A square slab of side @p side at height @p z, less the cells in @p holes. */
    Builder& slab(std::uint32_t side, std::uint32_t z, std::array<float, 3> normal, std::vector<Coords> holes = {})
    {
        for (std::uint32_t y = 0; y < side; ++y)
            for (std::uint32_t x = 0; x < side; ++x)
                if (std::find(holes.begin(), holes.end(), Coords{x, y, z}) == holes.end()) add({x, y, z}, normal);
        return *this;
    }
    AoCells done()
    {
        cells.leafBegin.resize(cells.size() + 1);
        std::iota(cells.leafBegin.begin(), cells.leafBegin.end(), 0);
        return cells;
    }
};

/** A direction whose drift per slice along z is exactly (ax, ay): d ∝ (ax, ay, 1), float exact ratios. */
std::array<float, 3> drifting(float ax, float ay)
{
    const float s = 1.0f / std::sqrt(ax * ax + ay * ay + 1.0f);
    return {ax * s, ay * s, s};
}

/** Visibility of every cell toward @p d through one Slices kernel: seen / total, −1 where total is 0. */
std::map<Coords, float> visibility(const AoCells& cells, std::array<float, 3> d, double bias = 1.0,
                                   detail::SliceTuning tuning = {})
{
    AoOptions options;
    options.bias = bias;
    const detail::PreparedCells prepared = detail::prepareCells(cells);
    detail::SliceKernel kernel(prepared, options, tuning);
    detail::Accumulator sums(prepared.size());
    kernel.run(d, sums);
    std::map<Coords, float> v;
    for (std::size_t i = 0; i < cells.size(); ++i)
        v[cells.coords[i]] = sums.total[i] > 0.0f ? sums.seen[i] / sums.total[i] : -1.0f;
    return v;
}

float at(const std::map<Coords, float>& v, std::uint32_t x, std::uint32_t y, std::uint32_t z)
{
    return v.at(Coords{x, y, z});
}

} // namespace

TEST(AoSlices, MaskComposesByStepAndRemembersBursts)
{
    // A box of 2^20 × 2^20 mask cells takes the hash directory; 2^10 × 2^10 the dense one.
    for (const int side : {1 << 10, 1 << 20}) {
        detail::SliceMask mask;
        mask.reset(side, side, 2);
        const int x = side - 1, y = side - 2;
        EXPECT_EQ(mask.visible(x, y, 0), 1.0f);
        mask.compose(x, y, 0.5f, 3);  // a burst begins at step 3
        mask.compose(x, y, 0.5f, 5);  // 2 steps later: the same burst
        mask.compose(0, 0, 2.0f, 5);  // coverage over 1 is all
        EXPECT_EQ(mask.tilesUsed(), 2);
        EXPECT_EQ(mask.visible(x, y, 6), 0.25f); // both steps count
        EXPECT_EQ(mask.visible(x, y, 4), 0.25f); // the burst began before the window: it counts whole
        EXPECT_EQ(mask.visible(x, y, 3), 1.0f);  // it began inside the window: T before it
        EXPECT_EQ(mask.visible(0, 0, 9), 0.0f);
        mask.compose(x, y, 0.5f, 8); // 3 steps later: a new burst
        EXPECT_EQ(mask.visible(x, y, 9), 0.125f);
        EXPECT_EQ(mask.visible(x, y, 7), 0.25f);
        mask.reset(side, side, 2);
        EXPECT_EQ(mask.visible(x, y, 9), 1.0f);
        EXPECT_EQ(mask.tilesUsed(), 0);
    }
}

TEST(AoSlices, OccluderTwoAboveHidesTheCellBelowAlongTheAxis)
{
    const AoCells cells = Builder().add({1, 1, 0}).add({1, 1, 2}).add({0, 1, 0}).done();
    auto v = visibility(cells, Up);
    EXPECT_EQ(at(v, 1, 1, 0), 0.0f);
    EXPECT_EQ(at(v, 0, 1, 0), 1.0f);
    EXPECT_EQ(at(v, 1, 1, 2), 1.0f);
    v = visibility(cells, Down); // behind every normal: no weight
    EXPECT_EQ(at(v, 1, 1, 0), -1.0f);
    EXPECT_EQ(at(v, 1, 1, 2), -1.0f);
}

TEST(AoSlices, BiasSparesAnOccluderOneEdgeAbove)
{
    // (c_j − c_i)·n = 1: not more than bias 1, so not an occluder; with bias ½ it is. The rule reads the
    // receiver's normal only: the occluder's does not matter.
    for (const auto normal : {Up, Down}) {
        const AoCells cells = Builder().add({0, 0, 0}).add({0, 0, 1}, normal).done();
        EXPECT_EQ(at(visibility(cells, Up, 1.0), 0, 0, 0), 1.0f);
        EXPECT_EQ(at(visibility(cells, Up, 0.5), 0, 0, 0), 0.0f);
    }
    // A tilted receiver (n·d = 0.6) and an occluder two slices up, 1.2 above its tangent plane.
    const AoCells tilted = Builder().add({0, 0, 0}, {0.8f, 0.0f, 0.6f}).add({0, 0, 2}).done();
    EXPECT_EQ(at(visibility(tilted, Up, 1.0), 0, 0, 0), 0.0f);
    EXPECT_EQ(at(visibility(tilted, Up, 1.3), 0, 0, 0), 1.0f);  // 1.2 is not more than 1.3
}

TEST(AoSlices, SquaresSplitOverTheMaskCellsTheyOverlap)
{
    // Drift ½ on x and y per slice; the occluder at (2, 2, 2) is at step 1 (the cell at z = 3, far off,
    // makes it so): its square lies at [2.5, 3.5]² in the light's frame, ¼ on each of the 4 mask cells it
    // overlaps (of the 3 × 3 around it that a drift in [−1, 1]² may reach). The cells at z = 0 (step 3)
    // read the ray through their centre, column x + 2.
    Builder b;
    b.add({2, 2, 2}, Down).add({12, 12, 3}, Down);
    for (std::uint32_t y = 0; y < 4; ++y)
        for (std::uint32_t x = 0; x < 4; ++x) b.add({x, y, 0});
    const auto v = visibility(b.done(), drifting(0.5f, 0.5f), 0.0);
    for (std::uint32_t y = 0; y < 4; ++y)
        for (std::uint32_t x = 0; x < 4; ++x)
            EXPECT_EQ(at(v, x, y, 0), (x == 0 || x == 1) && (y == 0 || y == 1) ? 0.75f : 1.0f) << x << " " << y;
}

TEST(AoSlices, ShadowsDoNotBlurAsTheyTravel)
{
    // Footprints read by area (the paper's split, done once): drift ½ on x. One slice below the
    // occluder, the cells straddle its column half and half; two slices below the drift is a whole
    // cell and the shadow falls on one cell exactly (a per-slice resampling would spread it ¼ ½ ¼).
    const detail::SliceTuning byArea{false, 0.0, 2};
    Builder one, two;
    one.add({2, 0, 1}, Down);
    two.add({2, 0, 2}, Down);
    for (std::uint32_t x = 0; x < 4; ++x) {
        one.add({x, 0, 0});
        two.add({x, 0, 0});
    }
    const auto v1 = visibility(one.done(), drifting(0.5f, 0.0f), 0.0, byArea);
    const auto v2 = visibility(two.done(), drifting(0.5f, 0.0f), 0.0, byArea);
    const float expected1[] = {1.0f, 0.5f, 0.5f, 1.0f}, expected2[] = {1.0f, 0.0f, 1.0f, 1.0f};
    for (std::uint32_t x = 0; x < 4; ++x) {
        EXPECT_EQ(at(v1, x, 0, 0), expected1[x]) << x;
        EXPECT_EQ(at(v2, x, 0, 0), expected2[x]) << x;
    }
}

TEST(AoSlices, SlabAboveAFloor)
{
    Builder b;
    b.slab(5, 3, Down);
    for (std::uint32_t y = 0; y < 7; ++y)
        for (std::uint32_t x = 0; x < 7; ++x) b.add({x, y, 0});
    const AoCells cells = b.done();
    auto v = visibility(cells, Up);
    for (std::uint32_t y = 0; y < 7; ++y)
        for (std::uint32_t x = 0; x < 7; ++x) EXPECT_EQ(at(v, x, y, 0), x < 5 && y < 5 ? 0.0f : 1.0f);
    // Drift ½ on both axes, three slices down: the ray of cell (x, y) crosses the slab's slice at
    // (x + 2, y + 2) (its centre + 1½), inside the slab for x, y ≤ 2.
    v = visibility(cells, drifting(0.5f, 0.5f));
    for (std::uint32_t y = 0; y < 7; ++y)
        for (std::uint32_t x = 0; x < 7; ++x) EXPECT_EQ(at(v, x, y, 0), x <= 2 && y <= 2 ? 0.0f : 1.0f);
}

TEST(AoSlices, HoleInTheSlab)
{
    Builder b;
    b.slab(5, 2, Down, {{2, 2, 2}});
    for (std::uint32_t x = 0; x < 5; ++x) b.add({x, 2, 0}).add({x, 1, 0});
    AoCells cells = b.done();
    auto v = visibility(cells, Up);
    EXPECT_EQ(at(v, 2, 2, 0), 1.0f);
    EXPECT_EQ(at(v, 1, 2, 0), 0.0f);
    EXPECT_EQ(at(v, 2, 1, 0), 0.0f);
    // Drift ½ on x, two slices: the ray of (1, 2, 0) crosses the slab through the hole's centre.
    v = visibility(cells, drifting(0.5f, 0.0f));
    const float row2[] = {0.0f, 1.0f, 0.0f, 0.0f, 1.0f};
    for (std::uint32_t x = 0; x < 5; ++x) {
        EXPECT_EQ(at(v, x, 2, 0), row2[x]) << x;
        EXPECT_EQ(at(v, x, 1, 0), x <= 3 ? 0.0f : 1.0f) << x; // no hole in row 1
    }
    // With the slab one slice further from the sky (a far cell at z = 3 comes first), its squares lie
    // half a column off the mask: the hole's column keeps half of each neighbour, and the two cells
    // whose rays straddle the hole each get half the light through it.
    cells = Builder(b).add({20, 0, 3}, Down).done();
    v = visibility(cells, drifting(0.5f, 0.0f));
    const float halfOff[] = {0.5f, 0.5f, 0.0f, 0.5f, 1.0f};
    for (std::uint32_t x = 0; x < 5; ++x) EXPECT_EQ(at(v, x, 2, 0), halfOff[x]) << x;
}

TEST(AoSlices, PartialOpacityCompounds)
{
    for (const float alpha : {0.5f, 0.25f}) {
        const AoCells cells = Builder()
                                  .add({0, 0, 0})
                                  .add({0, 0, 2}, Down, alpha)
                                  .add({0, 0, 3}, Down, alpha)
                                  .add({0, 0, 4}, Down, alpha)
                                  .done();
        EXPECT_FLOAT_EQ(at(visibility(cells, Up), 0, 0, 0), std::pow(1.0f - alpha, 3.0f)) << alpha;
    }
}

TEST(AoSlices, FlatSurfacesSeeTheWholeSkyInFrontOfThem)
{
    AoOptions options;
    options.method = AoMethod::Slices;
    options.directions = 256;
    options.threads = 2;
    Builder floor;
    for (std::uint32_t y = 0; y < 16; ++y)
        for (std::uint32_t x = 0; x < 16; ++x) floor.add({x, y, 3});
    auto values = computeAmbientOcclusion(floor.done(), options);
    ASSERT_TRUE(values.ok());
    for (const float v : values.value()) EXPECT_EQ(v, 1.0f);

    // A 45° staircase x = z facing (−1, 0, 1)/√2: its squares reach 0.7 edge from the plane and the mask's
    // blur up to 1.4 more along a diagonal, past the tolerance (bias + ¾) at the grazing directions
    // (n·d < 0.1) where the burst starts early: 2 of the 256 directions lose a little on a few cells.
    Builder ramp;
    const float h = float(std::sqrt(0.5));
    for (std::uint32_t k = 0; k < 16; ++k)
        for (std::uint32_t y = 0; y < 16; ++y) ramp.add({k, y, k}, {-h, 0.0f, h});
    values = computeAmbientOcclusion(ramp.done(), options);
    ASSERT_TRUE(values.ok());
    double sum = 0.0;
    for (const float v : values.value()) {
        EXPECT_GE(v, 0.9995f);
        sum += v;
    }
    EXPECT_GE(sum / double(values->size()), 0.99995);
}

TEST(AoSlices, CancelAndThreads)
{
    Builder b;
    b.slab(12, 6, Down, {{3, 4, 6}, {5, 5, 6}, {6, 5, 6}});
    for (std::uint32_t y = 0; y < 14; ++y)
        for (std::uint32_t x = 0; x < 14; ++x) b.add({x, y, std::uint32_t((x * y) % 3)}, {0.3f, -0.2f, 0.93f}, 0.7f);
    const AoCells cells = b.done();
    AoOptions options;
    options.method = AoMethod::Slices;
    options.directions = 100;
    options.cosineWeighted = true;
    options.threads = 2;
    const auto first = computeAmbientOcclusion(cells, options);
    const auto second = computeAmbientOcclusion(cells, options);
    ASSERT_TRUE(first.ok() && second.ok());
    EXPECT_EQ(first.value(), second.value());
    options.threads = 1;
    const auto single = computeAmbientOcclusion(cells, options);
    ASSERT_TRUE(single.ok());
    for (std::size_t i = 0; i < cells.size(); ++i) EXPECT_NEAR(single.value()[i], first.value()[i], 1e-5);

    SilentProgress progress;
    progress.cancel();
    const auto cancelled = computeAmbientOcclusion(cells, options, &progress);
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
}

TEST(AoSlices, AgreesWithTheReferenceOnAGeneratedDrum)
{
    const stylos::test::TempDir dir;
    // 48 flutes 2 cm deep (4 cells at level 7, 9 mm each), so that the level resolves them.
    synth::SyntheticStreamOptions stream;
    stream.points = 200'000;
    stream.grooveDepth = 0.02;
    octree::BuildOptions build;
    build.depth = 7;
    const octree::PointSourceFactory open = [stream] { return synth::openSyntheticStream(stream); };
    ASSERT_TRUE(octree::buildOctree(open, dir / "drum.poct", build).ok());
    const auto tree = octree::PackedOctree::open(dir / "drum.poct");
    ASSERT_TRUE(tree.ok());
    const auto cells = cellsAtLevel(tree.value(), 7);
    ASSERT_TRUE(cells.ok());

    AoOptions options;
    options.method = AoMethod::Slices;
    options.directions = 64;
    options.threads = 2;
    const auto values = computeAmbientOcclusion(cells.value(), options);
    ASSERT_TRUE(values.ok());
    std::vector<std::size_t> samples;
    for (std::size_t i = 0; i < cells->size(); i += 9) samples.push_back(i);
    const auto reference = referenceAmbientOcclusion(cells.value(), samples, options);
    ASSERT_TRUE(reference.ok());

    double error = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    const double n = double(samples.size());
    for (std::size_t j = 0; j < samples.size(); ++j) {
        const double x = values.value()[samples[j]], y = reference.value()[j];
        error += std::abs(x - y);
        sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y;
    }
    const double correlation =
        (sxy / n - sx * sy / (n * n)) / std::sqrt((sxx / n - sx * sx / (n * n)) * (syy / n - sy * sy / (n * n)));
    EXPECT_LE(error / n, 0.04);        // measured 0.024
    EXPECT_GE(correlation, 0.93);      // measured 0.965
}
