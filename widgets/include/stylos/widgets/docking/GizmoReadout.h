#pragma once
/** @file
 * @brief What a gizmo drag has done so far, in words for the status bar: the handle and the snapped amount
 *        ("Along the drum axis: +12.0 mm", "About the drum axis: +22.50° (3 flutes)"), in the interface's
 *        language and number format, with the key that cancels. GUI thread only.
 */
#include "stylos/core/view/GizmoHandles.h"

#include <QCoreApplication>
#include <QString>

namespace stylos::widgets {

class GizmoReadout {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::GizmoReadout)

public:
    /**
     * @brief The readout of a drag of @p role in @p frame by @p value (metres for an arrow, radians for a ring,
     *        as core::view::GizmoDrag::value()). Millimetres to 0.1 mm, degrees to 0.01°, signed; the drum's θ
     *        also in flutes when @p pitch (radians; 0: no flutes) divides it.
     */
    static QString text(core::view::HandleRole role, core::view::GizmoFrame frame, double value, double pitch);
};

} // namespace stylos::widgets
