#pragma once
// Helpers shared by the synthetic-scan tests: coarse options, generation that records failures, and
// the pose read back from a truth sidecar.
#include "stylos/core/synth/SyntheticScan.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace stylos::test {

/** Options for quick tests: a coarse spacing (few points) and a fixed seed. */
inline core::synth::SyntheticOptions coarse(double spacing = 0.005, std::uint64_t seed = 7)
{
    core::synth::SyntheticOptions o;
    o.spacing = spacing;
    o.seed = seed;
    return o;
}

/** generateScan(), failing the current test (and returning an empty report) on error. */
inline core::synth::SyntheticReport generate(core::synth::SyntheticKind kind, const core::synth::SyntheticOptions& o,
                                             const std::filesystem::path& out)
{
    auto r = core::synth::generateScan(kind, o, out);
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
    return r.ok() ? *r : core::synth::SyntheticReport{};
}

/** The sidecar's "pose": row-major 4×4 from the object frame to the output frame. */
inline Eigen::Affine3d poseOf(const nlohmann::json& truth)
{
    Eigen::Matrix4d m;
    for (int i = 0; i < 16; ++i) m(i / 4, i % 4) = truth["pose"][i].get<double>();
    return Eigen::Affine3d(m);
}

} // namespace stylos::test
