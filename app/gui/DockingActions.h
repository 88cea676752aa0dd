#pragma once
/** @file
 * @brief The docking actions: Tools › Move tool (the gizmo, W in the 3D view), Gizmo frame (World, Fragment,
 *        Drum; L in the view cycles them), Dock against this drum, Dock to flutes (Ctrl+J) and its Docking locks
 *        (z, r, θ, tilts), Fit drum guides, Set axis from two points, Edit axis…, Delete guides; View › Show guides. They act on the current fragment
 *        through the widgets' GizmoController, DockRunner, GuideFitRunner and GuidesDisplay, and keep its contact
 *        readout (ContactMonitor, shown by the Properties dock) on it; results and failures of the fits and docks
 *        go out as reported() for the window's log. GUI thread only.
 */
#include "stylos/core/scene/Fragment.h"

#include <QList>
#include <QObject>
#include <QString>

class QAction;
class QActionGroup;
class QMenu;
class QWidget;

namespace stylos::widgets {
class AxisGuideEditor;
class ContactMonitor;
class DockRunner;
class DrumGuidesCache;
class GizmoController;
class GuideFitRunner;
class GuidesDisplay;
class SceneDocument;
class ViewportWidget;
} // namespace stylos::widgets

namespace stylos::app {

class DockingActions : public QObject {
    Q_OBJECT

public:
    /** None owned. Without a 3D view (@p viewport null) the gizmo and guide display actions are disabled. */
    DockingActions(widgets::SceneDocument& document, widgets::ViewportWidget* viewport, QWidget& window);
    ~DockingActions() override;

    /** @brief Adds the actions to the Tools menu and Show guides to the View menu. */
    void populate(QMenu& tools, QMenu& view);
    /** @brief The fragment the actions act on (the current selection; NoFragment: none). */
    void setFragment(core::scene::FragmentId id);
    void retranslateUi();

    widgets::GizmoController* gizmo() const { return m_gizmo; }
    widgets::GuidesDisplay* guides() const { return m_guides; }
    widgets::GuideFitRunner& guideFits() const { return *m_fits; }
    widgets::DockRunner& docker() const { return *m_docker; }
    widgets::ContactMonitor& contact() const { return *m_contact; }
    /** @brief The drums' fitted guides (the développée's unrolling radius comes from them too). */
    widgets::DrumGuidesCache& guidesCache() const { return *m_cache; }
    QAction* moveToolAction() const { return m_moveTool; }
    QAction* fitGuidesAction() const { return m_fitGuides; }
    QAction* setAxisAction() const { return m_setAxis; }
    QAction* editAxisAction() const { return m_editAxis; }
    QAction* reverseAxisAction() const { return m_reverseAxis; }
    widgets::AxisGuideEditor& axisEditor() const { return *m_axisEditor; }
    QAction* showGuidesAction() const { return m_showGuides; }
    QAction* dockToFlutesAction() const { return m_dockToFlutes; }
    /** @brief The lock actions: z, r, θ, tilts (checkable). */
    const QList<QAction*>& lockActions() const { return m_locks; }

Q_SIGNALS:
    /** @brief A message for the log (and, when @p failed, a box). */
    void reported(const QString& message, bool failed);

private:
    void updateEnabled();
    void createDocking();
    void createAxisEditing(widgets::ViewportWidget* viewport);

    widgets::SceneDocument& m_document;
    widgets::GizmoController* m_gizmo = nullptr;
    widgets::GuidesDisplay* m_guides = nullptr;
    widgets::GuideFitRunner* m_fits;
    widgets::DrumGuidesCache* m_cache;
    widgets::DockRunner* m_docker;
    widgets::ContactMonitor* m_contact;
    core::scene::FragmentId m_fragment = core::scene::NoFragment;
    QMenu* m_frameMenu = nullptr;
    QAction* m_moveTool;
    QActionGroup* m_frames;
    QAction* m_dockAgainst;
    QAction* m_dockToFlutes;
    QMenu* m_lockMenu = nullptr;
    QList<QAction*> m_locks;
    QAction* m_fitGuides;
    QAction* m_setAxis;
    QAction* m_editAxis;
    QAction* m_reverseAxis;
    widgets::AxisGuideEditor* m_axisEditor;
    QWidget& m_window;
    QAction* m_deleteGuides;
    QAction* m_showGuides;
};

} // namespace stylos::app
