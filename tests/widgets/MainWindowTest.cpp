// The workbench through its main window: import in the background, the Scene tree, errors naming the
// file, undo/redo from the Edit menu, save and reopen a project, the développée linked to the 3D view,
// the skydome task, the language menu, closing with a task running; a pose edit reaches the 3D view as a
// pose only (no new cut), any other edit as new fragments.
#include "AnnotationActions.h"
#include "AssemblyActions.h"
#include "DeveloppeeLink.h"
#include "DrumOctreeFixture.h"
#include "LogDock.h"
#include "MainActions.h"
#include "MainWindow.h"
#include "ProjectActions.h"
#include "SceneDock.h"
#include "StatusReadout.h"
#include "Translations.h"
#include "WidgetTestSupport.h"
#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/widgets/annotation/DeveloppeeAnnotator.h"
#include "stylos/widgets/annotation/LegendText.h"
#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/plate/PlateTexts.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/document/DemoScene.h"
#include "stylos/widgets/document/ScanImporter.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/document/SceneTreeModel.h"
#include "stylos/widgets/skydome/SkydomeRunner.h"
#include "stylos/widgets/tasks/TaskManager.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QAction>
#include <QApplication>
#include <QTimer>
#include <QMessageBox>
#include <QComboBox>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QItemSelectionModel>
#include <QTreeView>
#include <QUndoStack>

#include <memory>

using namespace stylos;

class MainWindowTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void importsInTheBackgroundAndListsTheFragments();
    void reportsErrorsNamingTheFile();
    void undoAndRedoFromTheEditMenu();
    void aPoseEditReachesTheViewAsAPoseOnly();
    void removesTheSelectionInOneUndoStep();
    void assembliesFromTheSelectionMoveAsOneInTheView();
    void savesAndReopensTheProject();
    void theFileChoosersOpenInAFolderThatExists();
    void theDemosProjectIsNeverSavedOver();
    void developpeeClickMarksThe3dPointAndBack();
    void computesTheSkydomeOfTheSelection();
    void switchesTheLanguageFromTheMenu();
    void statusReadoutFormats();
    void closingCancelsTasksAndSavesTheLayout();
    void theLassoAndTheLegendShareTheActiveClass();
    void openAsksOnceAboutUnsavedChanges();

private:
    /** A window with dialogs off, shown, the importer writing into the test folder. */
    std::unique_ptr<app::MainWindow> makeWindow();
    /** Imports @p paths and waits until every task is done. */
    static void importAndWait(app::MainWindow& window, const QStringList& paths);
    static QAction* menuAction(app::MainWindow& window, const QString& objectName);

    QTemporaryDir m_dir;
    test::DrumOctree m_drum;
    std::unique_ptr<app::Translations> m_translations;
};

void MainWindowTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_drum = test::makeDrumOctree(m_dir.path());
    m_translations = std::make_unique<app::Translations>();
}

void MainWindowTest::init()
{
    QSettings().clear();
}

void MainWindowTest::cleanup()
{
    QSettings().clear();
}

void MainWindowTest::theLassoAndTheLegendShareTheActiveClass()
{
    using stylos::core::annotation::AnnotationLayer;
    auto window = makeWindow();
    QComboBox* box = window->annotation().classBox();
    widgets::DeveloppeeAnnotator& annotator = window->annotator();
    // Chosen in the Legend dock (the annotator's active class): the lasso's box follows.
    annotator.setActive(AnnotationLayer::Material, 4);
    QCOMPARE(box->currentData().toInt(), 4);
    annotator.setActive(AnnotationLayer::Material, 2);
    QCOMPARE(box->currentData().toInt(), 2);
    // Chosen in the lasso's box: the Legend dock and the développée follow.
    const int three = box->findData(3);
    QVERIFY(three >= 0);
    box->setCurrentIndex(three);
    Q_EMIT box->activated(three);
    QCOMPARE(int(annotator.activeClass()), 3);
    QCOMPARE(annotator.layer(), AnnotationLayer::Material);
    // A class of the other layer: the lasso takes that layer (the 3D view's annotation shading with it) and the class.
    annotator.setActive(AnnotationLayer::Toolmark, 2);
    QCOMPARE(box->currentData().toInt(), 2);
    QCOMPARE(box->count(), int(window->document().legend().classes(AnnotationLayer::Toolmark).size()));
    // The box names the classes as the Legend does (translated defaults).
    const auto& first = window->document().legend().classes(AnnotationLayer::Toolmark).front();
    QCOMPARE(box->itemText(0), widgets::LegendText::className(AnnotationLayer::Toolmark, first));
    annotator.setActive(AnnotationLayer::Material, 3);
    QCOMPARE(box->currentData().toInt(), 3);
}

