#pragma once
/** @file
 * @brief The 3D view's default tool (ViewportTool): navigation. Left drag orbits about the target, right or
 *        middle drag (or Shift + left) pans, the wheel dollies; a left click (press and release within 4
 *        pixels, Manhattan) picks the surface point under the cursor, marks it (ViewportWidget::setMarker)
 *        and emits ViewportWidget::pointPicked(); moving the cursor with no button held emits
 *        ViewportWidget::cursorMoved() when it is over a surface.
 *        Keys (the numeric keypad works too): F fit to the scene, Shift+F fit to the selection, 1 front,
 *        Ctrl+1 back, 3 right, Ctrl+3 left, 7 top, Ctrl+7 bottom, 0 isometric, 5 perspective/orthographic.
 *
 * Camera moves are continuous moves (ViewportWidget::setCamera(camera, true): the view refines once they
 * stop); the view keys are jumps. It drags only what it pressed: a move or release whose press another
 * tool consumed is not a drag (a move is then treated as a hover). Units: pixels, radians (0.008 per pixel
 * of orbit). GUI thread only.
 */
#include "stylos/widgets/view3d/ViewportTool.h"

#include <QPoint>

namespace stylos::widgets {

class NavigationTool : public ViewportTool {
public:
    bool mousePress(ViewportWidget& view, QMouseEvent& event) override;
    bool mouseMove(ViewportWidget& view, QMouseEvent& event) override;
    bool mouseRelease(ViewportWidget& view, QMouseEvent& event) override;
    bool hover(ViewportWidget& view, QMouseEvent& event) override;
    bool wheel(ViewportWidget& view, QWheelEvent& event) override;
    bool keyPress(ViewportWidget& view, QKeyEvent& event) override;

    /** @brief A drag (orbit or pan) is in progress. */
    bool isDragging() const { return m_dragButton != Qt::NoButton && m_dragged; }

private:
    QPoint m_pressPosition;
    QPoint m_lastPosition;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    bool m_dragged = false;
};

} // namespace stylos::widgets
