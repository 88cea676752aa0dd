// The placement in the drum frame (Properties dock): the values read for a piece placed by hand about the drum's
// axis guide; a typed θ, z, r or tilt moves the piece to the pose placeInDrumFrame gives with the other values
// kept, one undo step per edit that undo() takes back exactly; a fragment without a drum leaves the fields off.
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "stylos/core/dock/DrumFramePose.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/view/GuideGeometry.h"
#include "stylos/widgets/docking/DrumFramePoseWidget.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QUndoStack>

#include <cmath>
#include <memory>
#include <numbers>

using stylos::widgets::DrumFramePoseWidget;
using stylos::widgets::SceneDocument;
using stylos::widgets::TaskManager;
namespace scene = stylos::core::scene;
namespace dock = stylos::core::dock;

namespace {
constexpr double Degree = std::numbers::pi / 180;
} // namespace

class DrumFramePoseWidgetTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void readsThePlacementAboutTheDrumAxis();
    void typingAValueMovesThePieceAsOneUndoStep_data();
    void typingAValueMovesThePieceAsOneUndoStep();
    void aFragmentWithoutADrumHasNoFields();

private:
    /** Types @p text into @p spin and presses Enter (keyboard tracking is off: one edit). */
    static void type(QDoubleSpinBox* spin, const QString& text)
    {
        spin->setFocus();
        spin->selectAll();
        QTest::keyClicks(spin, text);
        QTest::keyClick(spin, Qt::Key_Return);
    }
    dock::DrumFramePose read() const
    {
        const dock::DrumFrame frame(stylos::core::unroll::Axis{m_centre, Eigen::Vector3d::UnitZ()});
        const Eigen::Isometry3d drum(scene::toEigen(m_document->worldPose(m_drumId)));
        const Eigen::Isometry3d piece(scene::toEigen(m_document->worldPose(m_pieceId)));
        return dock::drumFramePose(frame, drum.inverse() * piece, m_centre);
    }

    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
    std::unique_ptr<TaskManager> m_tasks;
    std::unique_ptr<SceneDocument> m_document;
    std::unique_ptr<DrumFramePoseWidget> m_widget;
    Eigen::Vector3d m_centre = Eigen::Vector3d::Zero();
    scene::FragmentId m_drumId = 0;
    scene::FragmentId m_pieceId = 0;
};

void DrumFramePoseWidgetTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path(), 0.02, 5);
    m_centre = stylos::core::view::occupiedBounds(*m_drum.octree).center();
}

void DrumFramePoseWidgetTest::init()
{
    // The drum (its axis vertical through its centre) turned and moved in the scene, and a piece (the same octree,
    // so its centre is the drum's) 0.6 m along the drum frame's e1, 0.05 m up, docking against the drum.
    m_widget.reset();
    m_document.reset();
    m_tasks = std::make_unique<TaskManager>();
    m_document = std::make_unique<SceneDocument>(*m_tasks);
    scene::Fragment drum;
    drum.name = "drum";
    drum.octreePath = m_drum.poct;
    drum.guides.push_back({"Axis", scene::GuideKind::Axis, scene::toArray(m_centre), {0, 0, 1}});
    drum.pose = scene::Pose::fromTranslationAngles({{1.0, 2.0, 0.5}, {0.0, 0.0, 0.3}});
    m_drumId = m_document->addFragment(drum, m_drum.octree);
    const dock::DrumFrame frame(stylos::core::unroll::Axis{m_centre, Eigen::Vector3d::UnitZ()});
    const dock::DrumFramePose start{.theta = 0.0, .z = frame.toFrame(m_centre).z() + 0.05, .r = 0.6, .spin = 0.0};
    const Eigen::Isometry3d relative = dock::placeInDrumFrame(frame, start, m_centre);
    scene::Fragment piece;
    piece.name = "piece";
    piece.octreePath = m_drum.poct;
    piece.pose = scene::poseFromEigen((Eigen::Isometry3d(scene::toEigen(drum.pose)) * relative).matrix());
    m_pieceId = m_document->addFragment(piece, m_drum.octree);
    QVERIFY(m_document->setDockingDrum(m_drumId));
    m_document->undoStack()->clear();
    m_widget = std::make_unique<DrumFramePoseWidget>(*m_document);
    m_widget->setFragment(m_pieceId);
    m_widget->show();
}

