// "Fit drum guides" in the workbench: the background task on a generated drum (48 flutes) gives one Axis and
// 48 Groove guides in the fragment's frame as one undo step, undone and redone exactly; they survive save and
// reopen; "Delete guides" is one step too; a drum whose flutes cannot be found (a coarse octree) reports why and
// changes nothing; the guides are drawn in the 3D view (one segment each) and can be hidden.
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/widgets/docking/GuideFitRunner.h"
#include "stylos/widgets/docking/GuidesDisplay.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

#include <cmath>

using stylos::widgets::GuideFitResult;
using stylos::widgets::GuideFitRunner;
using stylos::widgets::SceneDocument;
using stylos::widgets::TaskManager;
namespace scene = stylos::core::scene;

class GuideFitTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void fitsTheDrumAsOneUndoStep();
    void noFlutesChangesNothing();
    void aCancelledFitIsSaidAndChangesNothing();
    void theGuidesAreDrawn();

private:
    scene::FragmentId addDrum(SceneDocument& document, const std::filesystem::path& poct);

    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
};

void GuideFitTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path(), 0.01, 7);
}

scene::FragmentId GuideFitTest::addDrum(SceneDocument& document, const std::filesystem::path& poct)
{
    scene::Fragment f;
    f.name = "drum";
    f.octreePath = poct;
    auto opened = stylos::core::octree::PackedOctree::open(poct);
    if (!opened) qFatal("open: %s", opened.error().message.c_str());
    return document.addFragment(f, std::make_shared<const stylos::core::octree::PackedOctree>(std::move(*opened)));
}

void GuideFitTest::fitsTheDrumAsOneUndoStep()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    GuideFitRunner runner(document);
    const scene::FragmentId id = addDrum(document, m_drum.poct);
    QSignalSpy fitted(&runner, &GuideFitRunner::fitted);
    QSignalSpy failed(&runner, &GuideFitRunner::failed);
    QVERIFY(runner.start(id));
    QVERIFY(!runner.start(id)); // one at a time
    QTRY_COMPARE_WITH_TIMEOUT(fitted.size(), 1, 60000);
    QCOMPARE(failed.size(), 0);
    QCOMPARE(document.undoStack()->count(), 2);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Fit the guides of drum"));

    const auto guides = document.fragment(id)->guides;
    QCOMPARE(guides.size(), 49u);
    QCOMPARE(guides[0].kind, scene::GuideKind::Axis);
    QCOMPARE(guides[0].name, std::string("Axis"));
    for (std::size_t k = 1; k < guides.size(); ++k) {
        QCOMPARE(guides[k].kind, scene::GuideKind::Groove);
        // Each flute line parallel to the axis.
        const Eigen::Vector3d a(guides[0].direction.data()), d(guides[k].direction.data());
        QVERIFY(std::abs(a.dot(d)) > 1 - 1e-12);
    }
    QCOMPARE(guides[48].name, std::string("Flute 48"));
    const auto result = fitted.first().at(1).value<GuideFitResult>();
    QCOMPARE(result.flutes, 48);
    QVERIFY(result.radius > 0.5 && result.radius < 0.6);

    document.undoStack()->undo();
    QVERIFY(document.fragment(id)->guides.empty());
    document.undoStack()->redo();
    QVERIFY(document.fragment(id)->guides == guides);

    // Saved and opened again: the same guides, bit for bit.
    const QString project = m_dir.filePath(QStringLiteral("guides.stylos"));
    QString error;
    QVERIFY2(document.saveAs(project, &error), qPrintable(error));
    SceneDocument reopened(tasks);
    QVERIFY2(reopened.open(project, &error), qPrintable(error));
    QCOMPARE(reopened.scene().size(), 1u);
    QVERIFY(reopened.scene().fragments().front().guides == guides);

    // Delete guides: one step, undone.
    QVERIFY(runner.deleteGuides(id));
    QVERIFY(document.fragment(id)->guides.empty());
    QCOMPARE(document.undoStack()->count(), 3);
    QVERIFY(!runner.deleteGuides(id)); // nothing left
    document.undoStack()->undo();
    QVERIFY(document.fragment(id)->guides == guides);
    tasks.cancelAllAndWait();
}

