// SceneTreeModel and FragmentPropertiesWidget: the Scene dock's tree follows the document (rows, guides,
// check boxes, colours) and edits made in it or in the Properties dock go through the undo stack.
#include "SceneTestSupport.h"
#include "WidgetTestSupport.h"

#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/view/GuideGeometry.h"
#include "stylos/widgets/developpee/DeveloppeeJob.h"
#include "stylos/widgets/document/FragmentPropertiesWidget.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/document/SceneTreeModel.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QAbstractItemModelTester>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMimeData>
#include <QScrollArea>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QWheelEvent>

#include <numbers>

using stylos::core::scene::Fragment;
using stylos::core::scene::FragmentId;
using stylos::core::scene::Guide;
using stylos::core::scene::GuideKind;
using stylos::core::scene::Pose;
using stylos::widgets::FragmentPropertiesWidget;
using stylos::widgets::SceneDocument;
using stylos::widgets::SceneTreeModel;
using stylos::widgets::TaskManager;

class SceneTreeModelTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void rowsFollowTheDocument();
    void editsInTheTreeAreUndoable();
    void developpeeRowFollowsTheDocument();
    void propertiesShowAndEditTheFragment();
    void poseFieldsReadScientificNotation();
    void theWheelScrollsPastUnfocusedPoseFields();
    void assembliesAreRowsHoldingTheirMembersAndTakeDrops();

private:
    Fragment fragment(const QString& name, int guides = 0) const;

    QTemporaryDir m_dir;
    QString m_octreePath;
    SceneDocument::OctreePtr m_octree;
};

void SceneTreeModelTest::initTestCase()
{
    m_octreePath = stylos::test::makeOctreeFile(m_dir.path(), "piece.poct");
    auto opened = stylos::core::octree::PackedOctree::open(m_octreePath.toStdString());
    QVERIFY(opened.ok());
    m_octree = std::make_shared<const stylos::core::octree::PackedOctree>(std::move(opened).value());
}

Fragment SceneTreeModelTest::fragment(const QString& name, int guides) const
{
    Fragment f;
    f.name = name.toStdString();
    f.octreePath = m_octreePath.toStdString();
    f.colour = {10, 200, 30};
    for (int i = 0; i < guides; ++i)
        f.guides.push_back(Guide{i == 0 ? "axis" : "groove " + std::to_string(i), i == 0 ? GuideKind::Axis : GuideKind::Groove});
    return f;
}

void SceneTreeModelTest::rowsFollowTheDocument()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    SceneTreeModel model(doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);

    const FragmentId drum = doc.addFragment(fragment("drum", 3), m_octree);
    const FragmentId piece = doc.addFragment(fragment("piece"), m_octree);
    QCOMPARE(model.rowCount(), 2);
    const QModelIndex drumRow = model.indexOf(drum);
    QCOMPARE(drumRow.row(), 0);
    QCOMPARE(model.data(drumRow).toString(), QString("drum"));
    QCOMPARE(model.data(drumRow, Qt::CheckStateRole).toInt(), int(Qt::Checked));
    QCOMPARE(model.data(drumRow, Qt::DecorationRole).value<QColor>(), QColor(10, 200, 30));
    QCOMPARE(model.data(drumRow, SceneTreeModel::FragmentIdRole).toULongLong(), drum);
    QCOMPARE(model.rowCount(drumRow), 3);
    QCOMPARE(model.rowCount(model.indexOf(piece)), 0);
    const QModelIndex groove = model.index(2, 0, drumRow);
    QCOMPARE(model.data(groove).toString(), QString("groove 2"));
    QCOMPARE(model.data(groove, Qt::ToolTipRole).toString(), QString("Groove"));
    QCOMPARE(model.data(groove, SceneTreeModel::GuideIndexRole).toInt(), 2);
    QCOMPARE(model.parent(groove), drumRow);
    QCOMPARE(model.fragmentAt(groove), drum);
    QVERIFY(model.isGuide(groove));
    QVERIFY(!model.isDeveloppee(groove));
    QVERIFY(!(model.flags(groove) & Qt::ItemIsEditable));

    QSignalSpy removed(&model, &QAbstractItemModel::rowsRemoved);
    doc.removeFragment(drum);
    QCOMPARE(model.rowCount(), 1);
    QCOMPARE(removed.size(), 1);
    QCOMPARE(model.data(model.index(0, 0)).toString(), QString("piece"));
    doc.undoStack()->undo();
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.rowCount(model.indexOf(drum)), 3);

    QSignalSpy reset(&model, &QAbstractItemModel::modelReset);
    doc.newProject();
    QCOMPARE(reset.size(), 1);
    QCOMPARE(model.rowCount(), 0);
}

