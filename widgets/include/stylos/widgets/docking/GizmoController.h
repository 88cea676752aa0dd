#pragma once
/** @file
 * @brief Connects the docking gizmo (GizmoTool) to the scene document: installs the tool on the 3D view
 *        ("Move tool") and removes it, gives it the current fragment's pose, centre and, when a docking drum
 *        is set (SceneDocument::setDockingDrum), the drum's axis and flute pitch (core::view::drumAxisOf) —
 *        again after every change of the document — and turns each pose the tool hands back into
 *        SceneDocument::setFragmentPose (`continuing` within a drag: one undo step a drag), and says what the
 *        drag has done so far (dragReadout()). Setting a docking drum switches the gizmo to the Drum frame.
 *        GUI thread only.
 */
#include "stylos/core/view/GizmoHandles.h"
#include "stylos/widgets/document/SceneDocument.h"

#include <QObject>
#include <QPointer>

#include <memory>

namespace stylos::widgets {

class FragmentBounds;
class GizmoTool;
class ViewportWidget;

class GizmoController : public QObject {
    Q_OBJECT

public:
    using FragmentId = SceneDocument::FragmentId;

    /** None owned; @p document must outlive this; @p view may go first. */
    GizmoController(SceneDocument& document, ViewportWidget& view, QObject* parent = nullptr);
    ~GizmoController() override;

    /** @brief The fragment the gizmo acts on (the current selection); NoFragment: none. */
    void setFragment(FragmentId id);
    FragmentId fragment() const { return m_fragment; }
    /** @brief Installs the gizmo as the view's tool (true) or gives the view back to navigation (false). */
    void setEnabled(bool enabled);
    /** @brief True while the gizmo is the view's tool. */
    bool isEnabled() const { return tool() != nullptr; }
    void setFrame(core::view::GizmoFrame frame);
    core::view::GizmoFrame frame() const { return m_frame; }
    /** @brief The installed tool; null when the view has another tool or none. */
    GizmoTool* tool() const;

Q_SIGNALS:
    void enabledChanged(bool enabled);
    /** @brief The frame changed (the menu, L in the view, a docking drum set); @p frame: a core::view::GizmoFrame. */
    void frameChanged(int frame);
    /** @brief What the drag under way has done (GizmoReadout: "Along the drum axis: +12.0 mm · Esc cancels"), at
     *         its press and each step; empty when it ends. */
    void dragReadout(const QString& text);

private:
    void refresh();

    SceneDocument& m_document;
    QPointer<ViewportWidget> m_view;
    GizmoTool* m_tool = nullptr;  ///< owned by the view while installed
    FragmentId m_fragment = core::scene::NoFragment;
    core::view::GizmoFrame m_frame = core::view::GizmoFrame::World;
    std::unique_ptr<FragmentBounds> m_bounds;
};

} // namespace stylos::widgets