void MainWindowTest::openAsksOnceAboutUnsavedChanges()
{
    // A project to open, then unsaved changes: File › Open asks once (Discard), shows the file dialog, opens. It
    // asked a second time, and a Save there saved what had just been discarded.
    auto window = makeWindow();
    const QString project = m_dir.filePath("asked-once.stylos");
    QString error;
    QVERIFY(window->document().saveAs(project, &error));
    window->document().newProject();
    importAndWait(*window, {QString::fromStdString(m_drum.ply.string())});
    QVERIFY(window->document().isModified());
    window->projectActions().setPromptsEnabled(true);
    int asked = 0;
    QTimer answer;
    QObject::connect(&answer, &QTimer::timeout, [&] {
        QWidget* modal = QApplication::activeModalWidget();
        if (auto* box = qobject_cast<QMessageBox*>(modal)) {
            ++asked;
            box->button(QMessageBox::Discard)->click();
        }
    });
    answer.start(50);
    window->projectActions().setProjectChooser([&](QWidget&, const QString&) { return project; });
    menuAction(*window, QStringLiteral("actionOpen"))->trigger();
    answer.stop();
    window->projectActions().setPromptsEnabled(false);
    QCOMPARE(asked, 1);
    QCOMPARE(window->document().projectPath(), QFileInfo(project).absoluteFilePath());
    QVERIFY(window->tasks().waitForIdle(30000));
}

std::unique_ptr<app::MainWindow> MainWindowTest::makeWindow()
{
    auto window = std::make_unique<app::MainWindow>(*m_translations, m_dir.filePath("demo"));
    window->setErrorDialogsEnabled(false);
    window->importer().setCacheDirectory(m_dir.filePath("octrees"));
    window->resize(1000, 700);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get())) qWarning("window not exposed");
    return window;
}

void MainWindowTest::importAndWait(app::MainWindow& window, const QStringList& paths)
{
    window.projectActions().openPaths(paths);
    QVERIFY(window.tasks().waitForIdle(60000));
    QTRY_VERIFY_WITH_TIMEOUT(!window.isBusy(), 10000);
}

QAction* MainWindowTest::menuAction(app::MainWindow& window, const QString& objectName)
{
    return window.findChild<QAction*>(objectName);
}

void MainWindowTest::importsInTheBackgroundAndListsTheFragments()
{
    auto window = makeWindow();
    const QString ply = QString::fromStdString(m_drum.ply.string());
    const QString poct = QString::fromStdString(m_drum.poct.string());
    window->projectActions().openPaths({ply, poct});
    // The build runs in the background: the call returned at once, the task is listed.
    QVERIFY(window->isBusy());
    QCOMPARE(window->tasks().count(), 2);
    QVERIFY(window->tasks().waitForIdle(60000));
    QTRY_VERIFY(!window->isBusy());

    const widgets::SceneTreeModel& tree = *window->sceneDock().model();
    QCOMPARE(tree.rowCount(), 2);
    QCOMPARE(tree.index(0, 0).data().toString(), QStringLiteral("drum"));
    QCOMPARE(tree.index(1, 0).data().toString(), QStringLiteral("drum"));
    const auto& fragments = window->document().scene().fragments();
    // The scan was built into the importer's folder; the .poct was opened where it is.
    // (in the order they finished: the .poct only had to be opened)
    QCOMPARE(fragments[0].octreePath, m_drum.poct);
    QCOMPARE(QFileInfo(QString::fromStdString(fragments[1].octreePath.string())).absolutePath(),
             QDir(m_dir.filePath("octrees")).absolutePath());
    QCOMPARE(window->document().octree(fragments[1].id)->description().points, m_drum.octree->description().points);
    QVERIFY(window->logDock().text().contains(QStringLiteral("Imported drum")));
    QCOMPARE(window->logDock().errorCount(), 0);
    QVERIFY(window->windowTitle().startsWith(QStringLiteral("Untitled")));
    QVERIFY(window->isWindowModified());
    if (auto* viewport = window->viewport()) QTRY_COMPARE(viewport->fragments().size(), std::size_t{2});
}

