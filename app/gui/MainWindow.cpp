#include "MainWindow.h"

#include "AnnotationActions.h"
#include "AnnotationSync.h"
#include "DeveloppeeLink.h"
#include "DeveloppeeDock.h"
#include "LegendDock.h"
#include "AssemblyActions.h"
#include "DockingActions.h"
#include "LogDock.h"
#include "MainActions.h"
#include "PlateActions.h"
#include "ProjectActions.h"
#include "PropertiesDock.h"
#include "SceneDock.h"
#include "TasksDock.h"
#include "UndoShortcuts.h"
#include "StatusMessage.h"
#include "StatusReadout.h"
#include "ToolBarRows.h"
#include "Translations.h"
#include "ViewportSync.h"
#include "DisplaySettingsWidget.h"
#include "stylos/widgets/annotation/ClassMeasures.h"
#include "stylos/widgets/annotation/DeveloppeeAnnotator.h"
#include "stylos/widgets/annotation/LegendWidget.h"
#include "stylos/widgets/annotation/PaintToolBar.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/docking/GizmoController.h"
#include "stylos/widgets/document/DemoScene.h"
#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/developpee/DeveloppeeSettings.h"
#include "stylos/widgets/document/ScanImporter.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/document/SceneTreeModel.h"
#include "stylos/widgets/skydome/SkydomeRunner.h"
#include "stylos/widgets/tasks/TaskManager.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <algorithm>

#include <QLocale>
#include <QCloseEvent>
#include <QDir>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>
#include <QStatusTipEvent>
#include <QToolBar>
#include <QTreeView>
#include <QUndoStack>

#include <memory>

