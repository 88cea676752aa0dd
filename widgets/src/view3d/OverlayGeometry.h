#pragma once
/** @file
 * @brief Lines of a constant width on screen for the 3D view's overlays (gizmo handles, guides), built on the
 *        CPU for one camera: each segment becomes a quad facing the eye (two triangles), its half-width in
 *        pixels turned into metres at each end's depth; arrow heads are triangles facing the eye. OpenGL 3.3
 *        core draws no wide lines, hence quads. Positions are relative to an origin (the overlay's model
 *        translation) so that site coordinates keep their precision in float.
 *        Units: metres (scene frame), logical pixels. Thread-safety: a value type; GUI thread in practice.
 */
#include "stylos/core/view/Camera.h"

#include <QColor>

#include <Eigen/Core>

#include <vector>

namespace stylos::widgets {

/** @brief One vertex: position relative to the origin, colour (straight alpha). */
struct OverlayVertex {
    float x, y, z;
    float r, g, b, a;
};

class OverlayGeometry {
public:
    /** @p camera: the frame's; @p origin: subtracted from every position (e.g. the camera's target). */
    OverlayGeometry(const core::view::Camera& camera, const Eigen::Vector3d& origin);

    /** @brief A segment @p width pixels wide; nothing when an end lies behind the eye. */
    void addSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double width, const QColor& colour);
    /** @brief A circle of @p radius metres about the unit @p axis through @p centre, as @p segments segments. */
    void addRing(const Eigen::Vector3d& centre, const Eigen::Vector3d& axis, double radius, double width,
                 const QColor& colour, int segments = 128);
    /** @brief An arrow from @p base to @p tip: a shaft @p width pixels wide and a head @p head pixels long. */
    void addArrow(const Eigen::Vector3d& base, const Eigen::Vector3d& tip, double width, double head, const QColor& colour);

    const Eigen::Vector3d& origin() const { return m_origin; }
    /** @brief The triangles, three vertices each. */
    const std::vector<OverlayVertex>& triangles() const { return m_triangles; }
    bool empty() const { return m_triangles.empty(); }

private:
    /** A unit vector across the segment a → b on screen (⊥ to it and to the line of sight); empty when degenerate. */
    bool across(const Eigen::Vector3d& a, const Eigen::Vector3d& b, Eigen::Vector3d& side) const;
    void vertex(const Eigen::Vector3d& p, const QColor& colour);

    const core::view::Camera& m_camera;
    Eigen::Vector3d m_origin;
    std::vector<OverlayVertex> m_triangles;
};

} // namespace stylos::widgets
