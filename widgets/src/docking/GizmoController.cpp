#include "stylos/widgets/docking/GizmoController.h"

#include "docking/FragmentBounds.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/view/GuideGeometry.h"
#include "stylos/widgets/docking/GizmoReadout.h"
#include "stylos/widgets/docking/GizmoTool.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

namespace stylos::widgets {

GizmoController::GizmoController(SceneDocument& document, ViewportWidget& view, QObject* parent)
    : QObject(parent), m_document(document), m_view(&view), m_bounds(std::make_unique<FragmentBounds>())
{
    connect(&document, &SceneDocument::fragmentChanged, this, &GizmoController::refresh);
    connect(&document, &SceneDocument::fragmentRemoved, this, [this](quint64 id) {
        if (id == m_fragment) m_fragment = core::scene::NoFragment;
        refresh();
    });
    connect(&document, &SceneDocument::octreeChanged, this, &GizmoController::refresh);
    connect(&document, &SceneDocument::sceneReset, this, [this] {
        m_fragment = core::scene::NoFragment;
        refresh();
    });
    connect(&document, &SceneDocument::dockingDrumChanged, this, [this](quint64 id) {
        if (id != core::scene::NoFragment) setFrame(core::view::GizmoFrame::Drum);
        refresh();
    });
}

GizmoController::~GizmoController()
{
    // The view (which may live on) owns the tool: no drag of it may reach this controller once it is gone.
    if (GizmoTool* t = tool()) {
        t->setDragObserver({});
        m_view->resetTool();
    }
}

GizmoTool* GizmoController::tool() const
{
    return m_view && m_tool && m_view->tool() == m_tool ? m_tool : nullptr;
}

void GizmoController::setFragment(FragmentId id)
{
    if (id == m_fragment) return;
    m_fragment = id;
    refresh();
}

void GizmoController::setEnabled(bool enabled)
{
    if (!m_view || enabled == isEnabled()) return;
    if (!enabled) {
        m_view->resetTool();
        m_tool = nullptr;
        Q_EMIT enabledChanged(false);
        return;
    }
    auto tool = std::make_unique<GizmoTool>(
        [this](quint64 id, const Eigen::Matrix4d& pose, bool continuing) {
            m_document.setFragmentWorldPose(id, core::scene::poseFromEigen(pose), continuing);
        },
        [this](core::view::GizmoFrame frame) {
            m_frame = frame;
            Q_EMIT frameChanged(int(frame));
        });
    tool->setFrame(m_frame);
    tool->setDragObserver([this, t = tool.get()](const core::view::GizmoDrag* drag) {
        if (!drag) {
            Q_EMIT dragReadout(QString());
            return;
        }
        const auto& target = t->target();
        const double pitch = target && target->drum ? target->drum->pitch : 0.0;
        Q_EMIT dragReadout(GizmoReadout::text(drag->handle().role, t->effectiveFrame(), drag->value(), pitch));
    });
    m_tool = tool.get();
    m_view->setTool(std::move(tool));
    refresh();
    Q_EMIT enabledChanged(true);
}

void GizmoController::setFrame(core::view::GizmoFrame frame)
{
    if (frame == m_frame) return;
    m_frame = frame;
    if (GizmoTool* t = tool()) t->setFrame(frame);
    Q_EMIT frameChanged(int(frame));
}

void GizmoController::refresh()
{
    GizmoTool* t = tool();
    if (!t) return;
    const core::scene::Fragment* f = m_document.fragment(m_fragment);
    const Eigen::AlignedBox3d bounds = f ? m_bounds->of(m_document, m_fragment) : Eigen::AlignedBox3d();
    if (!f || bounds.isEmpty()) {
        t->setTarget(0, std::nullopt);
        return;
    }
    core::view::GizmoTarget target;
    target.pose = core::scene::toEigen(m_document.worldPose(m_fragment));
    target.localCentre = bounds.center();
    const FragmentId drumId = m_document.drumFor(m_fragment);
    if (const core::scene::Fragment* drum = m_document.fragment(drumId); drum && drumId != m_fragment) {
        const core::scene::Pose world = m_document.worldPose(drumId);
        target.drum = core::view::drumAxisOf(*drum, &world);
    }
    t->setTarget(m_fragment, target);
}

} // namespace stylos::widgets
