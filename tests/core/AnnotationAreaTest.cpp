// Area per class from the cells (crossing density at the area level), measured against analytic areas on a
// generated plain drum: the painted rectangle and the whole object. The bounds are the measured errors
// (docs/annotation.md) with a little margin.
#include "AnnotationTestSupport.h"

#include "stylos/core/annotation/LabelArea.h"
#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/synth/DrumShape.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numeric>

using namespace stylos::core::annotation;
namespace oct = stylos::core::octree;

TEST(AnnotationArea, MeasureClassesCountsAndSums)
{
    const std::vector<std::uint8_t> labels{0, 2, 2, 255};
    const std::vector<double> areas{1.0, 0.25, 0.5, 2.0};
    const auto m = measureClasses(labels, areas);
    ASSERT_EQ(m.size(), 256u);
    EXPECT_EQ(m[2].cells, 2u);
    EXPECT_DOUBLE_EQ(m[2].areaM2, 0.75);
    EXPECT_EQ(m[255].cells, 1u);
    EXPECT_EQ(m[0].cells, 1u);
    EXPECT_EQ(m[1].cells, 0u);
}

TEST(AnnotationArea, MatchesTheAnalyticAreaOfThePatchAndTheDrum)
{
    const auto& d = stylos::test::annotatedDrum();
    const double truePatch = d.rectangleArea();
    // The whole drum: lateral surface + two bed faces (their 2 mm recess adds its rim: 2 · 2π r · 0.002).
    const double ringInner = d.radius - std::min(0.08, 0.2 * d.radius);
    const double trueTotal = 2 * M_PI * d.radius * d.height + 2 * M_PI * d.radius * d.radius + 2 * 2 * M_PI * ringInner * 0.002;
    // The octree of the fixture (depth 7: leaf edge 3.9 mm, about two samples a leaf) and a deeper one of the same
    // scan (depth 9: about one sample a leaf, the closed-surface level two levels up).
    for (int depth : {7, 9}) {
        std::filesystem::path path = d.poct;
        if (depth != 7) {
            path = *d.dir / ("drum-d" + std::to_string(depth) + ".poct");
            oct::BuildOptions build;
            build.depth = depth;
            ASSERT_TRUE(oct::buildOctreeFile(*d.dir / "drum.ply", path, build).ok());
        }
        auto octree = oct::PackedOctree::open(path);
        ASSERT_TRUE(octree.ok());
        auto pixels = leafPixels(*octree, *d.map);
        ASSERT_TRUE(pixels.ok());
        std::vector<std::uint8_t> labels(pixels->size(), 0);
        applyLabelRaster(d.rectangle(2), *pixels, labels);
        auto areas = leafAreas(*octree);
        ASSERT_TRUE(areas.ok());
        ASSERT_EQ(areas->size(), labels.size());
        const auto m = measureClasses(labels, *areas);
        const double total = std::accumulate(areas->begin(), areas->end(), 0.0);
        std::printf("depth %d: patch %.5f m2 (analytic %.5f, %+.2f %%), whole drum %.4f m2 (analytic %.4f, %+.2f %%)\n", depth,
                    m[2].areaM2, truePatch, 100 * (m[2].areaM2 / truePatch - 1), total, trueTotal, 100 * (total / trueTotal - 1));
        // Measured: patch +0.35 % (depth 7), −0.20 % (depth 9); whole drum −0.00 %, −0.35 % (generator seeds 3
        // and 5: patch −0.14 % to −0.67 %, whole drum within 0.25 %).
        EXPECT_NEAR(m[2].areaM2 / truePatch, 1.0, 0.01) << "depth " << depth;
        EXPECT_NEAR(total / trueTotal, 1.0, 0.01) << "depth " << depth;
        for (double a : *areas) ASSERT_GE(a, 0.0);
    }
}