void SceneTreeModelTest::editsInTheTreeAreUndoable()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    SceneTreeModel model(doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    const FragmentId id = doc.addFragment(fragment("drum"), m_octree);
    const QModelIndex row = model.indexOf(id);
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);

    QVERIFY(model.flags(row) & Qt::ItemIsEditable);
    QVERIFY(model.setData(row, "Drum 2"));
    QCOMPARE(doc.fragment(id)->name, std::string("Drum 2"));
    QCOMPARE(doc.undoStack()->undoText(), QString("Rename drum to Drum 2"));
    QVERIFY(!changed.isEmpty());
    QVERIFY(!model.setData(row, "   ")); // a fragment keeps a name
    QVERIFY(model.setData(row, Qt::Unchecked, Qt::CheckStateRole));
    QCOMPARE(doc.fragment(id)->visible, false);
    QCOMPARE(model.data(row, Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
    QCOMPARE(doc.undoStack()->count(), 3);

    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(model.data(row).toString(), QString("drum"));
    QCOMPARE(model.data(row, Qt::CheckStateRole).toInt(), int(Qt::Checked));
}

void SceneTreeModelTest::propertiesShowAndEditTheFragment()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    const FragmentId id = doc.addFragment(fragment("drum"), m_octree);
    const Pose pose = Pose::fromTranslationAngles({{1.25, -2.5, 3.0}, {0.0, 0.0, std::numbers::pi / 2}});
    doc.setFragmentPose(id, pose);
    FragmentPropertiesWidget properties(doc);
    properties.show();
    QVERIFY(!properties.nameEdit()->isEnabled());
    QCOMPARE(properties.pointsLabel()->text(), QString("–"));
    QCOMPARE(properties.sizeLabel()->text(), QString("–"));

    properties.setFragment(id);
    QVERIFY(properties.nameEdit()->isEnabled());
    QCOMPARE(properties.nameEdit()->text(), QString("drum"));
    QCOMPARE(properties.poseSpin(0)->value(), 1.25);
    QCOMPARE(properties.poseSpin(1)->value(), -2.5);
    QCOMPARE(properties.poseSpin(5)->value(), 90.0);
    const QLocale locale;
    QCOMPARE(properties.pointsLabel()->text(), locale.toString(qulonglong(m_octree->description().points)));
    QCOMPARE(properties.leafCellsLabel()->text(), locale.toString(qulonglong(m_octree->cellCount(5))));
    QCOMPARE(properties.totalCellsLabel()->text(), locale.toString(qulonglong(m_octree->totalCells())));
    QCOMPARE(properties.depthLabel()->text(), QString("5"));
    QCOMPARE(properties.fileLabel()->text(), m_octreePath);
    // The size: the leaves' extent along the fragment's own axes, in millimetres, whatever the pose (here a
    // quarter turn): the extent of every leaf cell, walked one by one.
    Eigen::AlignedBox3d leaves;
    m_octree->forEachCell(5, [&leaves](const stylos::core::octree::CellView& cell) {
        for (int corner = 0; corner < 2; ++corner)
            leaves.extend(Eigen::Vector3d(cell.centre[0], cell.centre[1], cell.centre[2]) +
                          Eigen::Vector3d::Constant((corner - 0.5) * cell.size));
        return true;
    });
    const auto mm = [&locale](double metres) { return locale.toString(metres * 1000.0, 'f', 1); };
    const QString size = QString("%1 × %2 × %3 mm").arg(mm(leaves.sizes().x()), mm(leaves.sizes().y()), mm(leaves.sizes().z()));
    QCOMPARE(properties.sizeLabel()->text(), size);
    QVERIFY(leaves.sizes().maxCoeff() > 0.05 && leaves.sizes().maxCoeff() < 1.0);

    // Editing the translation's z keeps the rotation and the other components bit for bit.
    const int before = doc.undoStack()->count();
    properties.poseSpin(2)->setValue(4.5);
    QCOMPARE(doc.undoStack()->count(), before + 1);
    QCOMPARE(doc.fragment(id)->pose, pose.withTranslation({1.25, -2.5, 4.5}));
    // Editing a rotation angle turns the fragment about its centre (as the gizmo does), not about its file frame's
    // origin: the centre stays, the translation follows.
    const Eigen::Vector3d centre = stylos::core::view::occupiedBounds(*m_octree).center();
    const Eigen::Vector3d centreBefore = stylos::core::scene::apply(doc.fragment(id)->pose, centre);
    properties.poseSpin(3)->setValue(30.0);
    const auto angles = doc.fragment(id)->pose.toTranslationAngles();
    QVERIFY(std::abs(angles.angles[0] - std::numbers::pi / 6) < 1e-12);
    QVERIFY(std::abs(angles.angles[2] - std::numbers::pi / 2) < 1e-12);
    QVERIFY((stylos::core::scene::apply(doc.fragment(id)->pose, centre) - centreBefore).norm() < 1e-12);
    QVERIFY(centre.norm() > 0.01); // so the translation had to change
    QVERIFY(angles.translation != (std::array<double, 3>{1.25, -2.5, 4.5}));
    QCOMPARE(properties.poseSpin(0)->value(), std::round(angles.translation[0] * 1e4) / 1e4); // and shows
    QCOMPARE(properties.sizeLabel()->text(), size); // turned, the same size

    properties.nameEdit()->setText("Drum 1");
    QMetaObject::invokeMethod(properties.nameEdit(), "editingFinished");
    QCOMPARE(doc.fragment(id)->name, std::string("Drum 1"));
    properties.visibleCheck()->setChecked(false);
    QCOMPARE(doc.fragment(id)->visible, false);

    // Undo shows in the fields.
    doc.undoStack()->undo();
    QVERIFY(properties.visibleCheck()->isChecked());
    doc.undoStack()->undo();
    QCOMPARE(properties.nameEdit()->text(), QString("drum"));
    doc.undoStack()->undo();
    QCOMPARE(properties.poseSpin(3)->value(), 0.0);
    QCOMPARE(doc.undoStack()->count(), before + 4); // undoing pushes nothing

    doc.removeFragment(id);
    QCOMPARE(properties.fragment(), stylos::core::scene::NoFragment);
    QVERIFY(!properties.nameEdit()->isEnabled());

    // A fragment whose octree is not open has no centre to turn about: its rotations are off, its translation on.
    Fragment gone = fragment("gone");
    gone.octreePath = (m_dir.path() + "/missing.poct").toStdString();
    const FragmentId goneId = doc.addFragment(gone, nullptr);
    properties.setFragment(goneId);
    QVERIFY(properties.poseSpin(0)->isEnabled());
    QVERIFY(!properties.poseSpin(3)->isEnabled() && !properties.poseSpin(5)->isEnabled());
}

