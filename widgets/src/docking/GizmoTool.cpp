#include "stylos/widgets/docking/GizmoTool.h"

#include "docking/GizmoOverlay.h"
#include "stylos/core/view/GizmoMath.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QKeyEvent>
#include <QMouseEvent>

namespace stylos::widgets {

namespace {

core::view::DragModifiers dragModifiers(Qt::KeyboardModifiers modifiers)
{
    return {.fine = modifiers.testFlag(Qt::ShiftModifier), .precise = modifiers.testFlag(Qt::ControlModifier)};
}

Eigen::Vector2d pixel(const QPointF& p) { return {p.x(), p.y()}; }

} // namespace

GizmoTool::GizmoTool(PoseHandler onPose, FrameHandler onFrame)
    : m_onPose(std::move(onPose)), m_onFrame(std::move(onFrame)), m_overlay(std::make_shared<GizmoOverlay>())
{
}

GizmoTool::~GizmoTool() = default;

void GizmoTool::setTarget(quint64 id, const std::optional<core::view::GizmoTarget>& target)
{
    m_id = target ? id : 0;
    m_target = m_id != 0 ? target : std::nullopt;
    if (!m_target) m_hovered.reset();
    showState(m_view);
}

void GizmoTool::setFrame(core::view::GizmoFrame frame)
{
    if (frame == m_frame) return;
    m_frame = frame;
    m_hovered.reset();
    showState(m_view);
}

core::view::GizmoFrame GizmoTool::effectiveFrame() const
{
    if (m_frame == core::view::GizmoFrame::Drum && !(m_target && m_target->drum)) return core::view::GizmoFrame::World;
    return m_frame;
}

void GizmoTool::setTiltsShown(bool shown)
{
    if (shown == m_tilts) return;
    m_tilts = shown;
    showState(m_view);
}

std::vector<core::view::GizmoHandle> GizmoTool::handles(const core::view::Camera& camera) const
{
    if (!m_target) return {};
    return core::view::visibleGizmoHandles(*m_target, effectiveFrame(), m_tilts, camera);
}

std::optional<core::view::HandleRole> GizmoTool::handleAt(const core::view::Camera& camera, const QPointF& position) const
{
    const auto all = handles(camera);
    const auto index = core::view::pickHandle(all, camera, pixel(position), core::view::GizmoSizes{}.pickRadius);
    if (!index) return std::nullopt;
    return all[*index].role;
}

void GizmoTool::activate(ViewportWidget& view)
{
    m_view = &view;
    view.addOverlay(m_overlay);
    showState(&view);
}

void GizmoTool::deactivate(ViewportWidget& view)
{
    if (m_drag) endDrag(true);
    view.removeOverlay(m_overlay.get());
    view.requestFrame();
    m_view = nullptr;
}

bool GizmoTool::mousePress(ViewportWidget& view, QMouseEvent& event)
{
    if (event.button() != Qt::LeftButton || !m_target || m_drag) return false;
    setTiltsShown(event.modifiers().testFlag(Qt::AltModifier));
    const auto all = handles(view.camera());
    const auto index = core::view::pickHandle(all, view.camera(), pixel(event.position()), core::view::GizmoSizes{}.pickRadius);
    if (!index) return false;
    m_drag = core::view::GizmoDrag::begin(all[*index], view.camera(), pixel(event.position()), m_target->pose);
    if (!m_drag) return false;
    m_dragId = m_id;
    m_lastSent = m_target->pose;
    m_hovered = all[*index].role;
    showState(&view);
    if (m_onDrag) m_onDrag(&*m_drag);
    return true;
}

bool GizmoTool::mouseMove(ViewportWidget&, QMouseEvent& event)
{
    if (!m_drag) return false;
    const auto pose = m_drag->update(pixel(event.position()), dragModifiers(event.modifiers()));
    if (!pose || *pose == m_lastSent) return true;
    // Continuing while the document holds this drag's step: a drag back to the press's pose ends that step
    // (an obsolete merge), and the next pose starts a new one rather than merging into an older step.
    const bool continuing = m_lastSent != m_drag->startPose();
    m_lastSent = *pose;
    if (m_onPose) m_onPose(m_dragId, *pose, continuing);
    if (m_onDrag && m_drag) m_onDrag(&*m_drag); // the owner may have ended the drag (a new target)
    return true;
}

bool GizmoTool::mouseRelease(ViewportWidget& view, QMouseEvent& event)
{
    if (!m_drag) return false;
    if (event.button() == Qt::LeftButton) {
        endDrag(false);
        m_hovered = handleAt(view.camera(), event.position());
        showState(&view);
    }
    return true;
}

bool GizmoTool::hover(ViewportWidget& view, QMouseEvent& event)
{
    const bool tilts = event.modifiers().testFlag(Qt::AltModifier);
    const auto hovered = m_target ? handleAt(view.camera(), event.position()) : std::nullopt;
    if (hovered != m_hovered || tilts != m_tilts) {
        m_hovered = hovered;
        m_tilts = tilts;
        showState(&view);
    }
    return false; // navigation still reports the 3D point under the cursor
}

void GizmoTool::leave(ViewportWidget& view)
{
    if (!m_hovered) return;
    m_hovered.reset();
    showState(&view);
}

bool GizmoTool::keyPress(ViewportWidget& view, QKeyEvent& event)
{
    if (event.key() == Qt::Key_Escape && m_drag) {
        endDrag(true);
        showState(&view);
        return true;
    }
    if (event.key() == Qt::Key_Alt) {
        setTiltsShown(true);
        return false;
    }
    if (event.key() == Qt::Key_L && event.modifiers() == Qt::NoModifier && !m_drag) {
        using core::view::GizmoFrame;
        const bool drum = m_target && m_target->drum;
        const GizmoFrame next = m_frame == GizmoFrame::World      ? GizmoFrame::Fragment
                                : m_frame == GizmoFrame::Fragment ? (drum ? GizmoFrame::Drum : GizmoFrame::World)
                                                                  : GizmoFrame::World;
        setFrame(next);
        if (m_onFrame) m_onFrame(next);
        return true;
    }
    return false;
}

QCursor GizmoTool::cursor() const
{
    return QCursor(m_drag ? Qt::ClosedHandCursor : m_hovered ? Qt::OpenHandCursor : Qt::ArrowCursor);
}

void GizmoTool::endDrag(bool cancel)
{
    if (cancel && m_lastSent != m_drag->startPose() && m_onPose) m_onPose(m_dragId, m_drag->startPose(), true);
    m_drag.reset();
    if (m_onDrag) m_onDrag(nullptr);
}

void GizmoTool::showState(ViewportWidget* view)
{
    GizmoState state;
    state.target = m_target;
    state.frame = effectiveFrame();
    state.tilts = m_tilts;
    state.highlighted = m_drag ? std::optional(m_drag->handle().role) : m_hovered;
    m_overlay->setState(state);
    if (view) view->requestFrame();
}

} // namespace stylos::widgets
