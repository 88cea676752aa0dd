#pragma once
// A small plain-cylinder drum for the annotation tests: generated (true normals), built into a .poct, unrolled
// (the développée's map written as a sidecar), and a painted rectangle with its analytic surface area.
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include "stylos/core/annotation/LabelRaster.h"
#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/unroll/UnrollMap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <numbers>

namespace stylos::test {

struct AnnotatedDrum {
    std::unique_ptr<TempDir> dir;
    std::filesystem::path poct, sidecar;
    std::optional<core::unroll::UnrollMap> map;
    double radius = 0.2, height = 0.3;
    Eigen::Affine3d pose = Eigen::Affine3d::Identity(); ///< drum frame (axis z, bed at z = 0) → file frame
    int c0 = 0, c1 = 0, r0 = 0, r1 = 0;                ///< the painted rectangle: columns [c0, c1), rows [r0, r1)

    /** The rectangle of class @p id on the map's grid. */
    core::annotation::LabelRaster rectangle(std::uint8_t id) const
    {
        core::annotation::LabelRaster raster(map->width(), map->height());
        for (int r = r0; r < r1; ++r)
            for (int c = c0; c < c1; ++c) raster.at(c, r) = id;
        return raster;
    }
    /** Its analytic area on the cylinder of radius `radius`: arc (columns · s · radius / R_ref) × rows · s. */
    double rectangleArea() const
    {
        const double s = map->pixelSize();
        return (c1 - c0) * s * radius / map->surface().referenceRadius() * (r1 - r0) * s;
    }
};

/** Builds the drum once per test program (about a second). */
inline const AnnotatedDrum& annotatedDrum()
{
    static AnnotatedDrum drum = [] {
        AnnotatedDrum d;
        d.dir = std::make_unique<TempDir>();
        auto o = coarse(0.002, 11);
        o.radius = d.radius;
        o.height = d.height;
        o.grooves = 0;
        o.writeNormals = true;
        const auto ply = *d.dir / "drum.ply";
        const auto report = generate(core::synth::SyntheticKind::Drum, o, ply);
        std::ifstream truth(report.truthPath);
        d.pose = poseOf(nlohmann::json::parse(truth));
        d.poct = *d.dir / "drum.poct";
        core::octree::BuildOptions build;
        build.depth = 7;
        auto built = core::octree::buildOctreeFile(ply, d.poct, build);
        EXPECT_TRUE(built.ok()) << (built.ok() ? "" : built.error().message);
        auto dev = core::developpee::computeDeveloppee(d.poct);
        EXPECT_TRUE(dev.ok()) << (dev.ok() ? "" : dev.error().message);
        if (!dev.ok()) return d;
        d.map = dev->map;
        d.sidecar = *d.dir / "drum.png.json";
        EXPECT_TRUE(d.map->writeSidecar(d.sidecar).ok());
        // Rows of z in [0.6 h, 0.8 h] (above the broken region, below the claw band), a third of the columns.
        auto rowAt = [&](double z) {
            const Eigen::Vector3d p = d.pose * Eigen::Vector3d(d.radius, 0.0, z);
            return d.map->pixelOf(p)->row;
        };
        const double ra = rowAt(0.6 * d.height), rb = rowAt(0.8 * d.height);
        d.r0 = int(std::ceil(std::min(ra, rb)));
        d.r1 = int(std::floor(std::max(ra, rb)));
        d.c0 = d.map->width() / 3;
        d.c1 = 2 * d.map->width() / 3;
        return d;
    }();
    return drum;
}

} // namespace stylos::test