void GuideFitTest::noFlutesChangesNothing()
{
    // The same drum at depth 6: its leaves are too coarse for the flutes to stand out.
    const std::filesystem::path coarse = std::filesystem::path(m_dir.path().toStdString()) / "coarse.poct";
    stylos::core::octree::BuildOptions build;
    build.depth = 6;
    build.threads = 1;
    QVERIFY(stylos::core::octree::buildOctreeFile(m_drum.ply, coarse, build).ok());
    TaskManager tasks;
    SceneDocument document(tasks);
    GuideFitRunner runner(document);
    const scene::FragmentId id = addDrum(document, coarse);
    QSignalSpy fitted(&runner, &GuideFitRunner::fitted);
    QSignalSpy failed(&runner, &GuideFitRunner::failed);
    QVERIFY(runner.start(id));
    QTRY_COMPARE_WITH_TIMEOUT(failed.size(), 1, 60000);
    QCOMPARE(fitted.size(), 0);
    const QString message = failed.first().at(1).toString();
    QVERIFY2(message.startsWith(QStringLiteral("Could not fit the guides of drum:")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("no flutes found")), qPrintable(message));
    QVERIFY(document.fragment(id)->guides.empty());
    QCOMPARE(document.undoStack()->count(), 1);
    tasks.cancelAllAndWait();
}

void GuideFitTest::aCancelledFitIsSaidAndChangesNothing()
{
    // Cancelled from the Tasks dock: a line for the log (nothing was said), no error, the guides untouched.
    TaskManager tasks;
    SceneDocument document(tasks);
    GuideFitRunner runner(document);
    const scene::FragmentId id = addDrum(document, m_drum.poct);
    QSignalSpy fitted(&runner, &GuideFitRunner::fitted);
    QSignalSpy failed(&runner, &GuideFitRunner::failed);
    QSignalSpy cancelled(&runner, &GuideFitRunner::cancelled);
    QVERIFY(runner.start(id));
    tasks.cancelAll();
    QTRY_COMPARE_WITH_TIMEOUT(cancelled.size(), 1, 60000);
    QCOMPARE(cancelled.first().at(0).toULongLong(), quint64(id));
    QCOMPARE(cancelled.first().at(1).toString(), QStringLiteral("Fitting the guides of drum was cancelled"));
    QCOMPARE(fitted.size(), 0);
    QCOMPARE(failed.size(), 0);
    QVERIFY(document.fragment(id)->guides.empty());
    tasks.cancelAllAndWait();
}

void GuideFitTest::theGuidesAreDrawn()
{
    if (!stylos::widgets::ViewportWidget::isSupported()) QSKIP("no OpenGL 3.3 on this platform (run under xvfb-run)");
    TaskManager tasks;
    SceneDocument document(tasks);
    stylos::widgets::ViewportWidget view;
    stylos::widgets::GuidesDisplay display(document, view);
    const scene::FragmentId id = addDrum(document, m_drum.poct);
    display.pushNow();
    QCOMPARE(display.segmentCount(), 0);
    std::vector<scene::Guide> guides;
    guides.push_back({"Axis", scene::GuideKind::Axis, {0, 0, 0}, {0, 0, 1}});
    guides.push_back({"Flute 1", scene::GuideKind::Groove, {0.5, 0, 0}, {0, 0, 1}});
    QVERIFY(document.setFragmentGuides(id, guides));
    QTRY_COMPARE(display.segmentCount(), 2);
    QVERIFY(document.setFragmentVisible(id, false)); // a hidden fragment's guides are not drawn
    QTRY_COMPARE(display.segmentCount(), 0);
    display.setVisible(false);
    QVERIFY(!display.isVisible());
}

STYLOS_WIDGET_TEST_MAIN(GuideFitTest)
#include "GuideFitTest.moc"