void MainWindowTest::reportsErrorsNamingTheFile()
{
    auto window = makeWindow();
    const QString bad = test::writeFile(m_dir.path(), "broken-capital.ply", "garbage");
    importAndWait(*window, {bad, m_dir.filePath("missing-drum.ply")});
    QCOMPARE(window->document().scene().fragments().size(), std::size_t{0});
    QCOMPARE(window->logDock().errorCount(), 2);
    const QString log = window->logDock().text();
    QVERIFY2(log.contains(QStringLiteral("broken-capital.ply")), qPrintable(log));
    QVERIFY2(log.contains(QStringLiteral("missing-drum.ply")), qPrintable(log));
    // Nothing half-built is left behind.
    QCOMPARE(QDir(m_dir.filePath("octrees")).entryList({QStringLiteral("broken-capital*")}, QDir::Files).size(), 0);

    // A malformed project: the message names it, the scene is kept.
    const QString project = test::writeFile(m_dir.path(), "bad.stylos", "{\"format\": 3}");
    window->projectActions().openPaths({project});
    QCOMPARE(window->logDock().errorCount(), 3);
    QVERIFY(window->logDock().text().contains(QStringLiteral("bad.stylos")));
}

void MainWindowTest::undoAndRedoFromTheEditMenu()
{
    auto window = makeWindow();
    importAndWait(*window, {QString::fromStdString(m_drum.poct.string())});
    widgets::SceneTreeModel& tree = *window->sceneDock().model();
    QVERIFY(tree.setData(tree.index(0, 0), QStringLiteral("Drum III"), Qt::EditRole));
    QCOMPARE(tree.index(0, 0).data().toString(), QStringLiteral("Drum III"));

    QAction* undo = menuAction(*window, QStringLiteral("actionUndo"));
    QAction* redo = menuAction(*window, QStringLiteral("actionRedo"));
    QVERIFY(undo && redo);
    QVERIFY(window->menuBar()->findChild<QMenu*>(QStringLiteral("menuEdit"))->actions().contains(undo));
    QVERIFY(undo->isEnabled());
    undo->trigger();
    QCOMPARE(tree.index(0, 0).data().toString(), QStringLiteral("drum"));
    redo->trigger();
    QCOMPARE(tree.index(0, 0).data().toString(), QStringLiteral("Drum III"));
    undo->trigger();
    undo->trigger(); // the import itself
    QCOMPARE(tree.rowCount(), 0);
    QVERIFY(!undo->isEnabled());
    redo->trigger();
    QCOMPARE(tree.rowCount(), 1);
    QTRY_VERIFY(window->document().octree(window->document().scene().fragments()[0].id) != nullptr);
}

void MainWindowTest::aPoseEditReachesTheViewAsAPoseOnly()
{
    auto window = makeWindow();
    widgets::ViewportWidget* viewport = window->viewport();
    if (!viewport) QSKIP("no OpenGL 3.3 on this platform (run under xvfb-run)");
    importAndWait(*window, {QString::fromStdString(m_drum.poct.string())});
    QTRY_VERIFY_WITH_TIMEOUT(viewport->fragments().size() == 1 && viewport->isSettled(), 20000);
    viewport->scheduler().setIdleDelay(60000); // the deferred cut after a drag stays out of the way
    widgets::SceneDocument& document = window->document();
    const auto id = document.scene().fragments()[0].id;
    const std::uint64_t cuts = viewport->scheduler().cutsStarted();
    const Eigen::Matrix4d imported = viewport->fragments()[0].pose; // where the import placed it

    const auto pose = core::scene::Pose::translation({0.25, -0.5, 1});
    QVERIFY(document.setFragmentPose(id, pose));
    Eigen::Matrix4d expected = Eigen::Matrix4d::Identity();
    expected.topRightCorner<3, 1>() << 0.25, -0.5, 1;
    QTRY_VERIFY(viewport->fragments()[0].pose == expected); // pushed on the next turn of the event loop
    QCOMPARE(viewport->scheduler().cutsStarted(), cuts);
    const auto& origin = m_drum.octree->box().origin;
    Eigen::Matrix4d model = expected;
    model.topRightCorner<3, 1>() += Eigen::Vector3d(origin[0], origin[1], origin[2]);
    QVERIFY(*viewport->renderer().points().modelMatrix(id) == model);

    window->document().undoStack()->undo(); // undone: a pose again
    QTRY_VERIFY(viewport->fragments()[0].pose == imported);
    QVERIFY(document.renameFragment(id, QStringLiteral("Drum II"))); // nothing the view shows
    QTest::qWait(50);
    QCOMPARE(viewport->scheduler().cutsStarted(), cuts);

    // Any other change replaces the fragments: a new cut at once.
    QVERIFY(document.setFragmentColour(id, core::scene::Rgb{10, 20, 30}));
    QTRY_VERIFY(viewport->scheduler().cutsStarted() > cuts);
    QVERIFY((viewport->fragments()[0].colour == std::array<std::uint8_t, 3>{10, 20, 30}));
}

