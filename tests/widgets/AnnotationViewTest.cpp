// The annotation in the 3D view, wired as in the window (SceneDocument → ViewportSync + AnnotationSync → view;
// AnnotationActions' lasso): the Annotation shading mixes a labelled cell's shading 0.35 : 0.65 with its class
// colour (read back at the view's centre), a label change shows with no new cut (only the labels' range is
// sent), other layers and unlabelled cells keep the plain shading; the lasso, driven by synthesized mouse events,
// labels exactly the leaves core::view::lassoVisibleLeaves returns for its polygon, in one undo step; Ctrl erases;
// Escape cancels.
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "AnnotationActions.h"
#include "AnnotationSync.h"
#include "ViewportSync.h"

#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/view/LassoVisibility.h"
#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/annotation/LassoTool.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QAction>
#include <QComboBox>
#include <QMenu>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QToolBar>
#include <QUndoStack>

#include <numeric>

using stylos::core::annotation::AnnotationLayer;
using stylos::core::scene::FragmentId;
using stylos::widgets::PointRenderer;
using stylos::widgets::SceneDocument;
using stylos::widgets::ViewportWidget;

class AnnotationViewTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void theShadingTintsLabelledCellsWithoutANewCut();
    void theLassoLabelsTheVisibleLeavesInOneStep();
    void escapeCancelsTheLasso();

private:
    void settle();
    std::vector<std::uint8_t> labels(AnnotationLayer layer) const { return *m_document->labels().labels(m_id, layer); }

    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
    std::unique_ptr<stylos::widgets::TaskManager> m_tasks;
    std::unique_ptr<SceneDocument> m_document;
    std::unique_ptr<QWidget> m_window;
    ViewportWidget* m_view = nullptr;
    stylos::app::ViewportSync* m_sync = nullptr;
    stylos::app::AnnotationSync* m_annotationSync = nullptr;
    stylos::app::AnnotationActions* m_actions = nullptr;
    FragmentId m_id = 0;
    std::size_t m_leaves = 0;
};

void AnnotationViewTest::initTestCase()
{
    if (!ViewportWidget::isSupported()) QSKIP("no OpenGL 3.3 on this platform (run under xvfb-run)");
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path(), 0.01, 6);
    m_tasks = std::make_unique<stylos::widgets::TaskManager>();
    m_document = std::make_unique<SceneDocument>(*m_tasks);
    stylos::core::scene::Fragment f;
    f.name = "drum";
    f.octreePath = m_drum.poct.string();
    f.colour = {200, 190, 170};
    m_id = m_document->addFragment(f, m_drum.octree);
    m_leaves = stylos::core::annotation::leafCount(*m_drum.octree);

    m_window = std::make_unique<QWidget>();
    m_view = new ViewportWidget(m_window.get());
    m_view->resize(320, 240);
    m_window->resize(320, 240);
    m_sync = new stylos::app::ViewportSync(*m_document, *m_view, m_window.get());
    m_annotationSync = new stylos::app::AnnotationSync(*m_document, *m_view, m_window.get());
    m_actions = new stylos::app::AnnotationActions(*m_document, m_view, m_annotationSync, *m_window);
    auto* tools = new QMenu(m_window.get());
    auto* shading = new QMenu(m_window.get());
    auto* toolBar = new QToolBar(m_window.get()); // holds the class box: it lives as long as the window
    toolBar->hide();
    m_actions->populate(*tools, shading, *toolBar);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_view->setShading(PointRenderer::Shading::Annotation);
    m_view->setStandardView(stylos::core::view::StandardView::Front);
    settle();
    m_view->fitToScene();
    settle();
    QVERIFY2(m_view->glError().isEmpty(), qPrintable(m_view->glError()));
    QCOMPARE(m_view->fragments().size(), std::size_t(1));
}

void AnnotationViewTest::cleanupTestCase()
{
    m_window.reset();
    m_document.reset();
}

