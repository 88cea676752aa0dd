// Axis guides made in the workbench: "Set axis from two points" (AxisPickTool through AxisGuideEditor) driven by
// synthesized clicks on a fragment in the 3D view sets the axis guide through the two picked points (its own frame,
// the pose undone), keeping its flute guides, as one undo step; a drag and a click off the fragment pick nothing;
// Escape cancels and gives the view back to navigation. "Edit axis…" (EditAxisDialog) refuses a zero direction
// with a message and stays open, then sets the typed axis (a unit direction) as one undo step.
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "stylos/core/scene/SceneEigen.h"
#include "stylos/widgets/docking/AxisGuideEditor.h"
#include "stylos/widgets/docking/AxisPickTool.h"
#include "stylos/widgets/docking/EditAxisDialog.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

#include <memory>

using stylos::widgets::AxisGuideEditor;
using stylos::widgets::AxisPickTool;
using stylos::widgets::EditAxisDialog;
using stylos::widgets::SceneDocument;
using stylos::widgets::TaskManager;
using stylos::widgets::ViewportWidget;
namespace scene = stylos::core::scene;

class AxisGuideTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void twoClicksSetTheAxisAsOneUndoStep();
    void escapeCancels();
    void theDialogRefusesAZeroDirection();
    void reverseTurnsTheAxisEndForEnd();

private:
    void click(const QPoint& p) { QTest::mouseClick(m_view.get(), Qt::LeftButton, {}, p); }

    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
    std::unique_ptr<ViewportWidget> m_view;
    std::unique_ptr<TaskManager> m_tasks;
    std::unique_ptr<SceneDocument> m_document;
    std::unique_ptr<AxisGuideEditor> m_editor;
    scene::FragmentId m_id = 0;
    scene::Pose m_pose = scene::Pose::fromTranslationAngles({{0.3, -0.2, 0.1}, {0.0, 0.0, 0.5}});
};

void AxisGuideTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path(), 0.02, 5);
}

void AxisGuideTest::init()
{
    m_editor.reset();
    m_document.reset();
    m_tasks = std::make_unique<TaskManager>();
    m_document = std::make_unique<SceneDocument>(*m_tasks);
    scene::Fragment drum;
    drum.name = "drum";
    drum.octreePath = m_drum.poct;
    drum.pose = m_pose;
    drum.guides.push_back({"Flute 1", scene::GuideKind::Groove, {0, 0, 0}, {0, 0, 1}});
    m_id = m_document->addFragment(drum, m_drum.octree);
    m_document->undoStack()->clear();
    if (ViewportWidget::isSupported() && !m_view) {
        m_view = std::make_unique<ViewportWidget>();
        m_view->resize(320, 240);
        m_view->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
        stylos::core::view::ViewFragment f;
        f.id = m_id;
        f.octree = m_drum.octree;
        f.pose = scene::toEigen(m_pose);
        m_view->setFragments({f});
        QTRY_VERIFY_WITH_TIMEOUT(m_view->isSettled(), 20000);
    }
    m_editor = std::make_unique<AxisGuideEditor>(*m_document, m_view.get());
}

void AxisGuideTest::twoClicksSetTheAxisAsOneUndoStep()
{
    if (!m_view) QSKIP("no OpenGL 3.3 on this platform (run under xvfb-run)");
    const QPoint a(160, 90), b(160, 150);
    const auto pa = m_view->pickAt(a), pb = m_view->pickAt(b);
    QVERIFY(pa && pb && pa->fragmentId == m_id && pb->fragmentId == m_id);
    QVERIFY(m_editor->startPicking(m_id));
    QVERIFY(m_editor->isPicking());
    QCOMPARE(m_view->cursor().shape(), Qt::CrossCursor);
    auto* tool = static_cast<AxisPickTool*>(m_view->tool());
    // A drag is navigation (it orbits), and a click off the fragment picks nothing.
    const auto camera = m_view->camera();
    QTest::mousePress(m_view.get(), Qt::LeftButton, {}, a);
    QTest::mouseMove(m_view.get(), a + QPoint(30, 0));
    QTest::mouseRelease(m_view.get(), Qt::LeftButton, {}, a + QPoint(30, 0));
    QCOMPARE(tool->points().size(), std::size_t(0));
    m_view->setCamera(camera, false);
    click(QPoint(2, 2));
    QCOMPARE(tool->points().size(), std::size_t(0));
    // Two clicks on the fragment: its axis guide through the two points, in its own frame, one undo step.
    click(a);
    QCOMPARE(tool->points().size(), std::size_t(1));
    click(b);
    QCOMPARE(m_document->undoStack()->count(), 1);
    const auto& guides = m_document->fragment(m_id)->guides;
    QCOMPARE(guides.size(), std::size_t(2));
    QCOMPARE(guides[0].kind, scene::GuideKind::Axis);
    QCOMPARE(guides[1].kind, scene::GuideKind::Groove);
    const scene::Pose toLocal = m_pose.rigidInverse();
    const Eigen::Vector3d la = scene::apply(toLocal, pa->point), lb = scene::apply(toLocal, pb->point);
    const Eigen::Vector3d direction = (lb - la).normalized();
    for (int k = 0; k < 3; ++k) {
        QVERIFY(std::abs(guides[0].origin[std::size_t(k)] - la[k]) < 1e-9);
        QVERIFY(std::abs(guides[0].direction[std::size_t(k)] - direction[k]) < 1e-9);
    }
    QTRY_VERIFY(!m_editor->isPicking()); // the view is navigation's again
    QVERIFY(m_view->tool() == nullptr);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->fragment(m_id)->guides.size(), std::size_t(1));
}

