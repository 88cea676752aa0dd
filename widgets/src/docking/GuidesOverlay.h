#pragma once
/** @file
 * @brief Draws the fragments' guides over the points: each Axis guide as an orange line 3 pixels wide over its
 *        fragment's height, each Groove guide (a flute line) as a thin light-blue line, in the scene frame
 *        (core::view::guideSegments). No depth test: the lines stay visible through the points.
 *        OpenGL 3.3 core; context current in initialize/draw/release; GUI thread only.
 */
#include "stylos/core/view/GuideGeometry.h"
#include "stylos/widgets/view3d/ViewOverlay.h"
#include "view3d/OverlayMesh.h"

#include <vector>

namespace stylos::widgets {

class GuidesOverlay : public ViewOverlay {
public:
    bool initialize() override { return m_mesh.initialize(); }
    void release() override { m_mesh.release(); }
    void draw(const OverlayFrame& frame) override;

    void setSegments(std::vector<core::view::GuideSegment> segments) { m_segments = std::move(segments); }
    const std::vector<core::view::GuideSegment>& segments() const { return m_segments; }
    void setVisible(bool visible) { m_visible = visible; }
    bool isVisible() const { return m_visible; }

private:
    OverlayMesh m_mesh;
    std::vector<core::view::GuideSegment> m_segments;
    bool m_visible = true;
};

} // namespace stylos::widgets
