#include "stylos/widgets/annotation/LassoTool.h"

#include "stylos/widgets/view3d/ViewOverlay.h"
#include "stylos/widgets/view3d/ViewportWidget.h"
#include "view3d/OverlayMesh.h"

#include <QKeyEvent>
#include <QMouseEvent>

namespace stylos::widgets {

namespace {

constexpr double MinStepPixels = 2.0; ///< a new vertex once the mouse moved this far from the last one

} // namespace

/** The polygon drawn on the target's plane (facing the eye), 2 pixels wide; the closing edge fainter. */
class LassoOverlay : public ViewOverlay {
public:
    bool initialize() override { return m_mesh.initialize(); }
    void release() override { m_mesh.release(); }
    void draw(const OverlayFrame& frame) override
    {
        if (m_polygon.size() < 2) return;
        const core::view::Camera& camera = frame.camera;
        OverlayGeometry geometry(camera, camera.target());
        auto onTargetPlane = [&](const Eigen::Vector2d& p) {
            const core::view::Ray ray = camera.rayAt(p.x(), p.y());
            const double along = camera.isOrthographic() ? camera.distance() - camera.nearPlane() : camera.distance();
            return Eigen::Vector3d(ray.origin + along * ray.direction);
        };
        const QColor colour(255, 220, 60);
        for (std::size_t i = 1; i < m_polygon.size(); ++i)
            geometry.addSegment(onTargetPlane(m_polygon[i - 1]), onTargetPlane(m_polygon[i]), 2.0, colour);
        QColor closing = colour;
        closing.setAlphaF(0.45f);
        geometry.addSegment(onTargetPlane(m_polygon.back()), onTargetPlane(m_polygon.front()), 1.5, closing);
        m_mesh.draw(frame, geometry);
    }
    void setPolygon(std::vector<Eigen::Vector2d> polygon) { m_polygon = std::move(polygon); }

private:
    OverlayMesh m_mesh;
    std::vector<Eigen::Vector2d> m_polygon;
};

LassoTool::LassoTool(Handler onLasso) : m_onLasso(std::move(onLasso)), m_overlay(std::make_shared<LassoOverlay>()) {}

LassoTool::~LassoTool() = default;

void LassoTool::activate(ViewportWidget& view) { view.addOverlay(m_overlay); }

void LassoTool::deactivate(ViewportWidget& view) { view.removeOverlay(m_overlay.get()); }

void LassoTool::showPolygon(ViewportWidget& view)
{
    m_overlay->setPolygon(m_polygon);
    view.requestFrame();
}

std::vector<std::uint64_t> LassoTool::targets(const ViewportWidget& view, const Eigen::Vector2d& press)
{
    for (const core::view::ViewFragment& f : view.fragments())
        if (f.visible && f.selected && f.octree) return {f.id};
    if (const auto pick = view.pickAt(QPointF(press.x(), press.y()))) return {pick->fragmentId};
    return {};
}

bool LassoTool::mousePress(ViewportWidget& view, QMouseEvent& event)
{
    if (event.button() != Qt::LeftButton || (event.modifiers() & Qt::AltModifier)) return false;
    m_drawing = true;
    m_polygon = {Eigen::Vector2d(event.position().x(), event.position().y())};
    showPolygon(view);
    return true;
}

bool LassoTool::mouseMove(ViewportWidget& view, QMouseEvent& event)
{
    if (!m_drawing) return false;
    const Eigen::Vector2d p(event.position().x(), event.position().y());
    if ((p - m_polygon.back()).norm() < MinStepPixels) return true;
    m_polygon.push_back(p);
    showPolygon(view);
    return true;
}

bool LassoTool::mouseRelease(ViewportWidget& view, QMouseEvent& event)
{
    if (event.button() != Qt::LeftButton) return false;
    if (!m_drawing) return false; // not its drag, or cancelled with Escape
    m_drawing = false;
    const Eigen::Vector2d p(event.position().x(), event.position().y());
    if ((p - m_polygon.back()).norm() >= MinStepPixels) m_polygon.push_back(p);
    const std::vector<Eigen::Vector2d> polygon = std::move(m_polygon);
    m_polygon.clear();
    showPolygon(view);
    if (polygon.size() < 3) return true;
    const auto hits = core::view::lassoVisibleLeaves(view.fragments(), view.camera(), targets(view, polygon.front()), polygon);
    const bool erase = m_erase || (event.modifiers() & Qt::ControlModifier);
    if (m_onLasso) m_onLasso(hits, erase); // may replace this tool: nothing after
    return true;
}

bool LassoTool::keyPress(ViewportWidget& view, QKeyEvent& event)
{
    if (event.key() != Qt::Key_Escape || !m_drawing) return false;
    m_drawing = false;
    m_polygon.clear();
    showPolygon(view);
    return true;
}

QCursor LassoTool::cursor() const { return QCursor(Qt::CrossCursor); }

} // namespace stylos::widgets
