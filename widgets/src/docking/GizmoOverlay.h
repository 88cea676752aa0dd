#pragma once
/** @file
 * @brief Draws the docking gizmo (GizmoTool's handles) over the points: arrows and rings of a constant width
 *        on screen, coloured by axis (X red, Y green, Z blue; in the Drum frame θ gold, z blue, r magenta,
 *        tilts cyan), the hovered or dragged handle wider and light yellow. The handles are those of
 *        core::view::visibleGizmoHandles for the frame's camera, so that they are where GizmoTool picks them.
 *        OpenGL 3.3 core; context current in initialize/draw/release; GUI thread only.
 */
#include "stylos/core/view/GizmoHandles.h"
#include "stylos/widgets/view3d/ViewOverlay.h"
#include "view3d/OverlayMesh.h"

#include <optional>

namespace stylos::widgets {

/** @brief What the gizmo shows: its target, frame, the tilt rings, the highlighted handle. */
struct GizmoState {
    std::optional<core::view::GizmoTarget> target;   ///< none: nothing drawn
    core::view::GizmoFrame frame = core::view::GizmoFrame::World;
    bool tilts = false;
    std::optional<core::view::HandleRole> highlighted;
};

class GizmoOverlay : public ViewOverlay {
public:
    bool initialize() override { return m_mesh.initialize(); }
    void release() override { m_mesh.release(); }
    void draw(const OverlayFrame& frame) override;

    void setState(const GizmoState& state) { m_state = state; }
    const GizmoState& state() const { return m_state; }

private:
    OverlayMesh m_mesh;
    GizmoState m_state;
};

} // namespace stylos::widgets