void MainWindowTest::removesTheSelectionInOneUndoStep()
{
    auto window = makeWindow();
    const QString poct = QString::fromStdString(m_drum.poct.string());
    importAndWait(*window, {poct, poct, poct});
    QCOMPARE(window->sceneDock().model()->rowCount(), 3);
    QTreeView* view = window->sceneDock().view();
    view->selectAll();
    QCOMPARE(window->sceneDock().selectedFragments().size(), 3);
    QAction* remove = window->actions().removeAction();
    QVERIFY(remove->isEnabled());
    remove->trigger();
    QCOMPARE(window->sceneDock().model()->rowCount(), 0);
    QVERIFY(!remove->isEnabled());
    window->actions().undoAction()->trigger();
    QCOMPARE(window->sceneDock().model()->rowCount(), 3);
}

void MainWindowTest::assembliesFromTheSelectionMoveAsOneInTheView()
{
    auto window = makeWindow();
    const QString poct = QString::fromStdString(m_drum.poct.string());
    importAndWait(*window, {poct, poct, poct});
    widgets::SceneDocument& document = window->document();
    const auto ids = document.scene().membersOf(core::scene::NoAssembly);
    QCOMPARE(ids.size(), 3u);
    // Two selected, the drum with its axis among them: a new assembly (Ctrl+G) docking against it.
    const auto& trueAxis = m_drum.truth.at("axis");
    const std::array<double, 3> axisPoint{trueAxis["point"][0], trueAxis["point"][1], trueAxis["point"][2]};
    Eigen::Vector3d axisDir(trueAxis["direction"][0], trueAxis["direction"][1], trueAxis["direction"][2]);
    axisDir.normalize();
    QVERIFY(document.setFragmentGuides(
        ids[0], {{"Axis", core::scene::GuideKind::Axis, axisPoint, {axisDir.x(), axisDir.y(), axisDir.z()}}}));
    QTreeView* view = window->sceneDock().view();
    QItemSelection selection;
    for (auto id : {ids[0], ids[1]}) {
        const QModelIndex row = window->sceneDock().model()->indexOf(id);
        selection.select(row, row);
    }
    view->selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    QAction* make = window->assemblies().newAssemblyAction();
    QVERIFY(make->isEnabled());
    QCOMPARE(make->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_G));
    make->trigger();
    QCOMPARE(document.scene().assemblies().size(), 1u);
    const core::scene::Assembly assembly = document.scene().assemblies()[0]; // a copy: edits replace the list
    QCOMPARE(assembly.drum, ids[0]);
    QCOMPARE(document.scene().membersOf(assembly.id), (std::vector<core::scene::FragmentId>{ids[0], ids[1]}));
    QCOMPARE(window->sceneDock().model()->rowCount(), 2);            // the assembly and the third fragment
    QCOMPARE(window->sceneDock().selectedFragments().size(), 2);     // the selection survived the new tree
    QVERIFY(view->isExpanded(window->sceneDock().model()->indexOfAssembly(assembly.id)));

    // The member without an axis of its own unrolls about the drum's axis, carried into its frame.
    QVERIFY(document.setFragmentWorldPose(ids[1], core::scene::Pose::fromTranslationAngles({{0.5, -0.25, 0.0}, {0.0, 0.0, 0.3}})));
    window->sceneDock().selectFragment(ids[1]);
    const auto offered = window->developpeePanel().axisGuide();
    QVERIFY(offered.has_value());
    const core::scene::Pose toMember = document.worldPose(ids[1]).rigidInverse() * document.worldPose(ids[0]);
    const auto expectedPoint = toMember.apply(axisPoint);
    QVERIFY(std::abs(expectedPoint[0]) > 0.1); // not the identity
    for (int k = 0; k < 3; ++k) QVERIFY(std::abs(offered->point[k] - expectedPoint[k]) < 1e-12);
    // Away from the drum (not docked yet), its développée about the drum's axis finds no point on the drum's
    // cylinder: the error says what to do.
    auto* compute = window->developpeePanel().findChild<QPushButton*>(QStringLiteral("developpeeCompute"));
    QVERIFY(compute && compute->isEnabled());
    const int errorsBefore = window->logDock().errorCount();
    compute->click();
    QTRY_VERIFY_WITH_TIMEOUT(window->logDock().errorCount() == errorsBefore + 1, 60000);
    QVERIFY2(window->logDock().text().contains(
                 QStringLiteral("is unrolled about its drum's axis guide and does not stand on the drum yet: dock it first")),
             qPrintable(window->logDock().text()));

    // The assembly's développée: the drum's, with the member drawn at its place (here the same drum turned
    // about its axis, so on its surface everywhere: it covers the drum's développée).
    const Eigen::Vector3d a(axisPoint[0], axisPoint[1], axisPoint[2]);
    const Eigen::Isometry3d turn(Eigen::Translation3d(a) * Eigen::AngleAxisd(0.3, axisDir) * Eigen::Translation3d(-a));
    const Eigen::Matrix4d drumWorld = core::scene::toEigen(document.worldPose(ids[0])); // where its import put it
    QVERIFY(document.setFragmentWorldPose(ids[1], core::scene::poseFromEigen(drumWorld * turn.matrix())));
    QAction* unroll = window->assemblies().developpeeAction();
    window->sceneDock().view()->setCurrentIndex(window->sceneDock().model()->indexOfAssembly(assembly.id));
    QVERIFY(unroll->isEnabled());
    unroll->trigger();
    widgets::DeveloppeeView* dview = window->developpeePanel().view();
    QTRY_VERIFY_WITH_TIMEOUT(dview->hasDeveloppee() && dview->fragmentId() == ids[0], 60000);
    std::size_t owned = 0, pixels = 0;
    for (int r = 0; r < dview->map()->height(); ++r)
        for (int c = 0; c < dview->map()->width(); ++c, ++pixels) owned += dview->pieceAt(c, r) == ids[1];
    QVERIFY2(owned > pixels / 2, qPrintable(QString("%1 of %2").arg(owned).arg(pixels)));
    dview->setPieces(nullptr);
    QCOMPARE(dview->pieceAt(0, 0), 0u); // none without pieces

    // Moving the assembly moves both members in the view, not the third.
    widgets::ViewportWidget* viewport = window->viewport();
    const auto shift = core::scene::Pose::translation({0, 0, 2});
    const double z0 = document.worldPose(ids[0])(2, 3), z1 = document.worldPose(ids[1])(2, 3);
    const double z2 = document.worldPose(ids[2])(2, 3); // each where its import placed it
    const core::scene::Pose drumBefore = document.worldPose(ids[0]);
    QVERIFY(document.setAssemblyPose(assembly.id, shift * assembly.pose));
    if (viewport) {
        QTRY_VERIFY(viewport->fragments().size() == 3 && std::abs(viewport->fragments()[1].pose(2, 3) - (z1 + 2.0)) < 1e-12);
        QCOMPARE(viewport->fragments()[0].pose(2, 3), z0 + 2.0);
        QCOMPARE(viewport->fragments()[2].pose(2, 3), z2);
    }
    // Hiding the assembly hides its members in the view.
    QVERIFY(document.setAssemblyVisible(assembly.id, false));
    if (viewport) QTRY_VERIFY(!viewport->fragments()[0].visible && !viewport->fragments()[1].visible &&
                              viewport->fragments()[2].visible);
    // Remove the assembly from the dock: the fragments stay where they are, at the top.
    window->sceneDock().view()->setCurrentIndex(window->sceneDock().model()->indexOfAssembly(assembly.id));
    QAction* remove = window->assemblies().removeAction();
    QVERIFY(remove->isEnabled());
    remove->trigger();
    QVERIFY(document.scene().assemblies().empty());
    QCOMPARE(document.worldPose(ids[0]), shift * drumBefore);
    QCOMPARE(window->sceneDock().model()->rowCount(), 3);
}