void AnnotationViewTest::settle()
{
    QTest::qWait(0); // the syncs push on the next turn of the event loop
    QTRY_VERIFY_WITH_TIMEOUT(m_view->isSettled(), 20000);
}

void AnnotationViewTest::theShadingTintsLabelledCellsWithoutANewCut()
{
    const QImage plain = m_view->grabFramebuffer();
    const QPoint centre(plain.width() / 2, plain.height() / 2);
    const QColor before = plain.pixelColor(centre);
    QVERIFY2(before != QColor(33, 36, 41), "the drum is at the view's centre");

    // Material class 3 (plaster) on every leaf: pushed as a range of labels, no new cut.
    QSignalSpy cuts(&m_view->scheduler(), &stylos::widgets::LodScheduler::cutReady);
    std::vector<std::uint32_t> all(m_leaves);
    std::iota(all.begin(), all.end(), 0u);
    QVERIFY(m_document->setLabels(m_id, AnnotationLayer::Material, all, 3, QStringLiteral("Paint")));
    settle();
    QVERIFY(m_view->renderer().points().hasLabels(m_id));
    const QColor after = m_view->grabFramebuffer().pixelColor(centre);
    QCOMPARE(cuts.count(), 0);
    const auto& c = m_document->legend().find(AnnotationLayer::Material, 3)->colour;
    const auto mix = [](int shade, int cls) { return 0.35 * shade + 0.65 * cls; };
    QVERIFY2(std::abs(after.red() - mix(before.red(), c.r)) <= 3 && std::abs(after.green() - mix(before.green(), c.g)) <= 3 &&
                 std::abs(after.blue() - mix(before.blue(), c.b)) <= 3,
             qPrintable(QStringLiteral("before %1, after %2, class %3,%4,%5")
                            .arg(before.name(), after.name())
                            .arg(c.r).arg(c.g).arg(c.b)));

    // The tool-mark layer holds nothing: the plain shading again; back to material: the tint.
    m_annotationSync->setLayer(AnnotationLayer::Toolmark);
    settle();
    QCOMPARE(m_view->grabFramebuffer().pixelColor(centre), before);
    m_annotationSync->setLayer(AnnotationLayer::Material);
    settle();
    QCOMPARE(m_view->grabFramebuffer().pixelColor(centre), after);

    // Undo: the labels go, the plain shading comes back, still without a new cut.
    m_document->undoStack()->undo();
    settle();
    QCOMPARE(m_view->grabFramebuffer().pixelColor(centre), before);
    QCOMPARE(cuts.count(), 0);
}