namespace stylos::app {

namespace {
const auto GeometryKey = QStringLiteral("mainWindow/geometry");
const auto StateKey = QStringLiteral("mainWindow/state");
} // namespace

MainWindow::MainWindow(Translations& translations, const QString& demoDirectory, QWidget* parent)
    : QMainWindow(parent), m_translations(translations), m_tasks(new widgets::TaskManager(this)),
      m_document(new widgets::SceneDocument(*m_tasks, this)),
      m_importer(new widgets::ScanImporter(*m_document, *m_tasks, this)),
      m_demo(new widgets::DemoScene(*m_tasks, demoDirectory, this)),
      m_skydome(new widgets::SkydomeRunner(*m_document, this))
{
    setObjectName(QStringLiteral("MainWindow"));
    setAcceptDrops(true);
    setDockNestingEnabled(true);
    if (widgets::ViewportWidget::isSupported()) {
        m_viewport = new widgets::ViewportWidget(this);
        m_viewport->setObjectName(QStringLiteral("viewport"));
        m_viewport->setFocusPolicy(Qt::StrongFocus);
        setCentralWidget(m_viewport);
        m_sync = new ViewportSync(*m_document, *m_viewport, this);
        m_annotationSync = new AnnotationSync(*m_document, *m_viewport, this);
    } else {
        auto* message = new QLabel(this);
        message->setObjectName(QStringLiteral("noViewport"));
        message->setAlignment(Qt::AlignCenter);
        message->setWordWrap(true);
        setCentralWidget(message);
    }
    m_message = new StatusMessage(this);
    statusBar()->addWidget(m_message, 1);
    createDocks();
    createMenus();
    connectDocument();

    m_readout = new StatusReadout(this);
    statusBar()->addPermanentWidget(m_readout);
    if (m_viewport) {
        connect(m_viewport, &widgets::ViewportWidget::cursorMoved, m_readout, &StatusReadout::setCursor3d);
        connect(m_viewport, &widgets::ViewportWidget::frameTimeChanged, m_readout, &StatusReadout::setFrameTime);
        connect(m_viewport, &widgets::ViewportWidget::pointsDrawn, m_readout, &StatusReadout::setPointsDrawn);
        connect(m_viewport, &widgets::ViewportWidget::pointPicked, this, [this](const Eigen::Vector3d& p, quint64 id) {
            const auto* f = m_document->fragment(id);
            m_message->showMessage(tr("%1 on %2").arg(StatusReadout::formatPoint(p),
                                                        f ? QString::fromStdString(f->name) : QString()));
            m_picked = {id, m_message->message()};
        });
        // A picked point's line goes with its fragment (removed, or a new or another project opened).
        const auto forgetPick = [this](quint64 id) {
            if (m_picked.first == 0 || (id != 0 && id != m_picked.first)) return;
            if (m_message->message() == m_picked.second) m_message->clearMessage();
            m_picked = {};
        };
        connect(m_document, &widgets::SceneDocument::sceneAboutToBeReset, this, [forgetPick] { forgetPick(0); });
        connect(m_document, &widgets::SceneDocument::fragmentAboutToBeRemoved, this, forgetPick);
    }

    QSettings settings;
    if (!restoreGeometry(settings.value(GeometryKey).toByteArray())) resize(1280, 800);
    restoreState(settings.value(StateKey).toByteArray());
    retranslateUi();
    updateTitle();
}

MainWindow::~MainWindow()
{
    // The workers must not outlive the document they report to.
    m_tasks->cancelAllAndWait();
}

void MainWindow::createDocks()
{
    m_sceneDock = new SceneDock(*m_document, this);
    addDockWidget(Qt::LeftDockWidgetArea, m_sceneDock);
    m_propertiesDock = new PropertiesDock(*m_document, m_viewport, this);
    addDockWidget(Qt::LeftDockWidgetArea, m_propertiesDock);

    m_developpeeDock = new DeveloppeeDock(this);
    // A développée is wide (a drum's circumference by its height): it gets the bottom, under the 3D view.
    addDockWidget(Qt::BottomDockWidgetArea, m_developpeeDock);
    m_developpeeLink = new DeveloppeeLink(*m_document, m_developpeeDock->panel(), m_viewport, this);
    connect(m_developpeeLink, &DeveloppeeLink::finished, this, &MainWindow::report);

    // Annotation: the développée paints the document's labels; the Legend dock chooses the class and edits it.
    widgets::DeveloppeeView& developpeeView = *m_developpeeDock->panel().view();
    m_annotator = new widgets::DeveloppeeAnnotator(*m_document, developpeeView, this);
    m_developpeeDock->panel().setPaintBar(new widgets::PaintToolBar(*m_document, *m_annotator, developpeeView));
    // A stroke on an assembly's développée that is out of date: say why (the status bar and the log).
    connect(m_annotator, &widgets::DeveloppeeAnnotator::refused, this, [this](const QString& message) { report(message, false); });
    m_measures = new widgets::ClassMeasures(*m_document, this);
    m_legendDock = new LegendDock(*m_document, m_measures, this);
    addDockWidget(Qt::RightDockWidgetArea, m_legendDock); // beside the 3D view: the classes with their figures
    connect(&m_legendDock->legend(), &widgets::LegendWidget::classChosen, m_annotator,
            &widgets::DeveloppeeAnnotator::setActive);
    connect(m_annotator, &widgets::DeveloppeeAnnotator::activeChanged, &m_legendDock->legend(),
            &widgets::LegendWidget::showActive);
    m_legendDock->legend().showActive(m_annotator->layer(), m_annotator->activeClass());

    m_tasksDock = new TasksDock(*m_tasks, this);
    splitDockWidget(m_developpeeDock, m_tasksDock, Qt::Horizontal);
    m_logDock = new LogDock(this);
    tabifyDockWidget(m_tasksDock, m_logDock);
    m_tasksDock->raise();
    resizeDocks({m_sceneDock, m_legendDock}, {280, 440}, Qt::Horizontal);
    resizeDocks({m_developpeeDock, m_tasksDock}, {900, 300}, Qt::Horizontal);
    resizeDocks({m_developpeeDock}, {330}, Qt::Vertical);

    connect(m_sceneDock, &SceneDock::selectionChanged, this, &MainWindow::selectionChanged);
}

void MainWindow::createMenus()
{
    m_projectActions = new ProjectActions(*m_document, *m_importer, *this);
    connect(m_projectActions, &ProjectActions::reported, this, &MainWindow::report);
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->setObjectName(QStringLiteral("menuFile"));
    m_projectActions->populate(*m_fileMenu);
    m_projectActions->setRebuiltProject(m_demo->projectPath());

    m_actions = new MainActions(*m_document, m_viewport, m_translations, *this);
    QMenu* viewMenu = m_actions->populate(*menuBar());
    new UndoShortcuts(*this, *m_actions->undoAction(), *m_actions->redoAction());
    for (QDockWidget* dock : {static_cast<QDockWidget*>(m_sceneDock), static_cast<QDockWidget*>(m_propertiesDock),
                              static_cast<QDockWidget*>(m_legendDock), static_cast<QDockWidget*>(m_developpeeDock),
                              static_cast<QDockWidget*>(m_tasksDock),
                              static_cast<QDockWidget*>(m_logDock)})
        viewMenu->addAction(dock->toggleViewAction());
    m_docking = new DockingActions(*m_document, m_viewport, *this);
    m_docking->populate(*m_actions->toolsMenu(), *viewMenu);
    connect(m_docking, &DockingActions::reported, this, &MainWindow::report);
    m_developpeeLink->setGuidesCache(&m_docking->guidesCache());
    m_assemblies = new AssemblyActions(*m_document, *m_sceneDock, *this);
    m_assemblies->populate(*m_actions->toolsMenu());
    connect(m_assemblies, &AssemblyActions::reported, this, &MainWindow::report);
    connect(m_assemblies, &AssemblyActions::developpeeRequested, this, [this](quint64 id) {
        if (m_developpeeLink->computeAssembly(id)) {
            m_developpeeDock->show();
            m_developpeeDock->raise();
        }
    });
    connect(m_developpeeLink, &DeveloppeeLink::fragmentPicked, this,
            [this](quint64 id) { m_sceneDock->selectFragment(core::scene::FragmentId(id)); });
    m_propertiesDock->addContactReadout(m_docking->contact());
    if (widgets::GizmoController* gizmo = m_docking->gizmo()) {
        // A gizmo drag says what it has done so far in the status bar; its end takes that line away (not a report
        // that came meanwhile).
        connect(gizmo, &widgets::GizmoController::dragReadout, this, [this](const QString& text) {
            if (!text.isEmpty()) {
                m_message->showMessage(text);
                m_dragShown = m_message->message();
                return;
            }
            if (!m_dragShown.isEmpty() && m_message->message() == m_dragShown) m_message->clearMessage();
            m_dragShown.clear();
        });
    }
    m_plates = new PlateActions(*m_document, *m_developpeeDock->panel().view(), *this);
    m_plates->populate(*m_fileMenu, m_projectActions->quitAction());
    connect(m_plates, &PlateActions::reported, this, &MainWindow::report);
    m_plates->setCameraSource([this]() -> std::optional<std::array<double, 4>> {
        if (!m_viewport) return std::nullopt;
        const Eigen::Quaterniond q = m_viewport->camera().orientation();
        return std::array<double, 4>{q.w(), q.x(), q.y(), q.z()};
    });
    m_plates->setFragmentSource([this] { return m_sceneDock->currentFragment(); });

    // Two toolbars: the project and its undo steps; the view and the tools. Short labels (the full text and the
    // shortcut in each tooltip); on one row while they fit the window, on two when they do not (ToolBarRows).
    m_toolBar = addToolBar(QString());
    m_toolBar->setObjectName(QStringLiteral("mainToolBar"));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toolBar->addAction(m_projectActions->openAction());
    m_toolBar->addAction(m_projectActions->saveAction());
    m_toolBar->addAction(m_projectActions->importAction());
    m_toolBar->addSeparator();
    m_viewToolBar = addToolBar(QString());
    m_viewToolBar->setObjectName(QStringLiteral("viewToolBar"));
    m_viewToolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_actions->populateToolBars(*m_toolBar, *m_viewToolBar);

    m_annotation = new AnnotationActions(*m_document, m_viewport, m_annotationSync, *this);
    m_annotation->populate(*m_actions->toolsMenu(), m_actions->shadingMenu(), *m_viewToolBar);
    m_toolBarRows = new ToolBarRows(*this, *m_toolBar, *m_viewToolBar);
    m_annotation->setExclusiveWith(m_docking->moveToolAction());
    connect(m_annotation, &AnnotationActions::reported, this, &MainWindow::report);
    // One active class: the lasso's box, the Legend dock and the développée's paint bar show the same.
    connect(m_annotator, &widgets::DeveloppeeAnnotator::activeChanged, m_annotation, &AnnotationActions::showActive);
    connect(m_annotation, &AnnotationActions::classChosen, m_annotator, &widgets::DeveloppeeAnnotator::setActive);
    m_annotation->showActive(m_annotator->layer(), m_annotator->activeClass());
    if (auto* display = m_propertiesDock->displaySettings(); display && m_annotationSync) {
        connect(display, &DisplaySettingsWidget::annotationLayerChanged, m_annotationSync,
                [this](int layer) { m_annotationSync->setLayer(core::annotation::AnnotationLayer(layer)); });
        connect(m_annotationSync, &AnnotationSync::layerChanged, display, &DisplaySettingsWidget::setAnnotationLayer);
    }

    connect(m_actions, &MainActions::removeRequested, this, [this] {
        const auto ids = m_sceneDock->selectedFragments();
        const int n = static_cast<int>(ids.size());
        if (n > 1) m_document->beginMacro([n] { return tr("Remove %n fragment(s)", nullptr, n); });
        for (const auto id : ids) m_document->removeFragment(id);
        if (n > 1) m_document->endMacro();
    });
    connect(m_actions, &MainActions::skydomeRequested, this, &MainWindow::computeSkydome);
    connect(m_actions, &MainActions::developpeeRequested, this, &MainWindow::showDeveloppee);
    connect(m_actions, &MainActions::openDemoRequested, this, &MainWindow::openDemo);
    if (auto* display = m_propertiesDock->displaySettings())
        connect(m_actions, &MainActions::shadingChanged, display, &DisplaySettingsWidget::syncFromViewport);
}

void MainWindow::connectDocument()
{
    using widgets::SceneDocument;
    connect(m_document, &SceneDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_document, &SceneDocument::projectPathChanged, this, &MainWindow::updateTitle);
    connect(m_document, &SceneDocument::loadingFinished, this, &MainWindow::reportAll);
    connect(m_importer, &widgets::ScanImporter::importFailed, this,
            [this](const QString&, const QString& message) { m_logDock->append(LogDock::Level::Error, message); });
    connect(m_importer, &widgets::ScanImporter::fragmentImported, this, [this](quint64 id) {
        if (const auto* f = m_document->fragment(id))
            report(tr("Imported %1").arg(QString::fromStdString(f->name)), false);
    });
    connect(m_importer, &widgets::ScanImporter::importNote, this,
            [this](quint64, const QString& message) { report(message, false); });
    connect(m_importer, &widgets::ScanImporter::importsFinished, this, [this](const QStringList& errors) {
        // Each error is in the log already (importFailed); one box says it all.
        if (errors.isEmpty() || !m_errorDialogs || m_closing) return;
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Stylos"),
                                    errors.size() == 1 ? errors.first()
                                                       : tr("%n scan(s) could not be imported:", nullptr,
                                                            int(errors.size())),
                                    QMessageBox::Ok, this);
        box->setObjectName(QStringLiteral("errorBox"));
        if (errors.size() > 1) box->setInformativeText(errors.join(QStringLiteral("\n\n")));
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });
    connect(m_demo, &widgets::DemoScene::ready, this, [this](const QString& project) {
        m_demoPending = false;
        if (!m_projectActions->openProject(project)) return;
        // The instrument at work: once the octrees are open, the drum is selected and unrolled.
        auto once = std::make_shared<QMetaObject::Connection>();
        *once = connect(m_document, &SceneDocument::loadingFinished, this, [this, once](const QStringList& errors) {
            disconnect(*once);
            if (!errors.isEmpty() || m_document->scene().empty()) return;
            // The demo comes with its skydome: show it (whether just generated or reopened from the cache).
            const auto& fragments = m_document->scene().fragments();
            if (std::all_of(fragments.begin(), fragments.end(), [this](const core::scene::Fragment& f) {
                    const auto octree = m_document->octree(f.id);
                    return octree && octree->attribute("ambient").has_value();
                }))
                showSkydomeShading();
            m_sceneDock->selectFragment(m_document->scene().fragments().front().id);
            m_developpeeLink->compute();
        });
    });
    connect(m_demo, &widgets::DemoScene::failed, this, [this](const QString& message) {
        m_demoPending = false;
        report(message, true);
    });
    connect(m_skydome, &widgets::SkydomeRunner::computed, this, [this](quint64, const widgets::SkydomeResult& r) {
        const auto* f = m_document->fragment(r.fragmentId);
        report(tr("Skydome of %1: %2 cells at level %3, %4 sky directions, %5 s")
                   .arg(f ? QString::fromStdString(f->name) : r.octreePath)
                   .arg(QLocale().toString(qlonglong(r.cells)))
                   .arg(r.level)
                   .arg(r.directions)
                   .arg(QLocale().toString(r.seconds, 'f', 1)),
               false);
    });
    connect(m_skydome, &widgets::SkydomeRunner::failed, this,
            [this](quint64, const QString& message) { report(message, true); });
    connect(m_demo, &widgets::DemoScene::cancelled, this, [this] { m_demoPending = false; });
}

