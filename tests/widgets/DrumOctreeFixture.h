#pragma once
// A small generated drum for the 3D view's tests: core::synth::generateScan at a coarse spacing (with the
// true normals, so no estimation), then core::octree::buildOctreeFile. About 40 K points; well under a second.
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/synth/SyntheticScan.h"

#include <QString>
#include <QtTest/QtTest>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <memory>

namespace stylos::test {

struct DrumOctree {
    std::filesystem::path ply;
    std::filesystem::path poct;
    nlohmann::json truth;
    std::shared_ptr<const core::octree::PackedOctree> octree;
};

/** Generates the drum into @p dir and builds its octree (depth @p depth); QFAILs are the caller's to check. */
inline DrumOctree makeDrumOctree(const QString& dir, double spacing = 0.01, int depth = 7)
{
    DrumOctree d;
    d.ply = std::filesystem::path(dir.toStdString()) / "drum.ply";
    d.poct = std::filesystem::path(dir.toStdString()) / "drum.poct";
    core::synth::SyntheticOptions options;
    options.spacing = spacing;
    options.writeNormals = true;
    auto generated = core::synth::generateScan(core::synth::SyntheticKind::Drum, options, d.ply);
    if (!generated.ok()) qFatal("generateScan: %s", generated.error().message.c_str());
    std::ifstream truth(generated->truthPath);
    d.truth = nlohmann::json::parse(truth);
    core::octree::BuildOptions build;
    build.depth = depth;
    build.threads = 1;
    auto built = core::octree::buildOctreeFile(d.ply, d.poct, build);
    if (!built.ok()) qFatal("buildOctreeFile: %s", built.error().message.c_str());
    auto opened = core::octree::PackedOctree::open(d.poct);
    if (!opened.ok()) qFatal("open: %s", opened.error().message.c_str());
    d.octree = std::make_shared<const core::octree::PackedOctree>(std::move(opened.value()));
    return d;
}

} // namespace stylos::test
