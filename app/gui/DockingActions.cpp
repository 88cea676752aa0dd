#include "DockingActions.h"

#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/view/GuideGeometry.h"
#include "stylos/widgets/docking/AxisGuideEditor.h"
#include "stylos/widgets/docking/ContactMonitor.h"
#include "stylos/widgets/docking/DockRunner.h"
#include "stylos/widgets/docking/DrumGuidesCache.h"
#include "stylos/widgets/docking/GizmoController.h"
#include "stylos/widgets/docking/GuideFitRunner.h"
#include "stylos/widgets/docking/GuidesDisplay.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QLocale>
#include <QAction>
#include <QActionGroup>
#include <QMenu>

namespace stylos::app {

DockingActions::DockingActions(widgets::SceneDocument& document, widgets::ViewportWidget* viewport, QWidget& window)
    : QObject(&window), m_document(document), m_fits(new widgets::GuideFitRunner(document, this)),
      m_cache(new widgets::DrumGuidesCache(document, this)), m_docker(new widgets::DockRunner(document, *m_cache, this)),
      m_contact(new widgets::ContactMonitor(document, *m_cache, this)), m_moveTool(new QAction(this)),
      m_frames(new QActionGroup(this)), m_dockAgainst(new QAction(this)), m_dockToFlutes(new QAction(this)),
      m_fitGuides(new QAction(this)), m_setAxis(new QAction(this)), m_editAxis(new QAction(this)),
      m_reverseAxis(new QAction(this)),
      m_axisEditor(new widgets::AxisGuideEditor(document, viewport, this)), m_window(window),
      m_deleteGuides(new QAction(this)), m_showGuides(new QAction(this))
{
    m_moveTool->setObjectName(QStringLiteral("actionMoveTool"));
    m_dockAgainst->setObjectName(QStringLiteral("actionDockAgainst"));
    m_fitGuides->setObjectName(QStringLiteral("actionFitGuides"));
    m_deleteGuides->setObjectName(QStringLiteral("actionDeleteGuides"));
    m_showGuides->setObjectName(QStringLiteral("actionShowGuides"));
    m_moveTool->setCheckable(true);
    m_moveTool->setShortcut(QKeySequence(Qt::Key_W));
    m_showGuides->setCheckable(true);
    m_showGuides->setChecked(true);
    for (int frame = 0; frame < 3; ++frame) {
        QAction* action = m_frames->addAction(QString());
        action->setCheckable(true);
        action->setData(frame);
        action->setChecked(frame == 0);
    }

    if (viewport) {
        m_gizmo = new widgets::GizmoController(document, *viewport, this);
        m_guides = new widgets::GuidesDisplay(document, *viewport, this);
        // A single key acts only while the 3D view has the focus.
        m_moveTool->setShortcutContext(Qt::WidgetShortcut);
        viewport->addAction(m_moveTool);
        connect(m_moveTool, &QAction::toggled, m_gizmo, &widgets::GizmoController::setEnabled);
        connect(m_gizmo, &widgets::GizmoController::enabledChanged, m_moveTool, &QAction::setChecked);
        connect(m_frames, &QActionGroup::triggered, m_gizmo, [this](QAction* action) {
            m_gizmo->setFrame(static_cast<core::view::GizmoFrame>(action->data().toInt()));
        });
        connect(m_gizmo, &widgets::GizmoController::frameChanged, this, [this](int frame) {
            for (QAction* action : m_frames->actions()) action->setChecked(action->data().toInt() == frame);
        });
        connect(m_showGuides, &QAction::toggled, m_guides, &widgets::GuidesDisplay::setVisible);
    }
    connect(m_dockAgainst, &QAction::triggered, this, [this] {
        m_document.setDockingDrum(m_fragment);
        if (const auto* f = m_document.fragment(m_fragment))
            Q_EMIT reported(tr("Docking against %1").arg(QString::fromStdString(f->name)), false);
    });
    connect(m_fitGuides, &QAction::triggered, this, [this] {
        if (!m_fits->start(m_fragment))
            Q_EMIT reported(tr("The guides of this fragment are being fitted already, or its octree is not open yet"), false);
    });
    connect(m_deleteGuides, &QAction::triggered, this, [this] { m_fits->deleteGuides(m_fragment); });
    connect(m_fits, &widgets::GuideFitRunner::fitted, this, [this](quint64 id, const widgets::GuideFitResult& r) {
        const auto* f = m_document.fragment(id);
        Q_EMIT reported(tr("Guides of %1: %2 flutes, leading radius %3 mm, flute depth %4 mm, RMS %5 mm, %6 s")
                            .arg(f ? QString::fromStdString(f->name) : r.octreePath)
                            .arg(r.flutes)
                            .arg(QLocale().toString(r.radius * 1e3, 'f', 2))
                            .arg(QLocale().toString(r.fluteDepth * 1e3, 'f', 2))
                            .arg(QLocale().toString(r.rms * 1e3, 'f', 2))
                            .arg(QLocale().toString(r.seconds, 'f', 1)),
                        false);
    });
    connect(m_fits, &widgets::GuideFitRunner::failed, this,
            [this](quint64, const QString& message) { Q_EMIT reported(message, true); });
    connect(m_fits, &widgets::GuideFitRunner::cancelled, this,
            [this](quint64, const QString& message) { Q_EMIT reported(message, false); });
    createDocking();
    createAxisEditing(viewport);
    connect(&document, &widgets::SceneDocument::fragmentChanged, this, &DockingActions::updateEnabled);
    connect(&document, &widgets::SceneDocument::dockingDrumChanged, this, &DockingActions::updateEnabled);
    connect(&document, &widgets::SceneDocument::structureChanged, this, &DockingActions::updateEnabled);
    connect(&document, &widgets::SceneDocument::assemblyChanged, this, &DockingActions::updateEnabled);
    updateEnabled();
    retranslateUi();
}

DockingActions::~DockingActions() = default;

void DockingActions::createDocking()
{
    using core::dock::DockUnknown;
    m_dockToFlutes->setObjectName(QStringLiteral("actionDockToFlutes"));
    m_dockToFlutes->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_J));
    const std::vector<std::vector<DockUnknown>> locks = {
        {DockUnknown::Z}, {DockUnknown::R}, {DockUnknown::Theta, DockUnknown::Tangent}, {DockUnknown::TiltLean, DockUnknown::TiltRoll}};
    for (const auto& unknowns : locks) {
        auto* action = new QAction(this);
        action->setCheckable(true);
        action->setObjectName(QStringLiteral("actionLock_%1").arg(QString::fromLatin1(core::dock::dockUnknownName(unknowns[0]))));
        connect(action, &QAction::toggled, this, [this, unknowns](bool on) {
            for (DockUnknown u : unknowns) m_docker->setLocked(u, on);
        });
        m_locks.append(action);
    }
    connect(m_dockToFlutes, &QAction::triggered, this, [this] {
        if (!m_docker->start(m_fragment))
            Q_EMIT reported(tr("This fragment is being docked already, or its octree or the drum's is not open yet"), false);
    });
    connect(m_docker, &widgets::DockRunner::docked, this, [this](quint64 id, const widgets::DockJobResult& r) {
        const auto* f = m_document.fragment(id);
        Q_EMIT reported(widgets::DockJob::summary(f ? QString::fromStdString(f->name) : QString(), r), false);
    });
    connect(m_docker, &widgets::DockRunner::failed, this,
            [this](quint64, const QString& message) { Q_EMIT reported(message, true); });
    connect(m_docker, &widgets::DockRunner::cancelled, this,
            [this](quint64, const QString& message) { Q_EMIT reported(message, false); });
    connect(&m_document, &widgets::SceneDocument::fragmentRemoved, this, &DockingActions::updateEnabled);
}