// Painting the whole développée labels the surface it shows: the drum's lateral surface, analytically 2π r h, and
// not its bed faces (seen edge-on) — with every leaf taken (an infinite depth), the beds came too.
TEST(AnnotationArea, TheWholeDeveloppeePaintsTheLateralSurfaceOnly)
{
    const auto& d = stylos::test::annotatedDrum();
    const double lateral = 2 * M_PI * d.radius * d.height;
    auto octree = oct::PackedOctree::open(d.poct);
    ASSERT_TRUE(octree.ok());
    auto areas = leafAreas(*octree);
    ASSERT_TRUE(areas.ok());
    LabelRaster all;
    all.width = d.map->width();
    all.height = d.map->height();
    all.ids.assign(std::size_t(all.width) * std::size_t(all.height), 1);
    for (const double depth : {paintDepth(d.map->pixelSize()), std::numeric_limits<double>::infinity()}) {
        auto pixels = leafPixels(*octree, *d.map, nullptr, depth);
        ASSERT_TRUE(pixels.ok());
        std::vector<std::uint8_t> labels(pixels->size(), 0);
        applyLabelRaster(all, *pixels, labels);
        const double painted = measureClasses(labels, *areas)[1].areaM2;
        std::printf("depth %g: painted %.4f m2, lateral %.4f m2 (%+.2f %%)\n", depth, painted, lateral,
                    100 * (painted / lateral - 1));
        // Measured +3.3 % at this fixture's depth 7 (leaf 3.9 mm): the beds' 2 mm recess rims face outward (1.1 %),
        // and the leaves of the corners, their normals between the two faces, count; on a 2 mm fluted drum at depth
        // 10, +0.1 % (docs/annotation.md).
        if (std::isfinite(depth))
            EXPECT_NEAR(painted / lateral, 1.0, 0.04);
        else
            EXPECT_GT(painted / lateral, 1.3); // and the two bed faces, 2 π r² more
    }
}

// A fluted drum: the painted patch spans flutes and fillets, so its surface is the flute profile's arc length
// (from the generator's own DrumShape, not from the cells) times its height — 1.2 times the unrolled rectangle.
TEST(AnnotationArea, MatchesTheFlutedSurfaceOfAPatch)
{
    namespace synth = stylos::core::synth;
    stylos::test::TempDir dir;
    auto o = stylos::test::coarse(0.004, 11); // the generator's default drum: radius 0.55 m, height 0.5 m, 48 flutes
    o.writeNormals = true;
    const auto ply = dir / "fluted.ply";
    const auto report = stylos::test::generate(synth::SyntheticKind::Drum, o, ply);
    std::ifstream truthFile(report.truthPath);
    const auto truth = nlohmann::json::parse(truthFile);
    const Eigen::Affine3d pose = stylos::test::poseOf(truth);
    synth::DrumParameters p;
    p.radius = truth.at("radius");
    p.height = truth.at("height");
    p.grooves = truth.at("grooves").at("count");
    p.grooveDepth = truth.at("grooves").at("depth");
    p.groovePhase = truth.at("grooves").at("phase");
    p.filletFraction = truth.at("grooves").at("filletFraction");
    ASSERT_GT(p.grooves, 0);
    const synth::DrumShape shape(p);

    oct::BuildOptions build;
    build.depth = 9; // leaf 2.3 mm, the closed-surface level 8 (4.6 mm)
    ASSERT_TRUE(oct::buildOctreeFile(ply, dir / "fluted.poct", build).ok());
    auto octree = oct::PackedOctree::open(dir / "fluted.poct");
    ASSERT_TRUE(octree.ok());
    stylos::core::developpee::DeveloppeeOptions unroll;
    unroll.pixelSize = 0.004;
    auto dev = stylos::core::developpee::computeDeveloppee(dir / "fluted.poct", unroll);
    ASSERT_TRUE(dev.ok()) << dev.error().message;
    const auto& map = dev->map;
    // Rows of z in [0.6 h, 0.8 h], a quarter of the columns; the column of azimuth θ (drum frame) on the fillet circle.
    auto pixelAt = [&](double theta, double z) {
        return *map.pixelOf(pose * Eigen::Vector3d(p.radius * std::cos(theta), p.radius * std::sin(theta), z));
    };
    const double ra = pixelAt(0, 0.6 * p.height).row, rb = pixelAt(0, 0.8 * p.height).row;
    const int r0 = int(std::ceil(std::min(ra, rb))), r1 = int(std::floor(std::max(ra, rb)));
    const int c0 = map.width() / 3, c1 = c0 + map.width() / 4;
    stylos::core::annotation::LabelRaster raster(map.width(), map.height());
    for (int r = r0; r < r1; ++r)
        for (int c = c0; c < c1; ++c) raster.at(c, r) = 2;
    auto pixels = leafPixels(*octree, map);
    ASSERT_TRUE(pixels.ok());
    std::vector<std::uint8_t> labels(pixels->size(), 0);
    applyLabelRaster(raster, *pixels, labels);

    // The patch's azimuths: the columns as a function of θ, read off the map on a fine circle.
    const double zMid = 0.7 * p.height;
    auto columnOf = [&](double theta) { return pixelAt(theta, zMid).column; };
    // θ of the patch's first column (a fine search, then bisection), then the way and the span to its last.
    double ta = 0, bestError = 1e30;
    for (int i = 0; i < 20000; ++i) {
        const double t = 2 * M_PI * i / 20000.0, e = std::abs(columnOf(t) - c0);
        if (e < bestError) bestError = e, ta = t;
    }
    const double step = 2 * M_PI / 20000;
    const double way = columnOf(ta + 1e-4) > columnOf(ta) ? 1.0 : -1.0;
    auto solve = [&](double from, double lo, double hi, double column) { // θ = from + way · Δ, Δ in [lo, hi]
        for (int i = 0; i < 60; ++i) {
            const double mid = 0.5 * (lo + hi);
            (columnOf(from + way * mid) < column ? lo : hi) = mid;
        }
        return from + way * 0.5 * (lo + hi);
    };
    ta = solve(ta - way * step, 0, 2 * step, c0);
    const double span = (c1 - c0) * map.pixelSize() / map.surface().referenceRadius();
    double tb = solve(ta, 0.8 * span, 1.2 * span, c1);
    if (tb < ta) std::swap(ta, tb);
    // The arc length of the fluted outline between them, then times the rows' height.
    double arc = 0;
    const int steps = 200000;
    for (int i = 0; i < steps; ++i) {
        const double t0 = ta + (tb - ta) * i / steps, t1 = ta + (tb - ta) * (i + 1) / steps;
        const double q0 = shape.fluteRadius(t0), q1 = shape.fluteRadius(t1);
        arc += std::hypot(q1 * std::cos(t1) - q0 * std::cos(t0), q1 * std::sin(t1) - q0 * std::sin(t0));
    }
    const double truePatch = arc * (r1 - r0) * map.pixelSize();
    const double unrolled = (c1 - c0) * map.pixelSize() * p.radius / map.surface().referenceRadius() * (r1 - r0) * map.pixelSize();
    auto areas = leafAreas(*octree);
    ASSERT_TRUE(areas.ok());
    const double measured = measureClasses(labels, *areas)[2].areaM2;
    std::printf("fluted: patch %.5f m2 (analytic %.5f, %+.2f %%; the unrolled rectangle %.5f)\n", measured, truePatch,
                100 * (measured / truePatch - 1), unrolled);
    EXPECT_GT(truePatch, 1.02 * unrolled); // the flutes add surface (2.8 % here): the estimate must find it
    // Measured −0.33 % (seeds 3 and 5: −0.60 %, −0.55 %; at depth 8, one sample a leaf: −0.5 % to −1.35 %).
    EXPECT_NEAR(measured / truePatch, 1.0, 0.01);
}

