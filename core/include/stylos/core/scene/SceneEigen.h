#pragma once
/** @file
 * @brief The one conversion point between the scene's plain values (positions and directions as
 *        std::array<double, 3>, poses as row-major 4 × 4 arrays, guides) and Eigen, which the geometry
 *        (fits, unrolling, the view's maths) uses. Exact: doubles are copied, nothing is rounded.
 *        Units: metres. Thread-safety: pure functions.
 */
#include "stylos/core/scene/Fragment.h"
#include "stylos/core/scene/Pose.h"

#include <Eigen/Core>

#include <array>
#include <optional>

namespace stylos::core::scene {

class Scene;

inline Eigen::Vector3d toEigen(const std::array<double, 3>& p) { return {p[0], p[1], p[2]}; }
inline std::array<double, 3> toArray(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

/** @brief The pose as an Eigen matrix (same elements). */
inline Eigen::Matrix4d toEigen(const Pose& pose)
{
    Eigen::Matrix4d m;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) m(row, col) = pose(row, col);
    return m;
}

/** @brief A pose from an Eigen matrix (same elements; rigidity is the caller's to keep). */
inline Pose poseFromEigen(const Eigen::Matrix4d& m)
{
    std::array<double, 16> rowMajor{};
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) rowMajor[std::size_t(4 * row + col)] = m(row, col);
    return Pose(rowMajor);
}

/** @brief @p pose applied to the Eigen point @p p. */
inline Eigen::Vector3d apply(const Pose& pose, const Eigen::Vector3d& p) { return toEigen(pose.apply(toArray(p))); }

/** @brief A guide's line (origin, direction) in Eigen, in its fragment's frame. */
struct GuideLine {
    Eigen::Vector3d origin;
    Eigen::Vector3d direction;
};
inline GuideLine guideLine(const Guide& guide) { return {toEigen(guide.origin), toEigen(guide.direction)}; }

/** @brief The fragment's first guide of @p kind, as a line in its own frame; nullopt when it has none. */
inline std::optional<GuideLine> firstGuide(const Fragment& fragment, GuideKind kind)
{
    for (const Guide& guide : fragment.guides)
        if (guide.kind == kind) return guideLine(guide);
    return std::nullopt;
}

/** @brief The drum @p fragment docks against: its assembly's drum, else the scene's docking drum (NoFragment: none). */
FragmentId drumFor(const Scene& scene, FragmentId fragment);

/** @brief The fragment whose axis guide @p fragment unrolls about: itself when it has one, else @p drum (another
 *         fragment of @p scene) when that has one; NoFragment otherwise. */
FragmentId unrollAxisOwner(const Scene& scene, FragmentId fragment, FragmentId drum);

/**
 * @brief The axis @p fragment unrolls about (its développée in the workbench and on a plate): its own first
 *        Axis guide, else that of @p drum (another fragment of @p scene, e.g. its assembly's drum) carried into
 *        the fragment's frame through their scene poses; nullopt when neither has one.
 */
std::optional<GuideLine> unrollAxis(const Scene& scene, FragmentId fragment, FragmentId drum);

} // namespace stylos::core::scene