void DockingActions::createAxisEditing(widgets::ViewportWidget* viewport)
{
    m_setAxis->setObjectName(QStringLiteral("actionSetAxisFromPoints"));
    m_editAxis->setObjectName(QStringLiteral("actionEditAxis"));
    connect(m_setAxis, &QAction::triggered, this, [this, viewport] {
        m_moveTool->setChecked(false); // the pick tool takes the view's tool from the gizmo
        if (viewport) viewport->setFocus();
        m_axisEditor->startPicking(m_fragment);
    });
    connect(m_editAxis, &QAction::triggered, this, [this] { m_axisEditor->editAxis(m_fragment, &m_window); });
    m_reverseAxis->setObjectName(QStringLiteral("actionReverseAxis"));
    connect(m_reverseAxis, &QAction::triggered, this, [this] { m_axisEditor->reverseAxis(m_fragment); });
    connect(m_axisEditor, &widgets::AxisGuideEditor::reported, this, &DockingActions::reported);
}

void DockingActions::populate(QMenu& tools, QMenu& view)
{
    tools.addSeparator();
    tools.addAction(m_moveTool);
    m_frameMenu = tools.addMenu(QString());
    m_frameMenu->setObjectName(QStringLiteral("menuGizmoFrame"));
    m_frameMenu->addActions(m_frames->actions());
    tools.addAction(m_dockAgainst);
    tools.addAction(m_dockToFlutes);
    m_lockMenu = tools.addMenu(QString());
    m_lockMenu->setObjectName(QStringLiteral("menuDockingLocks"));
    m_lockMenu->addActions(m_locks);
    tools.addSeparator();
    tools.addAction(m_fitGuides);
    tools.addAction(m_setAxis);
    tools.addAction(m_editAxis);
    tools.addAction(m_reverseAxis);
    tools.addAction(m_deleteGuides);
    view.addAction(m_showGuides);
    retranslateUi();
}