void AnnotationViewTest::theLassoLabelsTheVisibleLeavesInOneStep()
{
    m_sync->setSelection({m_id});
    settle();
    m_actions->lassoAction()->setChecked(true);
    QVERIFY(dynamic_cast<stylos::widgets::LassoTool*>(m_view->tool()));
    m_actions->classBox()->setCurrentIndex(m_actions->classBox()->findData(2)); // fractured marble
    QCOMPARE(m_actions->activeClass(), std::uint8_t(2));

    // A square over the middle of the drum.
    const std::vector<QPoint> corners{{130, 90}, {190, 90}, {190, 150}, {130, 150}};
    std::vector<Eigen::Vector2d> polygon;
    for (const QPoint& p : corners) polygon.emplace_back(p.x(), p.y());
    const auto expected = stylos::core::view::lassoVisibleLeaves(m_view->fragments(), m_view->camera(), {m_id}, polygon);
    QCOMPARE(expected.size(), std::size_t(1));
    QVERIFY(expected[0].leaves.size() > 20);

    const int steps = m_document->undoStack()->index();
    QTest::mousePress(m_view, Qt::LeftButton, {}, corners[0]);
    for (std::size_t i = 1; i < corners.size(); ++i) QTest::mouseMove(m_view, corners[i]);
    auto* tool = dynamic_cast<stylos::widgets::LassoTool*>(m_view->tool());
    QCOMPARE(tool->polygon().size(), corners.size());
    QTest::mouseRelease(m_view, Qt::LeftButton, {}, corners.back());
    QVERIFY(tool->polygon().empty());
    QCOMPARE(m_document->undoStack()->index(), steps + 1);

    std::vector<std::uint8_t> want(m_leaves, 0);
    for (const std::uint32_t leaf : expected[0].leaves) want[leaf] = 2;
    QCOMPARE(labels(AnnotationLayer::Material), want);
    QCOMPARE(labels(AnnotationLayer::Toolmark), std::vector<std::uint8_t>(m_leaves, 0));
    settle();

    // Ctrl erases what the same lasso takes: one more step, all zero again; undo brings the class back.
    QTest::mousePress(m_view, Qt::LeftButton, {}, corners[0]);
    for (std::size_t i = 1; i < corners.size(); ++i) QTest::mouseMove(m_view, corners[i]);
    QTest::mouseRelease(m_view, Qt::LeftButton, Qt::ControlModifier, corners.back());
    QCOMPARE(m_document->undoStack()->index(), steps + 2);
    QCOMPARE(labels(AnnotationLayer::Material), std::vector<std::uint8_t>(m_leaves, 0));
    m_document->undoStack()->undo();
    QCOMPARE(labels(AnnotationLayer::Material), want);
    m_document->undoStack()->undo();
    QCOMPARE(labels(AnnotationLayer::Material), std::vector<std::uint8_t>(m_leaves, 0));
    settle();

    // The selected fragment hidden: nothing is labelled, and the message says why.
    QSignalSpy reported(m_actions, &stylos::app::AnnotationActions::reported);
    m_document->setFragmentVisible(m_id, false);
    settle();
    const int hiddenSteps = m_document->undoStack()->index();
    QTest::mousePress(m_view, Qt::LeftButton, {}, corners[0]);
    for (std::size_t i = 1; i < corners.size(); ++i) QTest::mouseMove(m_view, corners[i]);
    QTest::mouseRelease(m_view, Qt::LeftButton, {}, corners.back());
    QCOMPARE(m_document->undoStack()->index(), hiddenSteps);
    QCOMPARE(reported.count(), 1);
    QVERIFY2(reported.at(0).at(0).toString().contains(QStringLiteral("hidden")), qPrintable(reported.at(0).at(0).toString()));
    m_document->undoStack()->undo();
    settle();
}

void AnnotationViewTest::escapeCancelsTheLasso()
{
    m_actions->lassoAction()->setChecked(true);
    auto* tool = dynamic_cast<stylos::widgets::LassoTool*>(m_view->tool());
    QVERIFY(tool);
    const int steps = m_document->undoStack()->index();
    const auto camera = m_view->camera();
    QTest::mousePress(m_view, Qt::LeftButton, {}, QPoint(130, 90));
    QTest::mouseMove(m_view, QPoint(190, 90));
    QTest::mouseMove(m_view, QPoint(190, 150));
    QCOMPARE(tool->polygon().size(), std::size_t(3));
    QTest::keyClick(m_view, Qt::Key_Escape);
    QVERIFY(tool->polygon().empty());
    QTest::mouseRelease(m_view, Qt::LeftButton, {}, QPoint(130, 150));
    QCOMPARE(m_document->undoStack()->index(), steps);
    QCOMPARE(labels(AnnotationLayer::Material), std::vector<std::uint8_t>(m_leaves, 0));
    QVERIFY(m_view->camera().viewMatrix() == camera.viewMatrix()); // nor did navigation take the drag

    // Unchecking the action gives the view back to navigation.
    m_actions->lassoAction()->setChecked(false);
    QVERIFY(m_view->tool() == nullptr);
}

STYLOS_WIDGET_TEST_MAIN(AnnotationViewTest)
#include "AnnotationViewTest.moc"