void MainWindowTest::savesAndReopensTheProject()
{
    const QString folder = m_dir.filePath("project");
    QVERIFY(QDir().mkpath(folder));
    const QString path = folder + QStringLiteral("/temple.stylos");
    core::scene::Scene saved;
    {
        auto window = makeWindow();
        importAndWait(*window, {QString::fromStdString(m_drum.poct.string())});
        widgets::SceneDocument& doc = window->document();
        const auto id = doc.scene().fragments()[0].id;
        QVERIFY(doc.setFragmentPose(id, core::scene::Pose().withTranslation({0.25, -1.5, 2.0}).withAngles({0, 0, 30})));
        QVERIFY(doc.setFragmentColour(id, core::scene::Rgb{10, 120, 240}));
        QString error;
        QVERIFY2(doc.saveAs(path, &error), qPrintable(error));
        QVERIFY(!window->isWindowModified());
        QCOMPARE(window->windowTitle(), QStringLiteral("temple.stylos[*] — Stylos"));
        saved = doc.scene();
    }
    auto window = makeWindow();
    QVERIFY(window->projectActions().openProject(path));
    QVERIFY(window->tasks().waitForIdle(30000));
    QTRY_VERIFY(!window->isBusy());
    QCOMPARE(window->document().scene().fragments().size(), std::size_t{1});
    const core::scene::Fragment& f = window->document().scene().fragments()[0];
    QCOMPARE(f.name, saved.fragments()[0].name);
    QCOMPARE(f.pose, saved.fragments()[0].pose);
    QCOMPARE(f.colour, saved.fragments()[0].colour);
    // Saving copied the octree into the project's folder, so that the folder travels whole.
    QCOMPARE(QString::fromStdString(f.octreePath.string()), QFileInfo(folder).canonicalFilePath() + QStringLiteral("/drum.poct"));
    QVERIFY(window->document().octree(f.id) != nullptr);
    QVERIFY(!window->isWindowModified());
    QCOMPARE(app::ProjectActions::recentProjects().value(0), QFileInfo(path).absoluteFilePath());
}