void DockingActions::setFragment(core::scene::FragmentId id)
{
    m_fragment = id;
    if (m_gizmo) m_gizmo->setFragment(id);
    m_contact->setFragment(id);
    updateEnabled();
}

void DockingActions::updateEnabled()
{
    const core::scene::Fragment* f = m_document.fragment(m_fragment);
    m_moveTool->setEnabled(m_gizmo != nullptr);
    m_frames->setEnabled(m_gizmo != nullptr);
    m_showGuides->setEnabled(m_guides != nullptr);
    m_dockAgainst->setEnabled(f && core::view::drumAxisOf(*f).has_value());
    m_dockToFlutes->setEnabled(m_docker->canDock(m_fragment));
    m_fitGuides->setEnabled(f != nullptr);
    m_setAxis->setEnabled(f != nullptr && m_gizmo != nullptr);
    m_editAxis->setEnabled(f != nullptr);
    m_reverseAxis->setEnabled(f && core::scene::firstGuide(*f, core::scene::GuideKind::Axis).has_value());
    m_deleteGuides->setEnabled(f && !f->guides.empty());
}

void DockingActions::retranslateUi()
{
    m_moveTool->setText(tr("&Move tool"));
    m_moveTool->setStatusTip(tr("Move the selected fragment with arrows and rings in the 3D view; Shift: finer, "
                                "Ctrl: by degrees, Alt: tilts, L: the next frame, Escape: cancel the drag"));
    if (m_frameMenu) m_frameMenu->setTitle(tr("Gizmo &frame"));
    const QStringList frames = {tr("&World"), tr("&Fragment"), tr("&Drum")};
    for (QAction* action : m_frames->actions()) action->setText(frames.value(action->data().toInt()));
    m_dockAgainst->setText(tr("Dock against this &drum"));
    m_dockAgainst->setStatusTip(tr("Use the axis and flutes of the selected fragment for the gizmo's Drum frame"));
    m_dockToFlutes->setText(tr("Dock to &flutes"));
    m_dockToFlutes->setStatusTip(tr("Snap the selected fragment onto the nearest flutes of the docking drum and refine "
                                    "its pose against them (one undo step)"));
    if (m_lockMenu) m_lockMenu->setTitle(tr("Docking &locks"));
    const QStringList locks = {tr("Lock &z (along the axis)"), tr("Lock &r (radial)"), tr("Lock &θ (about the axis)"),
                               tr("Lock &tilts")};
    for (int i = 0; i < m_locks.size(); ++i) m_locks[i]->setText(locks.value(i));
    m_fitGuides->setText(tr("Fit drum &guides"));
    m_fitGuides->setStatusTip(tr("Fit the axis and the flute lines of the selected drum in the background"));
    m_setAxis->setText(tr("Set &axis from two points"));
    m_setAxis->setStatusTip(tr("Click two points on the selected fragment in the 3D view: its axis guide goes through "
                               "them (Escape cancels)"));
    m_editAxis->setText(tr("&Edit axis…"));
    m_editAxis->setStatusTip(tr("Type the point and direction of the selected fragment's axis guide"));
    m_reverseAxis->setText(tr("&Reverse axis"));
    m_reverseAxis->setStatusTip(tr("Turn the selected fragment's axis guide end for end: a drum lying on its side "
                                   "whose développée came out upside down unrolls the right way up"));
    m_deleteGuides->setText(tr("De&lete guides"));
    m_deleteGuides->setStatusTip(tr("Remove the axis and flute guides of the selected fragment"));
    m_showGuides->setText(tr("Show &guides"));
}

} // namespace stylos::app