void DrumFramePoseWidgetTest::readsThePlacementAboutTheDrumAxis()
{
    QVERIFY(m_widget->isAvailable());
    QVERIFY(m_widget->field(DrumFramePoseWidget::Theta)->isEnabled());
    QCOMPARE(m_widget->field(DrumFramePoseWidget::Theta)->value(), 0.0);
    QCOMPARE(m_widget->field(DrumFramePoseWidget::R)->value(), 600.0);
    QCOMPARE(m_widget->field(DrumFramePoseWidget::Z)->value(), 50.0);
    QCOMPARE(m_widget->field(DrumFramePoseWidget::TiltLean)->value(), 0.0);
    QCOMPARE(m_widget->field(DrumFramePoseWidget::TiltRoll)->value(), 0.0);
    QCOMPARE(m_widget->field(DrumFramePoseWidget::Spin)->value(), std::round(read().spin / Degree * 1e3) / 1e3);
    QVERIFY(m_widget->statusLabel()->text().contains(QStringLiteral("drum")));
    // The drum's own octree is the piece's: the drum itself has no drum to be placed in.
    m_widget->setFragment(m_drumId);
    QVERIFY(!m_widget->isAvailable());
    // It says so (it said the drum had no drum with an axis guide).
    QCOMPARE(m_widget->statusLabel()->text(), QStringLiteral("This is the drum the others are placed against: select one of them."));
}

void DrumFramePoseWidgetTest::typingAValueMovesThePieceAsOneUndoStep_data()
{
    QTest::addColumn<int>("field");
    QTest::addColumn<QString>("text");
    QTest::addColumn<double>("value"); // metres or radians
    QTest::newRow("theta") << int(DrumFramePoseWidget::Theta) << QStringLiteral("7.5") << 7.5 * Degree;
    QTest::newRow("z") << int(DrumFramePoseWidget::Z) << QStringLiteral("-12.25") << -0.01225;
    QTest::newRow("r") << int(DrumFramePoseWidget::R) << QStringLiteral("545") << 0.545;
    QTest::newRow("lean") << int(DrumFramePoseWidget::TiltLean) << QStringLiteral("2") << 2 * Degree;
    QTest::newRow("roll") << int(DrumFramePoseWidget::TiltRoll) << QStringLiteral("-1.5") << -1.5 * Degree;
    QTest::newRow("spin") << int(DrumFramePoseWidget::Spin) << QStringLiteral("12.5") << 12.5 * Degree;
}

void DrumFramePoseWidgetTest::typingAValueMovesThePieceAsOneUndoStep()
{
    QFETCH(int, field);
    QFETCH(QString, text);
    QFETCH(double, value);
    const scene::Pose before = m_document->fragment(m_pieceId)->pose;
    const dock::DrumFramePose start = read();
    type(m_widget->field(DrumFramePoseWidget::Field(field)), text);
    QCOMPARE(m_document->undoStack()->count(), 1);
    const dock::DrumFramePose now = read();
    // Six values, the whole placement: the one typed changes, the others stay.
    const auto values = [](const dock::DrumFramePose& p) {
        return std::array<double, 6>{p.theta, p.z, p.r, p.tiltLean, p.tiltRoll, p.spin};
    };
    for (int index = 0; index < 6; ++index) {
        const double expected = index == field ? value : values(start)[std::size_t(index)];
        const double got = values(now)[std::size_t(index)];
        QVERIFY2(std::abs(got - expected) < 1e-9,
                 qPrintable(QStringLiteral("%1: %2, expected %3").arg(index).arg(got).arg(expected)));
    }
    // The fields show the new value; undo puts the pose back exactly.
    QCOMPARE(m_widget->field(DrumFramePoseWidget::Field(field))->text().remove(QLatin1Char(' ')).startsWith(text), true);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->fragment(m_pieceId)->pose, before);
}

void DrumFramePoseWidgetTest::aFragmentWithoutADrumHasNoFields()
{
    QVERIFY(m_document->setDockingDrum(scene::NoFragment));
    QVERIFY(!m_widget->isAvailable());
    for (int i = 0; i < DrumFramePoseWidget::FieldCount; ++i)
        QVERIFY(!m_widget->field(DrumFramePoseWidget::Field(i))->isEnabled());
    QVERIFY(m_widget->statusLabel()->text().contains(QStringLiteral("axis guide")));
    m_widget->setFragment(scene::NoFragment);
    QVERIFY(!m_widget->isAvailable());
}

STYLOS_WIDGET_TEST_MAIN(DrumFramePoseWidgetTest)
#include "DrumFramePoseWidgetTest.moc"
