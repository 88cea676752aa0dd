#pragma once
// Helpers of the docking tests: a drum and fragments of the same design (generated with one design seed,
// their own noise, registration and pose) and the true fragment → drum pose; DockGeometry.h has the
// perturbed starts and the errors in the drum frame.
#include "DockGeometry.h"
#include "FitTestSupport.h"

#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/dock/FluteModel.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace stylos::test {

inline constexpr std::uint64_t kDockDesign = 21;

/** A generated drum of design kDockDesign, by one all-round station (its registration error is then a
 *  rigid motion known from the truth: the points' frame is exact, see truePose()). */
inline const FitScan& dockDrum(double spacing = 0.003)
{
    auto o = allRound(spacing, 101, 48);
    o.designSeed = kDockDesign;
    return generatedScan("dock-drum-" + std::to_string(spacing), core::synth::SyntheticKind::Drum, o);
}

/** A generated fragment of the same drum design, scan seed @p seed, one all-round station. */
inline const FitScan& dockFragment(std::uint64_t seed, double spacing = 0.003)
{
    auto o = allRound(spacing, seed, 48);
    o.designSeed = kDockDesign;
    return generatedScan("dock-fragment-" + std::to_string(seed) + "-" + std::to_string(spacing),
                         core::synth::SyntheticKind::Fragment, o);
}

/** Fragment file frame → drum file frame, as the single stations placed them (registration error included). */
inline Eigen::Isometry3d truePose(const FitScan& fragment, const FitScan& drum)
{
    const Eigen::Affine3d a = affineOf(drum.truth["stations"][0]["toOutput"]) *
                              affineOf(fragment.truth["stations"][0]["toOutput"]).inverse();
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = a.linear();
    pose.translation() = a.translation();
    return pose;
}

} // namespace stylos::test
