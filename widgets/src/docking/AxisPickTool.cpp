#include "stylos/widgets/docking/AxisPickTool.h"

#include "stylos/core/view/GizmoMath.h"
#include "stylos/widgets/view3d/ViewOverlay.h"
#include "stylos/widgets/view3d/ViewportWidget.h"
#include "view3d/OverlayMesh.h"

#include <QKeyEvent>
#include <QMouseEvent>

namespace stylos::widgets {

/** The picked points: a ring 7 pixels across facing the eye at each, the segment between two. */
class AxisPickOverlay : public ViewOverlay {
public:
    bool initialize() override { return m_mesh.initialize(); }
    void release() override { m_mesh.release(); }
    void draw(const OverlayFrame& frame) override
    {
        if (m_points.empty()) return;
        OverlayGeometry geometry(frame.camera, frame.camera.target());
        const QColor colour(255, 60, 200);
        for (const Eigen::Vector3d& p : m_points) {
            const auto mpp = core::view::metresPerPixel(frame.camera, p);
            if (mpp) geometry.addRing(p, -frame.camera.forward(), 7.0 * *mpp, 2.5, colour, 32);
        }
        if (m_points.size() == 2) geometry.addSegment(m_points[0], m_points[1], 2.0, colour);
        m_mesh.draw(frame, geometry);
    }
    void setPoints(std::vector<Eigen::Vector3d> points) { m_points = std::move(points); }

private:
    OverlayMesh m_mesh;
    std::vector<Eigen::Vector3d> m_points;
};

AxisPickTool::AxisPickTool(quint64 fragment, PickedHandler onPicked, CancelHandler onCancel)
    : m_fragment(fragment), m_onPicked(std::move(onPicked)), m_onCancel(std::move(onCancel)),
      m_overlay(std::make_shared<AxisPickOverlay>())
{
}

AxisPickTool::~AxisPickTool() = default;

void AxisPickTool::activate(ViewportWidget& view)
{
    view.addOverlay(m_overlay);
    view.requestFrame();
}

void AxisPickTool::deactivate(ViewportWidget& view)
{
    view.removeOverlay(m_overlay.get());
    view.requestFrame();
}

bool AxisPickTool::mousePress(ViewportWidget&, QMouseEvent& event)
{
    m_pressed = event.button() == Qt::LeftButton;
    m_press = event.position();
    return false; // navigation may orbit from here; a click is told by the release
}

bool AxisPickTool::mouseRelease(ViewportWidget& view, QMouseEvent& event)
{
    if (!m_pressed || event.button() != Qt::LeftButton) return false;
    m_pressed = false;
    const QPointF moved = event.position() - m_press;
    if (QPointF::dotProduct(moved, moved) > 16.0) return false; // a drag
    const auto pick = view.pickAt(event.position());
    if (!pick || pick->fragmentId != m_fragment) return false;
    m_points.push_back(pick->point);
    m_overlay->setPoints(m_points);
    view.requestFrame();
    if (m_points.size() == 2) {
        const auto points = m_points;
        m_points.clear();
        if (m_onPicked) m_onPicked(m_fragment, points[0], points[1]); // may replace this tool: nothing after
        return true;
    }
    return true;
}

bool AxisPickTool::keyPress(ViewportWidget&, QKeyEvent& event)
{
    if (event.key() != Qt::Key_Escape) return false;
    if (m_onCancel) m_onCancel(); // may replace this tool: nothing after
    return true;
}

QCursor AxisPickTool::cursor() const { return QCursor(Qt::CrossCursor); }

} // namespace stylos::widgets
