#pragma once
/** @file
 * @brief The docking gizmo as a tool of the 3D view (ViewportTool): on the fragment it is given, three arrows
 *        and three rings in the World frame or the Fragment's own frame, or the Drum frame's handles when a
 *        docking drum's axis is known (θ ring about the drum axis, z arrow along it, radial arrow; the two tilt
 *        rings while Alt is held) — core::view::gizmoHandles. A press on a handle (left button) starts a drag
 *        (core::view::GizmoDrag) that it consumes with the moves and the release that follow; a press elsewhere
 *        is left to navigation. Each move that changes the pose hands it to the owner's PoseHandler, the first
 *        with `continuing` false and the others true, so the owner makes the drag one undo step (a drag back to
 *        the press's pose ends that step, and the next pose starts one again); Escape during a drag hands back
 *        the pose of the press (continuing) and ends it. Shift: a tenth of the motion and the
 *        fine step; Ctrl: θ by degrees instead of flutes (see GizmoMath.h). L cycles the frame (World, Fragment,
 *        Drum when there is a drum). Hovering highlights the handle under the cursor (GizmoOverlay).
 *
 * The tool never reads the document: its owner (GizmoController) gives it the target and receives the poses.
 * Poses: fragment frame → scene frame, metres. GUI thread only.
 */
#include "stylos/core/view/GizmoDrag.h"
#include "stylos/core/view/GizmoHandles.h"
#include "stylos/widgets/view3d/ViewportTool.h"

#include <QtGlobal>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace stylos::widgets {

class GizmoOverlay;
struct GizmoState;

class GizmoTool : public ViewportTool {
public:
    /** Receives each pose of a drag: the fragment, its new pose, false for the first step of a drag. */
    using PoseHandler = std::function<void(quint64 id, const Eigen::Matrix4d& pose, bool continuing)>;
    /** Told when the frame changes from the keyboard (L). */
    using FrameHandler = std::function<void(core::view::GizmoFrame frame)>;
    /** Told at a drag's press, at each pose it hands on and at its end (null: the drag ended or was cancelled). */
    using DragObserver = std::function<void(const core::view::GizmoDrag* drag)>;

    explicit GizmoTool(PoseHandler onPose, FrameHandler onFrame = {});
    ~GizmoTool() override;

    /** @brief The fragment @p id to act on; nullopt (or id 0): no gizmo. A running drag keeps its own pose. */
    void setTarget(quint64 id, const std::optional<core::view::GizmoTarget>& target);
    quint64 targetId() const { return m_id; }
    const std::optional<core::view::GizmoTarget>& target() const { return m_target; }
    void setFrame(core::view::GizmoFrame frame);
    core::view::GizmoFrame frame() const { return m_frame; }
    /** @brief The frame the handles follow now: Drum only with a drum axis, World otherwise. */
    core::view::GizmoFrame effectiveFrame() const;
    /** @brief Shows the tilt rings of the Drum frame (what Alt does while held). */
    void setTiltsShown(bool shown);
    bool tiltsShown() const { return m_tilts; }
    /** @brief The handles shown for @p camera (scene frame), as the overlay draws them. */
    std::vector<core::view::GizmoHandle> handles(const core::view::Camera& camera) const;
    std::optional<core::view::HandleRole> hovered() const { return m_hovered; }
    bool isDragging() const { return m_drag.has_value(); }
    /** @brief The drag under way; null when none. */
    const core::view::GizmoDrag* drag() const { return m_drag ? &*m_drag : nullptr; }
    void setDragObserver(DragObserver observer) { m_onDrag = std::move(observer); }

    void activate(ViewportWidget& view) override;
    void deactivate(ViewportWidget& view) override;
    bool mousePress(ViewportWidget& view, QMouseEvent& event) override;
    bool mouseMove(ViewportWidget& view, QMouseEvent& event) override;
    bool mouseRelease(ViewportWidget& view, QMouseEvent& event) override;
    bool hover(ViewportWidget& view, QMouseEvent& event) override;
    /** No handle is under the mouse once it left the view: none stays highlighted (a drag keeps its own). */
    void leave(ViewportWidget& view) override;
    bool keyPress(ViewportWidget& view, QKeyEvent& event) override;
    QCursor cursor() const override;

private:
    std::optional<core::view::HandleRole> handleAt(const core::view::Camera& camera, const QPointF& position) const;
    /** Ends the drag; @p cancel: the pose of the press goes back to the owner first. */
    void endDrag(bool cancel);
    void showState(ViewportWidget* view);

    PoseHandler m_onPose;
    FrameHandler m_onFrame;
    DragObserver m_onDrag;
    std::shared_ptr<GizmoOverlay> m_overlay;
    ViewportWidget* m_view = nullptr;   ///< while active
    quint64 m_id = 0;
    std::optional<core::view::GizmoTarget> m_target;
    core::view::GizmoFrame m_frame = core::view::GizmoFrame::World;
    bool m_tilts = false;
    std::optional<core::view::HandleRole> m_hovered;
    std::optional<core::view::GizmoDrag> m_drag;
    quint64 m_dragId = 0;
    Eigen::Matrix4d m_lastSent = Eigen::Matrix4d::Identity(); ///< the pose last handed to the owner in this drag
};

} // namespace stylos::widgets
