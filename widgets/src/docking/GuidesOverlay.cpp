#include "docking/GuidesOverlay.h"

namespace stylos::widgets {

void GuidesOverlay::draw(const OverlayFrame& frame)
{
    if (!m_visible || m_segments.empty()) return;
    OverlayGeometry geometry(frame.camera, frame.camera.target());
    for (const core::view::GuideSegment& s : m_segments) {
        if (s.kind == core::scene::GuideKind::Axis) geometry.addSegment(s.a, s.b, 3.0, QColor(255, 140, 30));
        else geometry.addSegment(s.a, s.b, 1.3, QColor(120, 215, 255, 210));
    }
    m_mesh.draw(frame, geometry);
}

} // namespace stylos::widgets
