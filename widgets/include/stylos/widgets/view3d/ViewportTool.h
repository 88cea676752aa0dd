#pragma once
/** @file
 * @brief What the 3D view does with the mouse, the wheel and the keys: a tool. The view offers each input
 *        event first to the tool set with ViewportWidget::setTool() (a gizmo, a pick tool, an annotation
 *        lasso…), then, when that tool did not consume it, to its NavigationTool (orbit, pan, dolly, click to
 *        pick, the view keys), the default. So a tool takes what it needs and navigation keeps the rest: a
 *        gizmo that consumes a press on its handle, and the moves and release that follow, is dragged while
 *        the camera stays; a press elsewhere orbits.
 *
 * Each handler returns whether it consumed the event. The default implementations consume nothing. Mouse
 * moves come as hover() when no button is held and as mouseMove() otherwise. Positions are the events'
 * (logical pixels of the view, y downwards, as core::view::Camera::rayAt expects). After every event offered
 * and when the tool is set, the view shows the tool's cursor() (navigation's when none is set).
 *
 * A tool acts through the view's public interface (camera(), setCamera(), pickAt(), setMarker(),
 * addOverlay(), requestFrame()…) and never reads the scene document: what it changes goes to the document
 * as undo commands through its owner. GUI thread only.
 */
#include <QCursor>

class QKeyEvent;
class QMouseEvent;
class QWheelEvent;

namespace stylos::widgets {

class ViewportWidget;

class ViewportTool {
public:
    virtual ~ViewportTool() = default;

    /** @brief The tool became the view's tool (setTool()); e.g. add its overlays. */
    virtual void activate(ViewportWidget& view);
    /** @brief The tool stops being the view's tool (another setTool(), resetTool(), the view's destruction). */
    virtual void deactivate(ViewportWidget& view);

    virtual bool mousePress(ViewportWidget& view, QMouseEvent& event);
    /** @brief The mouse moved with a button held. */
    virtual bool mouseMove(ViewportWidget& view, QMouseEvent& event);
    virtual bool mouseRelease(ViewportWidget& view, QMouseEvent& event);
    /** @brief The mouse moved with no button held. */
    virtual bool hover(ViewportWidget& view, QMouseEvent& event);
    /** @brief The mouse left the view (what it pointed at is pointed at no more). */
    virtual void leave(ViewportWidget& view);
    virtual bool wheel(ViewportWidget& view, QWheelEvent& event);
    virtual bool keyPress(ViewportWidget& view, QKeyEvent& event);

    /** @brief The cursor over the view while this tool is set (default: the arrow). */
    virtual QCursor cursor() const;
};

} // namespace stylos::widgets