void MainWindowTest::theFileChoosersOpenInAFolderThatExists()
{
    // The folder last chosen, moved or deleted since: the choosers open in its nearest existing parent (given as it
    // was, Qt's chooser put its last name, "proj", in the file-name box of Import scans).
    QTemporaryDir base;
    QVERIFY(QDir(base.path()).mkpath(QStringLiteral("site/proj")));
    const QString proj = base.path() + QStringLiteral("/site/proj");
    QSettings().setValue(QStringLiteral("files/lastDirectory"), proj);
    QCOMPARE(app::ProjectActions::rememberedFolder(), QFileInfo(proj).absoluteFilePath());
    QVERIFY(QDir(proj).removeRecursively());
    QCOMPARE(app::ProjectActions::rememberedFolder(), QFileInfo(base.path() + QStringLiteral("/site")).absoluteFilePath());
    QSettings().remove(QStringLiteral("files/lastDirectory"));
    QCOMPARE(app::ProjectActions::rememberedFolder(), QString());
}

void MainWindowTest::theDemosProjectIsNeverSavedOver()
{
    // The demo's project is rebuilt whenever it differs from what its generator makes (a fragment more, say):
    // work saved into it would be lost at the next start, so Save asks for a file of one's own instead.
    auto window = makeWindow();
    importAndWait(*window, {QString::fromStdString(m_drum.poct.string())});
    const QString demo = window->demo().projectPath();
    QVERIFY(QDir().mkpath(QFileInfo(demo).absolutePath()));
    QString error;
    QVERIFY2(window->document().saveAs(demo, &error), qPrintable(error)); // as the demo's generator would
    const auto bytes = [](const QString& path) {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    };
    const QByteArray before = bytes(demo);
    QVERIFY(!before.isEmpty());
    const auto id = window->document().scene().fragments()[0].id;
    QVERIFY(window->document().setFragmentPose(id, core::scene::Pose().withTranslation({0.5, 0, 0})));
    QSignalSpy reports(&window->projectActions(), &app::ProjectActions::reported);
    QVERIFY(!window->projectActions().save()); // no prompts in tests: Save as is not answered
    QVERIFY(window->isWindowModified());
    QCOMPARE(bytes(demo), before);
    QVERIFY(!reports.isEmpty());
    QVERIFY(reports.first().at(0).toString().contains(QStringLiteral("save your work as a project of your own")));
    QVERIFY(!reports.first().at(1).toBool());
    // Saving as that very file, or beside it (the folder is rebuilt, octrees and all), or through a link to the
    // folder, is refused, naming the file.
    const QString link = m_dir.filePath("demo-link");
    QVERIFY(QFile::link(QFileInfo(demo).absolutePath(), link));
    for (const QString& target : {demo, QFileInfo(demo).absolutePath() + QStringLiteral("/mine.stylos"),
                                  link + QStringLiteral("/demo.stylos")}) {
        reports.clear();
        QVERIFY(!window->projectActions().saveTo(target));
        QCOMPARE(bytes(demo), before);
        QVERIFY(!QFileInfo::exists(QFileInfo(demo).absolutePath() + QStringLiteral("/mine.stylos")));
        QCOMPARE(reports.size(), 1);
        QVERIFY2(reports.first().at(0).toString().contains(QDir::toNativeSeparators(target)), qPrintable(target));
        QVERIFY(reports.first().at(1).toBool());
    }
    // Another file saves as ever.
    const QString mine = m_dir.filePath("mine.stylos");
    QVERIFY(window->projectActions().saveTo(mine));
    QVERIFY(!window->isWindowModified());
    // The shortcut of Save as is there on every desktop.
    QVERIFY(!window->findChild<QAction*>(QStringLiteral("actionSaveAs"))->shortcut().isEmpty());
}

