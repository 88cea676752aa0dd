#pragma once
/** @file
 * @brief One drag of a gizmo handle, from the press to the release: the raw motion of the cursor turned into
 *        the handle's parameter (metres along an arrow, radians about a ring), accumulated with Shift's
 *        tenth (FineDrag), snapped (angleStep / lengthStep) and applied to the pose the fragment had at the
 *        press (applyHandle). The handle's geometry and the camera are those of the press: the gizmo does not
 *        move under the cursor during the drag.
 *
 * Arrows: the closest parameter along the arrow's line to the cursor's ray, minus the press's. Rings: where
 * the ray meets the ring's plane, as the signed angle from the press point (unwrapped past ±π), when the
 * plane faces the camera (|cos| ≥ 0.2 between the press ray and the ring's axis); a ring seen nearly
 * edge-on (a drum's θ ring in a side view) turns instead by the cursor's motion along the ring's projected
 * tangent at the press point, divided by the pixels that tangent covers per radian (at the ring's silhouette,
 * where that tangent points at the eye: by the motion across the projected axis, the radius in pixels a radian).
 * Units: metres, radians, logical pixels. Thread-safety: a value type. Failure modes: begin() gives nullopt
 * when the handle cannot be dragged from there (an arrow pointing at the eye, a ring seen exactly edge-on
 * at the press point); update() gives nullopt, leaving the last pose, while the cursor's ray misses.
 */
#include "stylos/core/view/Camera.h"
#include "stylos/core/view/GizmoHandles.h"
#include "stylos/core/view/GizmoMath.h"

#include <Eigen/Core>

#include <optional>

namespace stylos::core::view {

class GizmoDrag {
public:
    /** @brief Starts dragging @p handle at @p cursor, seen by @p camera, from the pose @p start. */
    static std::optional<GizmoDrag> begin(const GizmoHandle& handle, const Camera& camera,
                                          const Eigen::Vector2d& cursor, const Eigen::Matrix4d& start);

    /** @brief The pose for the cursor at @p cursor with @p modifiers; nullopt when the ray misses (keep the last). */
    std::optional<Eigen::Matrix4d> update(const Eigen::Vector2d& cursor, DragModifiers modifiers);

    const GizmoHandle& handle() const { return m_handle; }
    const Eigen::Matrix4d& startPose() const { return m_start; }
    /** @brief The snapped value last applied (metres or radians). */
    double value() const { return m_snapped; }
    /** @brief True when a ring follows the tangent on screen rather than its plane. */
    bool followsTangent() const { return m_tangent; }

private:
    GizmoDrag(const GizmoHandle& handle, const Camera& camera, const Eigen::Vector2d& cursor, const Eigen::Matrix4d& start)
        : m_handle(handle), m_camera(camera), m_pressCursor(cursor), m_start(start)
    {
    }
    std::optional<double> raw(const Eigen::Vector2d& cursor) const;

    GizmoHandle m_handle;
    Camera m_camera;
    Eigen::Vector2d m_pressCursor;
    Eigen::Matrix4d m_start;
    double m_pressParameter = 0.0;                          ///< arrows: the parameter at the press
    Eigen::Vector3d m_zero = Eigen::Vector3d::UnitX();      ///< rings: centre → the press point
    bool m_tangent = false;
    Eigen::Vector2d m_tangentPixels = Eigen::Vector2d::Zero(); ///< pixels per radian along the ring at the press
    double m_lastRaw = 0.0;
    FineDrag m_fine;
    double m_snapped = 0.0;
};

} // namespace stylos::core::view
