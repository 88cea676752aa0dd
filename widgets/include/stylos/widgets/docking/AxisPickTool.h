#pragma once
/** @file
 * @brief "Set axis from two points" as a tool of the 3D view (ViewportTool): two clicks on the surface of the
 *        fragment it is given (a press and a release within 4 pixels, as ViewportWidget::pickAt() finds that
 *        fragment under the cursor) pick the two points of the axis, each shown by a marker (a ring facing the
 *        eye, the line between them once both are in); the second hands both to its owner (scene frame), which
 *        sets the guide (AxisGuideEditor). A click elsewhere, or a drag, is left to navigation (orbit, pan);
 *        Escape cancels (the owner is told). The tool never reads the document. GUI thread only.
 */
#include "stylos/widgets/view3d/ViewportTool.h"

#include <Eigen/Core>

#include <QPointF>
#include <QtGlobal>

#include <functional>
#include <memory>
#include <vector>

namespace stylos::widgets {

class AxisPickOverlay;

class AxisPickTool : public ViewportTool {
public:
    /** Receives the two points (scene frame) of fragment @p id. */
    using PickedHandler = std::function<void(quint64 id, const Eigen::Vector3d& a, const Eigen::Vector3d& b)>;
    using CancelHandler = std::function<void()>;

    AxisPickTool(quint64 fragment, PickedHandler onPicked, CancelHandler onCancel);
    ~AxisPickTool() override;

    quint64 fragment() const { return m_fragment; }
    /** @brief The points picked so far (0 or 1 before the handler runs), scene frame. */
    const std::vector<Eigen::Vector3d>& points() const { return m_points; }

    void activate(ViewportWidget& view) override;
    void deactivate(ViewportWidget& view) override;
    bool mousePress(ViewportWidget& view, QMouseEvent& event) override;
    bool mouseRelease(ViewportWidget& view, QMouseEvent& event) override;
    bool keyPress(ViewportWidget& view, QKeyEvent& event) override;
    QCursor cursor() const override;

private:
    quint64 m_fragment;
    PickedHandler m_onPicked;
    CancelHandler m_onCancel;
    std::shared_ptr<AxisPickOverlay> m_overlay;
    std::vector<Eigen::Vector3d> m_points;
    QPointF m_press;
    bool m_pressed = false;
};

} // namespace stylos::widgets