void MainWindowTest::developpeeClickMarksThe3dPointAndBack()
{
    auto window = makeWindow();
    const QString poct = QString::fromStdString(m_drum.poct.string());
    importAndWait(*window, {poct, poct});
    widgets::SceneDocument& doc = window->document();
    const auto id = doc.scene().fragments()[0].id;
    const auto other = doc.scene().fragments()[1].id;
    const core::scene::Pose pose = core::scene::Pose().withTranslation({2.0, 0.5, -1.0}).withAngles({0, 0, 90});
    QVERIFY(doc.setFragmentPose(id, pose));
    window->sceneDock().selectFragment(id);
    QCOMPARE(window->developpeePanel().fragmentId(), quint64(id));
    QVERIFY(window->actions().developpeeAction()->isEnabled());

    window->actions().developpeeAction()->trigger();
    QVERIFY(window->developpeePanel().isBusy());
    QVERIFY(window->tasks().waitForIdle(60000));
    widgets::DeveloppeeView* view = window->developpeePanel().view();
    QVERIFY2(view->hasDeveloppee(), qPrintable(window->developpeePanel().statusText()));

    // A click at the développée's centre marks a point of the drum's surface, in the octree's frame…
    const QSize size = view->map()->width() > 0 ? QSize(view->map()->width(), view->map()->height()) : QSize();
    const auto expected = view->pointAtPixel(size.width() / 2, size.height() / 2);
    QVERIFY(expected.has_value());
    // (its distance from the drum's true axis is the radius, to the grooves' depth)
    const auto& axis = m_drum.truth.at("axis");
    const Eigen::Vector3d a(axis["point"][0], axis["point"][1], axis["point"][2]);
    const Eigen::Vector3d d = Eigen::Vector3d(axis["direction"][0], axis["direction"][1], axis["direction"][2]).normalized();
    const Eigen::Vector3d offset = *expected - a;
    const double distance = (offset - offset.dot(d) * d).norm();
    const double radius = m_drum.truth.at("radius").get<double>();
    QVERIFY2(std::abs(distance - radius) < 0.05 * radius, qPrintable(QString::number(distance)));
    view->resize(400, 300);
    view->fitToWindow();
    QTest::mouseClick(view, Qt::LeftButton, {}, view->rect().center());
    QVERIFY(view->marker().has_value());
    // …which the 3D view shows at the same place through the fragment's pose.
    const Eigen::Vector3d local = *view->marker();
    const auto scene = pose.apply({local.x(), local.y(), local.z()});
    if (auto* viewport = window->viewport()) {
        QVERIFY(viewport->marker().has_value());
        QVERIFY((*viewport->marker() - Eigen::Vector3d(scene[0], scene[1], scene[2])).norm() < 1e-9);
    }
    // The développée is listed under its fragment, and comes back when the fragment is selected again.
    const QModelIndex row = window->sceneDock().model()->developpeeIndexOf(id);
    QVERIFY(row.isValid());
    QVERIFY(row.data().toString().startsWith(QStringLiteral("Développée (Cylinder, ")));
    QCOMPARE(row.data(widgets::SceneTreeModel::FragmentIdRole).value<quint64>(), quint64(id));
    QVERIFY(doc.developpee(id) != nullptr);
    window->sceneDock().selectFragment(other);
    QVERIFY(!view->hasDeveloppee());
    window->sceneDock().selectFragment(id);
    QVERIFY(view->hasDeveloppee());
    QCOMPARE(view->fragmentId(), quint64(id));
    // A pick in 3D comes back into the développée through the inverse pose.
    view->setMarker(std::nullopt);
    window->developpeeLink().markInDeveloppee(Eigen::Vector3d(scene[0], scene[1], scene[2]), id);
    QVERIFY(view->marker().has_value());
    QVERIFY((*view->marker() - local).norm() < 1e-9);
    // A pick on another fragment clears it.
    window->developpeeLink().markInDeveloppee(Eigen::Vector3d::Zero(), other);
    QVERIFY(!view->marker().has_value());
    // Removing the fragment drops its développée, from the tree and from the dock.
    QVERIFY(doc.removeFragment(id));
    QVERIFY(!view->hasDeveloppee());
    QCOMPARE(window->sceneDock().model()->rowCount(), 1);
}

void MainWindowTest::computesTheSkydomeOfTheSelection()
{
    // A copy: the skydome is written into the fragment's own .poct.
    const QString copy = m_dir.filePath("skydome-drum.poct");
    QFile::remove(copy);
    QVERIFY(QFile::copy(QString::fromStdString(m_drum.poct.string()), copy));
    auto window = makeWindow();
    importAndWait(*window, {copy});
    const auto id = window->document().scene().fragments()[0].id;
    // What was just imported is selected; without a selection there is nothing to compute.
    QCOMPARE(window->sceneDock().selectedFragments(), QList<core::scene::FragmentId>{id});
    window->sceneDock().view()->clearSelection();
    QVERIFY(!window->actions().skydomeAction()->isEnabled());
    window->sceneDock().selectFragment(id);
    QVERIFY(window->actions().skydomeAction()->isEnabled());
    window->actions().skydomeAction()->trigger();
    QCOMPARE(window->skydome().count(), 1);
    QVERIFY(window->tasks().waitForIdle(60000));
    QCOMPARE(window->skydome().count(), 0);
    const auto octree = window->document().octree(id);
    QVERIFY(octree != nullptr);
    QVERIFY(octree->attribute("ambient").has_value());
    QVERIFY2(window->logDock().text().contains(QStringLiteral("Skydome of skydome-drum")),
             qPrintable(window->logDock().text()));
    if (auto* viewport = window->viewport()) QCOMPARE(viewport->shading(), widgets::PointRenderer::Shading::Ambient);
}