void MainWindow::selectionChanged()
{
    const auto ids = m_sceneDock->selectedFragments();
    if (m_sync) m_sync->setSelection(ids);
    const auto current = m_sceneDock->currentFragment();
    m_propertiesDock->setFragment(current);
    // An assembly's row: its développée again (it said "No développée yet" once another row had been selected).
    if (const auto assembly = m_sceneDock->currentAssembly(); assembly != core::scene::NoAssembly && current == core::scene::NoFragment)
        m_developpeeLink->showAssembly(assembly);
    else
        m_developpeeLink->setFragment(ids.size() == 1 ? ids.first() : current);
    m_docking->setFragment(ids.size() == 1 ? ids.first() : current);
    m_actions->setSelectionCount(static_cast<int>(ids.size()));
    if (m_sceneDock->model()->isDeveloppee(m_sceneDock->view()->currentIndex())) {
        m_developpeeDock->show();
        m_developpeeDock->raise();
    }
}

void MainWindow::openDemo()
{
    if (m_demoPending || !m_projectActions->maybeSave()) return;
    m_demoPending = true;
    if (!m_demo->prepare()) m_demoPending = false;
}

void MainWindow::computeSkydome()
{
    const auto ids = m_sceneDock->selectedFragments();
    if (m_skydome->start(ids) == 0 && !ids.isEmpty()) {
        // A missing octree file is named, not taken for one still opening.
        for (const auto id : ids)
            if (const auto* f = m_document->fragment(id); f && f->octreeMissing) {
                report(tr("Could not compute the skydome of %1: its octree %2 does not exist")
                           .arg(QString::fromStdString(f->name), QDir::toNativeSeparators(QString::fromStdString(f->octreePath.string()))),
                       true);
                showSkydomeShading();
                return;
            }
        report(tr("The skydome of the selection is being computed already, or its octrees are not open yet"), false);
    }
    showSkydomeShading(); // the result shows as soon as it comes
}

