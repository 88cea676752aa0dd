#pragma once
// The mouse wheel over a field that does not have the keyboard focus scrolls what holds the field (a dock, a
// table) instead of changing its value: a spin box or a combo box met by the wheel while the user scrolls the
// Properties dock used to move the selected fragment or change a hatch, one undo step per notch, unseen.
class QWidget;

namespace stylos::widgets {

/** Gives @p field the focus by click and Tab only (not by the wheel), and passes the wheel on to its parents while
 *  it lacks the focus; with the focus (clicked or tabbed into) the wheel steps it as before. */
void guardWheel(QWidget* field);

} // namespace stylos::widgets