void MainWindowTest::switchesTheLanguageFromTheMenu()
{
    auto window = makeWindow();
    QMenu* file = window->menuBar()->findChild<QMenu*>(QStringLiteral("menuFile"));
    QMenu* language = window->menuBar()->findChild<QMenu*>(QStringLiteral("menuLanguage"));
    QVERIFY(file && language);
    QCOMPARE(language->actions().size(), 4); // system, English, French, Greek
    const auto pick = [language](const QString& code) {
        for (QAction* action : language->actions())
            if (action->data().toString() == code) action->trigger();
    };
    pick(QStringLiteral("fr"));
    QCOMPARE(m_translations->loadedLanguage(), QStringLiteral("fr"));
    QTRY_COMPARE(file->title(), QStringLiteral("&Fichier")); // LanguageChange is posted, not sent
    QCOMPARE(app::Translations::savedLanguage(), QStringLiteral("fr"));
    // Qt's own dialogs (the file chooser) speak French too: qtbase's catalogue (qt6-translations-l10n).
    QCOMPARE(QCoreApplication::translate("QFileDialog", "Alt+Left"), QStringLiteral("Alt+Gauche")); // only Qt's has it
    // A plate's numbers take the chosen language's decimal point, whatever the system's locale.
    QCOMPARE(widgets::PlateTexts::translated({}).decimalPoint, QStringLiteral(","));
    pick(QStringLiteral("el"));
    QTRY_COMPARE(file->title(), QStringLiteral("&Αρχείο"));
    QCOMPARE(widgets::PlateTexts::translated({}).decimalPoint, QStringLiteral(","));
    pick(QStringLiteral("en"));
    QTRY_COMPARE(file->title(), QStringLiteral("&File"));
    QCOMPARE(widgets::PlateTexts::translated({}).decimalPoint, QStringLiteral("."));
    // Back to the system's language from another: the system's, not the last one chosen.
    pick(QStringLiteral("fr"));
    QTRY_COMPARE(file->title(), QStringLiteral("&Fichier"));
    pick(QString());
    const QLocale::Language system = QLocale::system().language();
    const QString expected = system == QLocale::French ? QStringLiteral("fr") : system == QLocale::Greek ? QStringLiteral("el")
                                                                                                         : QStringLiteral("en");
    QCOMPARE(m_translations->loadedLanguage(), expected);
    QCOMPARE(QLocale().language(), system);
}

void MainWindowTest::statusReadoutFormats()
{
    QLocale::setDefault(QLocale::c());
    QCOMPARE(app::StatusReadout::formatPoint({1.2344, -0.5, 2.0}), QStringLiteral("x 1.234  y -0.500  z 2.000 m"));
    QCOMPARE(app::StatusReadout::formatFrame(50.0, 1250000), QStringLiteral("20 fps · 50.0 ms · 1.25 M points"));
}

void MainWindowTest::closingCancelsTasksAndSavesTheLayout()
{
    auto window = makeWindow();
    window->importer().setCacheDirectory(m_dir.filePath("closing"));
    window->projectActions().openPaths({QString::fromStdString(m_drum.ply.string())});
    QVERIFY(!window->tasks().isIdle());
    auto* brush = window->findChild<QDoubleSpinBox*>(QStringLiteral("paintBrushSize"));
    QVERIFY(brush);
    brush->setValue(50.0); // mm
    QVERIFY(window->close()); // cancels the build and waits for its worker
    QVERIFY(QSettings().contains(QStringLiteral("mainWindow/state")));
    // The brush size comes back in the next session (it went back to 10 mm).
    {
        auto next = makeWindow();
        auto* again = next->findChild<QDoubleSpinBox*>(QStringLiteral("paintBrushSize"));
        QVERIFY(again);
        QCOMPARE(again->value(), 50.0);
        QVERIFY(next->close());
    }
    QVERIFY(window->tasks().waitForIdle(10000));
    // The cancelled build added nothing and left nothing behind.
    QCOMPARE(window->document().scene().fragments().size(), std::size_t{0});
    QCOMPARE(QDir(m_dir.filePath("closing")).entryList(QDir::Files).size(), 0);
}

STYLOS_WIDGET_TEST_MAIN(MainWindowTest)
#include "MainWindowTest.moc"