void SceneTreeModelTest::poseFieldsReadScientificNotation()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    const FragmentId id = doc.addFragment(fragment("drum"), m_octree);
    FragmentPropertiesWidget properties(doc);
    properties.show();
    QVERIFY(QTest::qWaitForWindowExposed(&properties));
    properties.setFragment(id);
    QDoubleSpinBox* x = properties.poseSpin(0);
    const auto type = [x](const QString& text) {
        x->setFocus();
        x->selectAll();
        QTest::keyClicks(x, text);
        QTest::keyClick(x, Qt::Key_Return);
    };
    type("2.5e-3");
    QCOMPARE(x->value(), 0.0025);
    QCOMPARE(doc.fragment(id)->pose.toTranslationAngles().translation[0], 0.0025);
    type("-1.5E2");
    QCOMPARE(x->value(), -150.0);
    // Out of range (10,000 km at most): not applied, where the plain spin box dropped the "e" and read 112.
    const int edits = doc.undoStack()->count();
    type("1e12");
    QCOMPARE(x->value(), -150.0);
    x->clearFocus();
    QCOMPARE(x->value(), -150.0);
    QCOMPARE(doc.undoStack()->count(), edits);
    type("1e1x"); // the "x" is refused as typed
    QCOMPARE(x->value(), 10.0);
    type("12");
    QCOMPARE(x->value(), 12.0);
    // With a French decimal comma.
    x->setLocale(QLocale(QLocale::French, QLocale::France));
    type("2,5e1");
    QCOMPARE(x->value(), 25.0);
    type("2.5"); // a point typed where French writes a comma: the decimal point, not refused (25)
    QCOMPARE(x->value(), 2.5);
    type("2.5e-3");
    QCOMPARE(x->value(), 0.0025);
    // Greek groups with the point: scientific notation with a point still reads as such (it read 253).
    x->setLocale(QLocale(QLocale::Greek, QLocale::Greece));
    type("2.5e-3");
    QCOMPARE(x->value(), 0.0025);
    type("2,5");
    QCOMPARE(x->value(), 2.5);
    type("1.5"); // the point as a decimal point, never as Greek's group separator (it read 15)
    QCOMPARE(x->value(), 1.5);
    type("1.500");
    QCOMPARE(x->value(), 1.5);
    x->setLocale(QLocale::c());

    // A plain number out of range is not applied either (the spin box refused the last key: 720° became 72°).
    QDoubleSpinBox* rz = properties.poseSpin(5);
    const double turned = rz->value();
    const int before = doc.undoStack()->count();
    rz->setFocus();
    rz->selectAll();
    QTest::keyClicks(rz, QStringLiteral("720"));
    QTest::keyClick(rz, Qt::Key_Return);
    QCOMPARE(rz->value(), turned);
    QCOMPARE(doc.undoStack()->count(), before);
}

