#include "stylos/widgets/view3d/NavigationTool.h"

#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include <cmath>

namespace stylos::widgets {

using core::view::StandardView;

namespace {

constexpr double RadiansPerPixel = 0.008;
constexpr int ClickTolerance = 4; ///< a press and release closer than this (Manhattan, pixels) is a click

} // namespace

bool NavigationTool::mousePress(ViewportWidget&, QMouseEvent& event)
{
    m_pressPosition = m_lastPosition = event.position().toPoint();
    m_dragButton = event.button();
    m_dragged = false;
    return true;
}

bool NavigationTool::hover(ViewportWidget& view, QMouseEvent& event)
{
    if (m_dragButton != Qt::NoButton) return mouseMove(view, event); // a drag whose buttons the event lost
    if (const auto pick = view.pickAt(event.position())) Q_EMIT view.cursorMoved(pick->point);
    return true;
}

bool NavigationTool::mouseMove(ViewportWidget& view, QMouseEvent& event)
{
    if (m_dragButton == Qt::NoButton) return hover(view, event); // not its drag: the press went elsewhere
    const QPoint position = event.position().toPoint();
    if ((position - m_pressPosition).manhattanLength() >= ClickTolerance) m_dragged = true;
    if (!m_dragged) return true;
    const QPoint delta = position - m_lastPosition;
    m_lastPosition = position;
    core::view::Camera camera = view.camera();
    const bool orbit = m_dragButton == Qt::LeftButton && !(event.modifiers() & Qt::ShiftModifier);
    if (orbit) camera.orbit(-delta.x() * RadiansPerPixel, delta.y() * RadiansPerPixel);
    else camera.pan(delta.x(), delta.y());
    view.setCamera(camera, true);
    return true;
}

bool NavigationTool::mouseRelease(ViewportWidget& view, QMouseEvent& event)
{
    if (event.button() != m_dragButton) return false;
    const bool click = !m_dragged && m_dragButton == Qt::LeftButton;
    m_dragButton = Qt::NoButton;
    m_dragged = false;
    if (!click) return true;
    if (const auto pick = view.pickAt(event.position())) {
        view.setMarker(pick->point);
        Q_EMIT view.pointPicked(pick->point, pick->fragmentId);
    }
    return true;
}

bool NavigationTool::wheel(ViewportWidget& view, QWheelEvent& event)
{
    const double steps = event.angleDelta().y() / 120.0;
    if (steps == 0) return false;
    core::view::Camera camera = view.camera();
    camera.dolly(std::pow(0.85, steps));
    view.setCamera(camera, true);
    return true;
}

bool NavigationTool::keyPress(ViewportWidget& view, QKeyEvent& event)
{
    const bool ctrl = event.modifiers() & Qt::ControlModifier;
    switch (event.key()) {
    case Qt::Key_F:
        if (event.modifiers() & Qt::ShiftModifier) view.fitToSelection();
        else view.fitToScene();
        return true;
    case Qt::Key_1: view.setStandardView(ctrl ? StandardView::Back : StandardView::Front); return true;
    case Qt::Key_3: view.setStandardView(ctrl ? StandardView::Left : StandardView::Right); return true;
    case Qt::Key_7: view.setStandardView(ctrl ? StandardView::Bottom : StandardView::Top); return true;
    case Qt::Key_0: view.setStandardView(StandardView::Iso); return true;
    case Qt::Key_5: view.setOrthographic(!view.camera().isOrthographic()); return true;
    default: return false;
    }
}

} // namespace stylos::widgets