void AxisGuideTest::escapeCancels()
{
    if (!m_view) QSKIP("no OpenGL 3.3 on this platform (run under xvfb-run)");
    const QPoint a(160, 100);
    QVERIFY(m_view->pickAt(a));
    QSignalSpy picking(m_editor.get(), &AxisGuideEditor::pickingChanged);
    QVERIFY(m_editor->startPicking(m_id));
    click(a);
    QCOMPARE(static_cast<AxisPickTool*>(m_view->tool())->points().size(), std::size_t(1));
    QTest::keyClick(m_view.get(), Qt::Key_Escape);
    QTRY_VERIFY(!m_editor->isPicking());
    QVERIFY(m_view->tool() == nullptr);
    QCOMPARE(picking.size(), 2); // on, then off
    QCOMPARE(m_document->undoStack()->count(), 0);
    QCOMPARE(m_document->fragment(m_id)->guides.size(), std::size_t(1));
}

void AxisGuideTest::theDialogRefusesAZeroDirection()
{
    QWidget parent;
    EditAxisDialog* dialog = m_editor->editAxis(m_id, &parent);
    QVERIFY(dialog != nullptr);
    QVERIFY(dialog->isVisible());
    QCOMPARE(dialog->direction(), Eigen::Vector3d(0, 0, 1)); // no axis yet: a vertical one offered
    dialog->setDirection(Eigen::Vector3d::Zero());
    dialog->buttons()->button(QDialogButtonBox::Ok)->click();
    QVERIFY(dialog->isVisible()); // refused, still open
    QVERIFY(dialog->errorLabel()->text().contains(QStringLiteral("cannot be zero")));
    QCOMPARE(m_document->undoStack()->count(), 0);
    dialog->setPoint({0.1, 0.2, 0.3});
    dialog->setDirection({0.0, 3.0, 4.0});
    dialog->buttons()->button(QDialogButtonBox::Ok)->click();
    QCOMPARE(m_document->undoStack()->count(), 1);
    const auto& guides = m_document->fragment(m_id)->guides;
    QCOMPARE(guides.size(), std::size_t(2)); // the axis in front, the flute kept
    QCOMPARE(guides[0].kind, scene::GuideKind::Axis);
    QCOMPARE(guides[0].origin, (std::array<double, 3>{0.1, 0.2, 0.3}));
    QVERIFY(std::abs(guides[0].direction[1] - 0.6) < 1e-15 && std::abs(guides[0].direction[2] - 0.8) < 1e-15);
    QCOMPARE(guides[1].kind, scene::GuideKind::Groove);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->fragment(m_id)->guides.size(), std::size_t(1));
}

// "Reverse axis": a drum lying on its side gets the axis sign "largest world component positive" from the fit, which
// may point down; the user turns it over: the same line, the opposite direction, the flute guides kept, one step.
void AxisGuideTest::reverseTurnsTheAxisEndForEnd()
{
    QVERIFY(!m_editor->reverseAxis(m_id)); // no axis guide yet: nothing
    QCOMPARE(m_document->undoStack()->count(), 0);
    QVERIFY(m_editor->setAxis(m_id, {0.1, 0.2, 0.3}, {0.0, -3.0, 4.0}, QStringLiteral("axis")));
    QSignalSpy reported(m_editor.get(), &AxisGuideEditor::reported);
    QVERIFY(m_editor->reverseAxis(m_id));
    QCOMPARE(m_document->undoStack()->count(), 2);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Reverse the axis of drum"));
    const auto& guides = m_document->fragment(m_id)->guides;
    QCOMPARE(guides.size(), std::size_t(2));
    QCOMPARE(guides[0].kind, scene::GuideKind::Axis);
    QCOMPARE(guides[1].name, std::string("Flute 1"));
    QCOMPARE(guides[0].origin, (std::array<double, 3>{0.1, 0.2, 0.3}));
    QCOMPARE(guides[0].direction, (std::array<double, 3>{-0.0, 0.6, -0.8}));
    QCOMPARE(reported.size(), 1);
    QCOMPARE(reported.at(0).at(1).toBool(), false);
    QVERIFY(m_editor->reverseAxis(m_id)); // and back
    QCOMPARE(m_document->fragment(m_id)->guides[0].direction, (std::array<double, 3>{0.0, -0.6, 0.8}));
    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    QCOMPARE(m_document->fragment(m_id)->guides[0].direction, (std::array<double, 3>{0.0, -0.6, 0.8}));
}

STYLOS_WIDGET_TEST_MAIN(AxisGuideTest)
#include "AxisGuideTest.moc"
