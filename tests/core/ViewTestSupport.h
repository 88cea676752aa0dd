#pragma once
// Helpers shared by the 3D view's core tests (core/view): a four-leaf octree with exact cells, and a small
// generated drum (core::synth::generateScan at a coarse spacing, true normals, then buildOctreeFile).
#include "PoctTestSupport.h"
#include "ReferenceOctree.h"
#include "SyntheticTestSupport.h"
#include "TestSupport.h"

#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/view/ViewFragment.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <memory>

namespace stylos::test {

// The four-leaf tree: root box origin (100, 200, 300), edge 4, depth 2 (leaves of 1 m). Cluster a in
// level-1 cell (0,0,0): leaves a1 (0,0,0) and a2 (1,0,0); cluster b in level-1 cell (1,1,1): leaves
// b1 (2,2,2) and b2 (3,2,2). Breadth-first: level 1 = [a, b], level 2 = [a1, a2, b1, b2]. Leaf colours
// (10, 20, 30), (40, 50, 60), (70, 80, 90), (100, 110, 120); normals +z, +x, +y, −z.
constexpr double FourLeafOrigin[3] = {100, 200, 300};

inline std::shared_ptr<const core::octree::PackedOctree> fourLeafOctree(const TempDir& dir)
{
    const double x = FourLeafOrigin[0], y = FourLeafOrigin[1], z = FourLeafOrigin[2];
    const std::vector<double> p{x + 0.5, y + 0.5, z + 0.5, x + 1.5, y + 0.5, z + 0.5,
                                x + 2.5, y + 2.5, z + 2.5, x + 3.5, y + 2.5, z + 2.5};
    const std::vector<float> n{0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, -1};
    const std::vector<std::uint8_t> c{10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120};
    const ReferenceOctree tree(p, n, c, 2, core::octree::NormalCodeKind::Octahedral16,
                               core::octree::RootBox{{x, y, z}, 4.0});
    return pack(tree, dir, "four.poct");
}

struct DrumOctree {
    std::filesystem::path ply;
    nlohmann::json truth;
    std::shared_ptr<const core::octree::PackedOctree> octree;
};

/** The generated drum at @p spacing (metres) as an octree of @p depth in @p dir; a null octree on failure. */
inline DrumOctree makeDrumOctree(const std::filesystem::path& dir, double spacing = 0.01, int depth = 6)
{
    DrumOctree d;
    d.ply = dir / "drum.ply";
    core::synth::SyntheticOptions options;
    options.spacing = spacing;
    options.writeNormals = true;
    const core::synth::SyntheticReport report = generate(core::synth::SyntheticKind::Drum, options, d.ply);
    if (report.truthPath.empty()) return d;
    std::ifstream truth(report.truthPath);
    d.truth = nlohmann::json::parse(truth);
    core::octree::BuildOptions build;
    build.depth = depth;
    build.threads = 1;
    const auto built = core::octree::buildOctreeFile(d.ply, dir / "drum.poct", build);
    EXPECT_TRUE(built.ok()) << (built.ok() ? "" : built.error().message);
    if (!built.ok()) return d;
    auto opened = core::octree::PackedOctree::open(dir / "drum.poct");
    EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error().message);
    if (opened.ok()) d.octree = std::make_shared<const core::octree::PackedOctree>(std::move(opened).value());
    return d;
}

/** A view fragment of @p octree with @p id and @p pose. */
inline core::view::ViewFragment viewFragment(std::uint64_t id, std::shared_ptr<const core::octree::PackedOctree> octree,
                                             const Eigen::Matrix4d& pose = Eigen::Matrix4d::Identity())
{
    core::view::ViewFragment f;
    f.id = id;
    f.octree = std::move(octree);
    f.pose = pose;
    return f;
}

} // namespace stylos::test