void MainWindow::showSkydomeShading()
{
    if (m_viewport && m_viewport->shading() != widgets::PointRenderer::Shading::Ambient) {
        m_viewport->setShading(widgets::PointRenderer::Shading::Ambient);
        m_actions->syncShading();
        if (auto* display = m_propertiesDock->displaySettings()) display->syncFromViewport();
    }
}

bool MainWindow::isBusy() const
{
    return !m_tasks->isIdle() || m_document->isLoading() || m_importer->pending() > 0 || m_demoPending;
}

void MainWindow::setErrorDialogsEnabled(bool enabled)
{
    m_errorDialogs = enabled;
    m_projectActions->setPromptsEnabled(enabled);
}

void MainWindow::showDeveloppee()
{
    m_developpeeDock->show();
    m_developpeeDock->raise();
    m_developpeeLink->compute();
}

bool MainWindow::event(QEvent* event)
{
    if (event->type() == QEvent::StatusTip) {
        m_message->setTip(static_cast<QStatusTipEvent*>(event)->tip());
        return true;
    }
    return QMainWindow::event(event);
}

void MainWindow::report(const QString& message, bool failed)
{
    m_logDock->append(failed ? LogDock::Level::Error : LogDock::Level::Info, message);
    m_message->showMessage(message, 8000); // its first line, cut with "…" to the width; the whole as its tooltip
    if (!failed || !m_errorDialogs || m_closing) return; // no window comes up once this one has closed
    // Window-modal and non-blocking: the event loop, and every task, keep running.
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Stylos"), message, QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("errorBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::reportAll(const QStringList& errors)
{
    if (errors.isEmpty()) return;
    for (const QString& error : errors.mid(0, errors.size() - 1)) m_logDock->append(LogDock::Level::Error, error);
    report(errors.size() == 1 ? errors.first() : errors.join(QStringLiteral("\n\n")), true);
}

void MainWindow::updateTitle()
{
    setWindowTitle(tr("%1[*] — Stylos").arg(m_document->displayName()));
    setWindowModified(m_document->isModified());
}

widgets::DeveloppeePanel& MainWindow::developpeePanel() const { return m_developpeeDock->panel(); }

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!m_projectActions->maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(GeometryKey, saveGeometry());
    settings.setValue(StateKey, saveState());
    m_developpeeDock->saveSettings();
    // Every job checks for Cancel between steps: this returns within a fraction of a second. What the cancelled
    // jobs then report goes to the log only.
    m_closing = true;
    m_tasks->cancelAllAndWait();
    event->accept();
}

void MainWindow::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        m_demo->relabel(*m_document); // the demo's names, then the undo steps that name them
        m_document->retranslate(); // before the Edit menu shows the undo step's text
        retranslateUi();
        m_actions->retranslateUi();
        m_docking->retranslateUi();
        m_annotation->retranslateUi();
        m_assemblies->retranslateUi();
        m_projectActions->retranslateUi();
        m_plates->retranslateUi();
        updateTitle();
    }
    QMainWindow::changeEvent(event);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (!ProjectActions::openableFiles(event->mimeData()->urls()).isEmpty()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    const QStringList paths = ProjectActions::openableFiles(event->mimeData()->urls());
    if (paths.isEmpty()) return;
    event->acceptProposedAction();
    m_projectActions->openPaths(paths);
}

void MainWindow::retranslateUi()
{
    m_fileMenu->setTitle(tr("&File"));
    m_toolBar->setWindowTitle(tr("Main toolbar"));
    m_viewToolBar->setWindowTitle(tr("View and tools toolbar"));
    if (auto* message = findChild<QLabel*>(QStringLiteral("noViewport")))
        message->setText(tr("The 3D view needs OpenGL 3.3 (core profile), which this display does not offer."));
}

} // namespace stylos::app