// A sparse fragment (4 mm samples, 3.53 mm pixels): a pixel that no leaf of the outer surface lands in holds only
// leaves of the inner break face, 17 cm down; its own top kept them, so a painted region showed them unpainted, as
// specks. Every leaf painting takes lies within twice the paint depth of the height the développée shows there.
TEST(AnnotationArea, ASparseFragmentsInnerFaceIsNotPainted)
{
    namespace synth = stylos::core::synth;
    stylos::test::TempDir dir;
    const auto ply = dir / "fragment.ply";
    stylos::test::generate(synth::SyntheticKind::Fragment, stylos::test::coarse(0.004, 5), ply);
    oct::BuildOptions build;
    build.depth = 9;
    ASSERT_TRUE(oct::buildOctreeFile(ply, dir / "fragment.poct", build).ok());
    auto octree = oct::PackedOctree::open(dir / "fragment.poct");
    ASSERT_TRUE(octree.ok());
    stylos::core::developpee::DeveloppeeOptions options;
    options.pixelSize = 0.00353;
    options.shading = stylos::core::developpee::Shading::Height;
    auto dev = stylos::core::developpee::computeDeveloppee(dir / "fragment.poct", options);
    ASSERT_TRUE(dev.ok()) << dev.error().message;
    const double depth = paintDepth(dev->map.pixelSize());
    auto pixels = leafPixels(*octree, dev->map, nullptr, depth);
    ASSERT_TRUE(pixels.ok());
    std::size_t mapped = 0, deep = 0;
    octree->forEachCell(octree->depth(), [&](const oct::CellView& cell) {
        const std::int64_t p = (*pixels)[cell.index];
        if (p < 0) return true;
        ++mapped;
        const auto hit = dev->map.pixelOf(Eigen::Vector3d(cell.centre[0], cell.centre[1], cell.centre[2]));
        const int c = int(p % dev->map.width()), r = int(p / dev->map.width());
        if (hit && dev->field.hasHeight(c, r) && hit->h < double(dev->field.heightAt(c, r)) - 2 * depth) ++deep;
        return true;
    });
    EXPECT_GT(mapped, 1000u);
    EXPECT_EQ(deep, 0u);
}
