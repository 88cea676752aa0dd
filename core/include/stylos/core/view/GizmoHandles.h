#pragma once
/** @file
 * @brief The handles of the docking gizmo on one fragment, as geometry in the scene frame: three arrows and
 *        three rings about the World axes or the Fragment's own axes, through the fragment's centre; or, in
 *        the Drum frame (when a docking drum's axis is known), a ring about the drum axis through the
 *        fragment's centre (θ), an arrow along the axis (z), a radial arrow from the axis through the centre
 *        (r) and, on request, two tilt rings about the radial and the tangential directions through the
 *        centre. What a handle does to a pose (applyHandle) and which handle is under the cursor (pickHandle).
 *
 * Sizes: arrows and the small rings have a constant size on screen (GizmoSizes, pixels, turned into metres
 * with the metres per pixel at the centre); the θ ring is the circle the centre travels about the drum axis
 * (its true radius; the on-screen size when the centre lies on the axis).
 * Units: metres, radians, pixels. Thread-safety: pure functions. Failure modes: none; a Drum frame without a
 * drum axis falls back to the World frame.
 */
#include "stylos/core/view/Camera.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace stylos::core::view {

/** @brief The frame the gizmo's handles follow. */
enum class GizmoFrame { World, Fragment, Drum };

/** @brief What a handle stands for. */
enum class HandleRole {
    MoveX, MoveY, MoveZ,           ///< arrows along the frame's axes (World or Fragment)
    TurnX, TurnY, TurnZ,           ///< rings about them
    DrumTheta,                     ///< ring about the drum axis
    DrumZ,                         ///< arrow along the drum axis
    DrumRadial,                    ///< arrow from the drum axis through the centre
    TiltRadial,                    ///< ring about the radial direction through the centre
    TiltTangential,                ///< ring about the tangential direction (axis × radial) through the centre
};

/** @brief True for the arrows (a translation), false for the rings (a rotation). */
bool isTranslation(HandleRole role);

/** @brief A docking drum's axis in the scene frame and its flute pitch (2π / flutes; 0: no flutes). */
struct DrumAxis {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ(); ///< unit
    double pitch = 0.0;                                    ///< radians
};

/** @brief What the gizmo acts on. */
struct GizmoTarget {
    Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();     ///< fragment frame → scene frame, rigid
    Eigen::Vector3d localCentre = Eigen::Vector3d::Zero();   ///< the fragment's centre in its own frame
    std::optional<DrumAxis> drum;                            ///< the docking drum's axis, scene frame

    /** @brief The centre in the scene frame. */
    Eigen::Vector3d centre() const { return pose.topLeftCorner<3, 3>() * localCentre + pose.topRightCorner<3, 1>(); }
};

/** @brief On-screen sizes of the handles, logical pixels. */
struct GizmoSizes {
    double arrow = 90;      ///< arrow length
    double ring = 70;       ///< radius of the World/Fragment rings
    double tilt = 48;       ///< radius of the tilt rings
    double pickRadius = 7;  ///< how near the cursor must come to a handle to take it
};

/** @brief One handle: an arrow from @p origin along @p direction, or a ring about @p direction through @p origin. */
struct GizmoHandle {
    HandleRole role = HandleRole::MoveX;
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();     ///< scene frame; a ring's centre
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX(); ///< unit; a ring's axis
    double size = 0.0;                                    ///< arrow length or ring radius, metres
    double pitch = 0.0;                                   ///< the angle a ring snaps by (DrumTheta), radians

    bool translates() const { return isTranslation(role); }
};

/**
 * @brief The handles of @p target in @p frame (Drum only with a drum axis, World otherwise); the tilt rings
 *        only with @p tilts. @p metresPerPixel: at the centre (metresPerPixel()); order: arrows, then rings.
 */
std::vector<GizmoHandle> gizmoHandles(const GizmoTarget& target, GizmoFrame frame, bool tilts, double metresPerPixel,
                                      const GizmoSizes& sizes = {});

/**
 * @brief The handles of gizmoHandles() as @p camera shows them (at the metres per pixel at the centre), less
 *        those that cannot be used from there (as ImGuizmo hides them): an arrow pointing within 8° of the line
 *        of sight, a World/Fragment or tilt ring seen within 6° of edge-on (a line on screen, over the arrows).
 *        The θ ring stays: seen edge-on in a side view it turns by its tangent (GizmoDrag). Empty when the
 *        centre is behind the eye.
 */
std::vector<GizmoHandle> visibleGizmoHandles(const GizmoTarget& target, GizmoFrame frame, bool tilts,
                                             const Camera& camera, const GizmoSizes& sizes = {});

/** @brief @p start moved by @p value along an arrow (metres) or turned by @p value about a ring's axis line
 *         (radians, counter-clockwise about its direction), in the scene frame: M·start. */
Eigen::Matrix4d applyHandle(const GizmoHandle& handle, const Eigen::Matrix4d& start, double value);

/** @brief The index of the handle nearest @p cursor on screen within @p radius pixels (the first of equals:
 *         arrows before rings); nullopt when none. */
std::optional<std::size_t> pickHandle(const std::vector<GizmoHandle>& handles, const Camera& camera,
                                      const Eigen::Vector2d& cursor, double radius);

} // namespace stylos::core::view
