#include "docking/GizmoOverlay.h"


namespace stylos::widgets {

namespace {

using core::view::HandleRole;

QColor handleColour(HandleRole role)
{
    switch (role) {
    case HandleRole::MoveX:
    case HandleRole::TurnX: return QColor(235, 70, 60);
    case HandleRole::MoveY:
    case HandleRole::TurnY: return QColor(110, 200, 60);
    case HandleRole::MoveZ:
    case HandleRole::TurnZ:
    case HandleRole::DrumZ: return QColor(70, 130, 245);
    case HandleRole::DrumTheta: return QColor(245, 185, 40);
    case HandleRole::DrumRadial: return QColor(215, 90, 215);
    case HandleRole::TiltRadial:
    case HandleRole::TiltTangential: return QColor(60, 210, 220);
    }
    return Qt::white;
}

} // namespace

void GizmoOverlay::draw(const OverlayFrame& frame)
{
    if (!m_state.target) return;
    const Eigen::Vector3d centre = m_state.target->centre();
    const auto handles = core::view::visibleGizmoHandles(*m_state.target, m_state.frame, m_state.tilts, frame.camera);
    OverlayGeometry geometry(frame.camera, centre);
    // The highlighted handle last, over the others.
    for (int pass = 0; pass < 2; ++pass) {
        for (const core::view::GizmoHandle& h : handles) {
            const bool lit = m_state.highlighted == h.role;
            if (lit != (pass == 1)) continue;
            const QColor colour = lit ? QColor(255, 240, 130) : handleColour(h.role);
            const double width = lit ? 5.0 : 3.0;
            if (h.translates()) geometry.addArrow(h.origin, h.origin + h.size * h.direction, width, 16.0, colour);
            else geometry.addRing(h.origin, h.direction, h.size, width, colour, h.role == HandleRole::DrumTheta ? 256 : 96);
        }
    }
    m_mesh.draw(frame, geometry);
}

} // namespace stylos::widgets