void SceneTreeModelTest::theWheelScrollsPastUnfocusedPoseFields()
{
    // Scrolling the Properties dock with the wheel passed over the pose fields and moved the fragment, one undo step
    // per notch: a field takes the wheel only once it has the focus.
    TaskManager tasks;
    SceneDocument doc(tasks);
    const FragmentId id = doc.addFragment(fragment("drum"), m_octree);
    QScrollArea area;
    auto* properties = new FragmentPropertiesWidget(doc);
    area.setWidget(properties);
    area.resize(300, 150); // smaller than the fields: the area scrolls
    area.show();
    area.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&area));
    properties->setFragment(id);
    QDoubleSpinBox* x = properties->poseSpin(0);
    // Qt passes a wheel event that a field leaves unaccepted on to its parents (the scroll area) when it comes from
    // the window system; one sent here is not propagated, so what is checked is that the field declines it.
    const auto wheel = [](QWidget* target) {
        const QPointF at(target->width() / 2.0, target->height() / 2.0);
        QWheelEvent event(at, target->mapToGlobal(at), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(target, &event);
        return event.isAccepted();
    };
    area.setFocus();
    QVERIFY(!x->hasFocus());
    const int steps = doc.undoStack()->count();
    for (QDoubleSpinBox* spin : {x, properties->poseSpin(5)}) QVERIFY(!wheel(spin));
    QCOMPARE(doc.undoStack()->count(), steps);
    QCOMPARE(x->value(), 0.0);
    QVERIFY(!x->hasFocus());
    // Clicked into, the field steps with the wheel as before.
    x->setFocus();
    QVERIFY(x->hasFocus());
    QVERIFY(wheel(x));
    QCOMPARE(doc.undoStack()->count(), steps + 1);
    QVERIFY(x->value() != 0.0);
}

void SceneTreeModelTest::developpeeRowFollowsTheDocument()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    SceneTreeModel model(doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    const FragmentId drum = doc.addFragment(fragment("drum", 2), m_octree);
    const QModelIndex drumRow = model.indexOf(drum);
    QCOMPARE(model.rowCount(drumRow), 2);
    QVERIFY(!model.developpeeIndexOf(drum).isValid());

    auto result = std::make_shared<stylos::widgets::DeveloppeeResult>();
    result->fragmentId = drum;
    result->image = QImage(532, 79, QImage::Format_ARGB32_Premultiplied);
    QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
    QVERIFY(doc.setDeveloppee(drum, result));
    QCOMPARE(inserted.size(), 1);
    QCOMPARE(model.rowCount(drumRow), 3);
    const QModelIndex row = model.developpeeIndexOf(drum);
    QCOMPARE(row, model.index(2, 0, drumRow)); // after the guides
    QVERIFY(model.isDeveloppee(row));
    QVERIFY(!model.isGuide(row));
    QVERIFY(model.isGuide(model.index(1, 0, drumRow)));
    QCOMPARE(row.data().toString(), QString("Développée (Cylinder, 532 × 79)"));
    QCOMPARE(row.data(SceneTreeModel::DeveloppeeRole).toBool(), true);
    QCOMPARE(row.data(SceneTreeModel::GuideIndexRole).toInt(), -1);
    QCOMPARE(model.fragmentAt(row), drum);
    QCOMPARE(model.parent(row), drumRow);
    QVERIFY(!(model.flags(row) & Qt::ItemIsEditable));
    // Replacing it keeps one row; forgetting it removes the row; not an undo step.
    QVERIFY(doc.setDeveloppee(drum, result));
    QCOMPARE(model.rowCount(drumRow), 3);
    QVERIFY(!doc.undoStack()->canUndo() || doc.undoStack()->count() == 1); // only the addition
    QVERIFY(doc.setDeveloppee(drum, nullptr));
    QCOMPARE(model.rowCount(drumRow), 2);
    QVERIFY(!doc.setDeveloppee(drum + 100, result));
    // Dropped with its fragment.
    QVERIFY(doc.setDeveloppee(drum, result));
    QVERIFY(doc.removeFragment(drum));
    doc.undoStack()->undo();
    QCOMPARE(doc.developpee(drum), nullptr);
    QCOMPARE(model.rowCount(model.indexOf(drum)), 2);
}

