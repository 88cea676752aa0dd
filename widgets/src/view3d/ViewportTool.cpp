#include "stylos/widgets/view3d/ViewportTool.h"

namespace stylos::widgets {

// Nothing is consumed unless a tool says so: the view then offers the event to navigation.
void ViewportTool::activate(ViewportWidget&) {}
void ViewportTool::deactivate(ViewportWidget&) {}
bool ViewportTool::mousePress(ViewportWidget&, QMouseEvent&) { return false; }
bool ViewportTool::mouseMove(ViewportWidget&, QMouseEvent&) { return false; }
bool ViewportTool::mouseRelease(ViewportWidget&, QMouseEvent&) { return false; }
bool ViewportTool::hover(ViewportWidget&, QMouseEvent&) { return false; }
void ViewportTool::leave(ViewportWidget&) {}
bool ViewportTool::wheel(ViewportWidget&, QWheelEvent&) { return false; }
bool ViewportTool::keyPress(ViewportWidget&, QKeyEvent&) { return false; }
QCursor ViewportTool::cursor() const { return QCursor(Qt::ArrowCursor); }

} // namespace stylos::widgets