void SceneTreeModelTest::assembliesAreRowsHoldingTheirMembersAndTakeDrops()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    SceneTreeModel model(doc);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    const FragmentId drum = doc.addFragment(fragment("drum", 3), m_octree);
    const FragmentId a = doc.addFragment(fragment("a"), m_octree);
    const FragmentId b = doc.addFragment(fragment("b"), m_octree);
    const auto id = doc.newAssembly(QStringLiteral("Drum 1 reconstruction"), {a});

    // Root: the assembly, then the top-level fragments in scene order; the member under the assembly.
    QCOMPARE(model.rowCount(), 3);
    const QModelIndex assemblyRow = model.indexOfAssembly(id);
    QCOMPARE(assemblyRow.row(), 0);
    QCOMPARE(model.data(assemblyRow).toString(), QString("Drum 1 reconstruction"));
    QCOMPARE(model.assemblyAt(assemblyRow), id);
    QCOMPARE(model.fragmentAt(assemblyRow), stylos::core::scene::NoFragment);
    QCOMPARE(model.rowCount(assemblyRow), 1);
    const QModelIndex memberRow = model.index(0, 0, assemblyRow);
    QCOMPARE(model.fragmentAt(memberRow), a);
    QCOMPARE(model.indexOf(a), memberRow);
    QCOMPARE(model.parent(memberRow), assemblyRow);
    QCOMPARE(model.fragmentAt(model.index(1, 0)), drum);
    QCOMPARE(model.fragmentAt(model.index(2, 0)), b);
    QCOMPARE(model.rowCount(model.indexOf(drum)), 3); // its guides, under it as before
    QCOMPARE(model.parent(model.index(0, 0, model.indexOf(drum))), model.indexOf(drum));

    // Renaming and hiding the assembly from the tree go through the undo stack.
    const int steps = doc.undoStack()->count();
    QVERIFY(model.setData(assemblyRow, QStringLiteral("Drum 1"), Qt::EditRole));
    QVERIFY(model.setData(model.indexOfAssembly(id), Qt::Unchecked, Qt::CheckStateRole));
    QCOMPARE(doc.undoStack()->count(), steps + 2);
    QCOMPARE(model.data(model.indexOfAssembly(id), Qt::CheckStateRole).toInt(), int(Qt::Unchecked));

    // Dragging b onto the assembly moves it in (one step); onto the root takes it out.
    QMimeData* data = model.mimeData({model.indexOf(b)});
    QVERIFY(data);
    QVERIFY(model.canDropMimeData(data, Qt::MoveAction, -1, 0, model.indexOfAssembly(id)));
    model.dropMimeData(data, Qt::MoveAction, -1, 0, model.indexOfAssembly(id));
    delete data;
    QCOMPARE(doc.fragment(b)->assembly, id);
    QCOMPARE(model.rowCount(model.indexOfAssembly(id)), 2);
    QCOMPARE(model.rowCount(), 2);
    data = model.mimeData({model.indexOf(b)});
    model.dropMimeData(data, Qt::MoveAction, -1, 0, QModelIndex());
    delete data;
    QCOMPARE(doc.fragment(b)->assembly, stylos::core::scene::NoAssembly);
    QCOMPARE(doc.undoStack()->count(), steps + 4);
    // Guide rows are not dragged.
    QVERIFY(!model.mimeData({model.index(0, 0, model.indexOf(drum))}));

    // Removing a member and undoing it keeps the tree right (rows removed and inserted under the assembly).
    doc.removeFragment(a);
    QCOMPARE(model.rowCount(model.indexOfAssembly(id)), 0);
    doc.undoStack()->undo();
    QCOMPARE(model.rowCount(model.indexOfAssembly(id)), 1);
    QCOMPARE(model.indexOf(a).parent(), model.indexOfAssembly(id));
}

STYLOS_WIDGET_TEST_MAIN(SceneTreeModelTest)
#include "SceneTreeModelTest.moc"
