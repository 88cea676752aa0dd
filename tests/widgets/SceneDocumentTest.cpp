// SceneDocument and its undo commands: every edit and its undo/redo give exact scene states and the
// right signals; the modified flag follows the undo stack's clean state; save then open gives an equal
// scene with its octrees reopened in the background; missing octrees and bad projects are reported.
#include "SceneTestSupport.h"
#include "WidgetTestSupport.h"

#include "stylos/core/octree/PackedOctree.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

#include <numbers>

using stylos::core::scene::Fragment;
using stylos::core::scene::FragmentId;
using stylos::core::scene::Pose;
using stylos::core::scene::Rgb;
using stylos::core::scene::Scene;
using stylos::widgets::SceneDocument;
using stylos::widgets::TaskManager;

class SceneDocumentTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void addAndRemoveUndoRedoExactly();
    void propertyEditsUndoRedoExactly();
    void poseDragStepsMergeIntoOneUndoStep();
    void editsThatChangeNothingPushNothing();
    void modifiedFollowsTheCleanState();
    void saveThenOpenGivesAnEqualScene();
    void aMissingOctreeIsReportedAndTheProjectOpens();
    void anUnreadablePlateIsReportedAndKept();
    void aBadProjectKeepsTheCurrentOne();
    void undoingARemovalDuringLoadingReopensTheOctree();
    void assembliesMoveTheirFragmentsAndUndoExactly();
    void anAssemblySurvivesSaveAndReopen();
    void theDockingDrumSurvivesSaveAndReopen();
    void savingCopiesTheOctreesIntoTheFolderSoItTravels();

private:
    Fragment fragment(const QString& name) const;

    QTemporaryDir m_dir;
    QString m_octreePath;
    SceneDocument::OctreePtr m_octree;
};

void SceneDocumentTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_octreePath = stylos::test::makeOctreeFile(m_dir.path(), "piece.poct");
    auto opened = stylos::core::octree::PackedOctree::open(m_octreePath.toStdString());
    QVERIFY(opened.ok());
    m_octree = std::make_shared<const stylos::core::octree::PackedOctree>(std::move(opened).value());
}

Fragment SceneDocumentTest::fragment(const QString& name) const
{
    Fragment f;
    f.name = name.toStdString();
    f.octreePath = m_octreePath.toStdString();
    return f;
}

void SceneDocumentTest::addAndRemoveUndoRedoExactly()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    QSignalSpy aboutToAdd(&doc, &SceneDocument::fragmentAboutToBeAdded);
    QSignalSpy added(&doc, &SceneDocument::fragmentAdded);
    QSignalSpy aboutToRemove(&doc, &SceneDocument::fragmentAboutToBeRemoved);
    QSignalSpy removed(&doc, &SceneDocument::fragmentRemoved);

    const FragmentId a = doc.addFragment(fragment("a"), m_octree);
    const FragmentId b = doc.addFragment(fragment("b"), m_octree);
    const FragmentId c = doc.addFragment(fragment("c"), m_octree);
    QCOMPARE(a, FragmentId(1));
    QCOMPARE(c, FragmentId(3));
    QCOMPARE(aboutToAdd.size(), 3);
    QCOMPARE(aboutToAdd.at(2).at(0).toInt(), 2);
    QCOMPARE(added.at(1).at(0).toULongLong(), b);
    QCOMPARE(doc.undoStack()->count(), 3);
    QCOMPARE(doc.undoStack()->undoText(), QString("Add c"));
    QVERIFY(!tasks.count()); // octrees given: nothing to open
    const Scene three = doc.scene();

    QVERIFY(doc.removeFragment(b));
    QCOMPARE(aboutToRemove.size(), 1);
    QCOMPARE(removed.at(0).at(0).toULongLong(), b);
    QCOMPARE(doc.scene().size(), 2u);
    QVERIFY(!doc.fragment(b));
    QVERIFY(!doc.octree(b));
    QCOMPARE(doc.undoStack()->undoText(), QString("Remove b"));

    doc.undoStack()->undo(); // b back in the middle, with its octree
    QCOMPARE(doc.scene(), three);
    QCOMPARE(aboutToAdd.last().at(0).toInt(), 1);
    QCOMPARE(doc.octree(b), m_octree);
    doc.undoStack()->redo();
    QCOMPARE(doc.scene().size(), 2u);
    QCOMPARE(doc.scene().indexOf(c), std::optional<std::size_t>(1));

    doc.undoStack()->setIndex(0);
    QVERIFY(doc.scene().empty());
    QCOMPARE(doc.scene().nextId(), FragmentId(4)); // ids are not given back
    QCOMPARE(removed.size(), 2 + 3); // b twice before, then c, b and a
    doc.undoStack()->setIndex(3);
    QCOMPARE(doc.scene(), three);
    QCOMPARE(doc.octree(a), m_octree);
    QCOMPARE(doc.octree(c), m_octree);
    // Ids are never reused, even after undo.
    QCOMPARE(doc.addFragment(fragment("d"), m_octree), FragmentId(4));
}

void SceneDocumentTest::propertyEditsUndoRedoExactly()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    const FragmentId a = doc.addFragment(fragment("drum"), m_octree);
    const Fragment before = *doc.fragment(a);
    QSignalSpy changed(&doc, &SceneDocument::fragmentChanged);

    const Pose pose = Pose::fromTranslationAngles({{1.5, -2.25, 100.125}, {0.1, 0.2, std::numbers::pi / 3}});
    QVERIFY(doc.renameFragment(a, "Drum 1"));
    QVERIFY(doc.setFragmentPose(a, pose));
    QVERIFY(doc.setFragmentColour(a, Rgb{10, 20, 30}));
    QVERIFY(doc.setFragmentVisible(a, false));
    QCOMPARE(changed.size(), 4);
    for (const auto& args : changed) QCOMPARE(args.at(0).toULongLong(), a);
    QCOMPARE(doc.undoStack()->count(), 5);
    QCOMPARE(doc.undoStack()->text(1), QString("Rename drum to Drum 1"));
    QCOMPARE(doc.undoStack()->text(2), QString("Move Drum 1"));
    QCOMPARE(doc.undoStack()->text(3), QString("Change the colour of Drum 1"));
    QCOMPARE(doc.undoStack()->text(4), QString("Hide Drum 1"));

    Fragment after = before;
    after.name = "Drum 1";
    after.pose = pose;
    after.colour = {10, 20, 30};
    after.visible = false;
    QCOMPARE(*doc.fragment(a), after);

    doc.undoStack()->undo();
    QCOMPARE(doc.fragment(a)->visible, true);
    doc.undoStack()->undo();
    QCOMPARE(doc.fragment(a)->colour, before.colour);
    doc.undoStack()->undo();
    QCOMPARE(doc.fragment(a)->pose, Pose());
    doc.undoStack()->undo();
    QCOMPARE(*doc.fragment(a), before);
    QCOMPARE(changed.size(), 8);
    doc.undoStack()->setIndex(5);
    QCOMPARE(*doc.fragment(a), after);
    QCOMPARE(doc.fragment(a)->pose.rowMajor(), pose.rowMajor()); // bit for bit
}

void SceneDocumentTest::poseDragStepsMergeIntoOneUndoStep()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    const FragmentId a = doc.addFragment(fragment("a"), m_octree);
    const FragmentId b = doc.addFragment(fragment("b"), m_octree);
    QCOMPARE(doc.undoStack()->count(), 2);
    QVERIFY(doc.setFragmentPose(a, Pose::translation({0.1, 0, 0})));
    QVERIFY(doc.setFragmentPose(a, Pose::translation({0.2, 0, 0}), true));
    QVERIFY(doc.setFragmentPose(a, Pose::translation({0.3, 0, 0}), true));
    QCOMPARE(doc.undoStack()->count(), 3);
    QCOMPARE(doc.fragment(a)->pose, Pose::translation({0.3, 0, 0}));
    // A new drag (not continuing) and another fragment's drag do not merge.
    QVERIFY(doc.setFragmentPose(a, Pose::translation({0.4, 0, 0})));
    QVERIFY(doc.setFragmentPose(b, Pose::translation({0, 1, 0}), true));
    QCOMPARE(doc.undoStack()->count(), 5);
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(doc.fragment(a)->pose, Pose::translation({0.3, 0, 0}));
    doc.undoStack()->undo();
    QCOMPARE(doc.fragment(a)->pose, Pose());

    // A drag that comes back to where it started leaves no undo step.
    doc.undoStack()->setIndex(2);
    QCOMPARE(doc.undoStack()->count(), 5);
    QVERIFY(doc.setFragmentPose(a, Pose::translation({0, 0, 5}))); // drops the redo steps
    QCOMPARE(doc.undoStack()->count(), 3);
    QVERIFY(doc.setFragmentPose(a, Pose(), true));
    QCOMPARE(doc.undoStack()->count(), 2);
    QCOMPARE(doc.fragment(a)->pose, Pose());
}

void SceneDocumentTest::editsThatChangeNothingPushNothing()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    const FragmentId a = doc.addFragment(fragment("a"), m_octree);
    QVERIFY(!doc.renameFragment(a, "a"));
    QVERIFY(!doc.setFragmentPose(a, Pose()));
    QVERIFY(!doc.setFragmentColour(a, doc.fragment(a)->colour));
    QVERIFY(!doc.setFragmentVisible(a, true));
    QVERIFY(!doc.removeFragment(99));
    QVERIFY(!doc.renameFragment(99, "x"));
    Fragment duplicate = fragment("dup");
    duplicate.id = a;
    QCOMPARE(doc.addFragment(duplicate, m_octree), stylos::core::scene::NoFragment);
    QCOMPARE(doc.undoStack()->count(), 1);
}

void SceneDocumentTest::modifiedFollowsTheCleanState()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    QSignalSpy modified(&doc, &SceneDocument::modifiedChanged);
    QVERIFY(!doc.isModified());
    QCOMPARE(doc.displayName(), QString("Untitled"));
    QString error;
    QVERIFY(!doc.save(&error));
    QVERIFY(!error.isEmpty());

    const FragmentId a = doc.addFragment(fragment("a"), m_octree);
    QVERIFY(doc.isModified());
    QCOMPARE(modified.size(), 1);
    QCOMPARE(modified.at(0).at(0).toBool(), true);

    const QString path = m_dir.filePath("modified.stylos");
    QVERIFY2(doc.saveAs(path, &error), qPrintable(error));
    QVERIFY(!doc.isModified());
    QCOMPARE(modified.last().at(0).toBool(), false);
    QCOMPARE(doc.projectPath(), QFileInfo(path).absoluteFilePath());
    QCOMPARE(doc.displayName(), QString("modified.stylos"));

    doc.renameFragment(a, "b");
    QVERIFY(doc.isModified());
    doc.undoStack()->undo();
    QVERIFY(!doc.isModified()); // back at the saved state
    doc.undoStack()->redo();
    QVERIFY(doc.isModified());
    QVERIFY(doc.save(&error));
    QVERIFY(!doc.isModified());

    doc.newProject();
    QVERIFY(!doc.isModified());
    QVERIFY(doc.scene().empty());
    QVERIFY(doc.projectPath().isEmpty());
    QCOMPARE(doc.undoStack()->count(), 0);
}

void SceneDocumentTest::saveThenOpenGivesAnEqualScene()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    const FragmentId a = doc.addFragment(fragment("drum"), m_octree);
    const FragmentId b = doc.addFragment(fragment("piece"), m_octree);
    doc.setFragmentPose(a, Pose::fromTranslationAngles({{0.1, 0.2, 0.3}, {1.0, -0.5, 2.0}}));
    doc.setFragmentColour(b, Rgb{1, 2, 3});
    doc.setFragmentVisible(b, false);
    const QString path = m_dir.filePath("equal.stylos");
    QString error;
    QVERIFY2(doc.saveAs(path, &error), qPrintable(error));

    SceneDocument reopened(tasks);
    QSignalSpy reset(&reopened, &SceneDocument::sceneReset);
    QSignalSpy loaded(&reopened, &SceneDocument::loadingFinished);
    QSignalSpy octrees(&reopened, &SceneDocument::octreeChanged);
    QVERIFY2(reopened.open(path, &error), qPrintable(error));
    QCOMPARE(reset.size(), 1);
    QCOMPARE(reopened.scene(), doc.scene());
    QVERIFY(reopened.isLoading());
    QVERIFY(!reopened.octree(a)); // opened in the background
    QVERIFY(loaded.wait(10000));
    QCOMPARE(loaded.at(0).at(0).toStringList(), QStringList());
    QCOMPARE(octrees.size(), 2);
    QVERIFY(!reopened.isLoading());
    QVERIFY(reopened.octree(a));
    QCOMPARE(reopened.octree(b)->totalCells(), m_octree->totalCells());
    QCOMPARE(reopened.scene(), doc.scene());
    QVERIFY(!reopened.isModified());
    QCOMPARE(reopened.undoStack()->count(), 0);
    QCOMPARE(reopened.projectPath(), doc.projectPath());
    QVERIFY(tasks.waitForIdle(10000));
}

void SceneDocumentTest::aMissingOctreeIsReportedAndTheProjectOpens()
{
    const QString folder = m_dir.filePath("missing");
    QVERIFY(QDir().mkpath(folder));
    const QString gone = stylos::test::makeOctreeFile(folder, "gone.poct");
    TaskManager tasks;
    SceneDocument doc(tasks);
    Fragment f = fragment("kept");
    doc.addFragment(f, m_octree);
    f.name = "gone";
    f.octreePath = gone.toStdString();
    const FragmentId goneId = doc.addFragment(f, m_octree);
    QString error;
    QVERIFY(doc.saveAs(folder + "/project.stylos", &error));
    QVERIFY(QFile::remove(gone));

    SceneDocument reopened(tasks);
    QSignalSpy loaded(&reopened, &SceneDocument::loadingFinished);
    QVERIFY2(reopened.open(folder + "/project.stylos", &error), qPrintable(error));
    QCOMPARE(reopened.scene().size(), 2u);
    QVERIFY(reopened.fragment(goneId)->octreeMissing);
    QVERIFY(loaded.wait(10000));
    const QStringList errors = loaded.at(0).at(0).toStringList();
    QCOMPARE(errors.size(), 1);
    QVERIFY2(errors[0].startsWith("Could not load gone.poct: the file does not exist."), qPrintable(errors[0]));
    QVERIFY(errors[0].contains(gone));
    QVERIFY(reopened.octree(1));
    QVERIFY(!reopened.octree(goneId));
    QVERIFY(tasks.waitForIdle(10000));
}

void SceneDocumentTest::anUnreadablePlateIsReportedAndKept()
{
    const QString folder = m_dir.filePath("plate");
    QVERIFY(QDir().mkpath(folder));
    TaskManager tasks;
    SceneDocument doc(tasks);
    doc.addFragment(fragment("drum"), m_octree);
    QString error;
    const QString path = folder + "/project.stylos";
    QVERIFY2(doc.saveAs(path, &error), qPrintable(error));
    // A hand-edited plate section with a misspelt key.
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QByteArray text = file.readAll();
    file.close();
    const QByteArray plate = "\"mystery\": 1,\n  \"plate\": {\"pagee\": \"A4\", \"panels\": []},\n  \"fragments\"";
    QVERIFY(text.contains("\"fragments\""));
    text.replace("\"fragments\"", plate);
    stylos::test::writeFile(folder, "project.stylos", text);

    SceneDocument reopened(tasks);
    QSignalSpy loaded(&reopened, &SceneDocument::loadingFinished);
    QVERIFY2(reopened.open(path, &error), qPrintable(error));
    QCOMPARE(reopened.scene().size(), 1u);
    QVERIFY(!reopened.scene().plate());
    QVERIFY(loaded.wait(10000));
    const QStringList errors = loaded.at(0).at(0).toStringList();
    QCOMPARE(errors.size(), 2);
    QVERIFY2(errors[0].startsWith("The plate layout kept in project.stylos could not be read"), qPrintable(errors[0]));
    QVERIFY2(errors[0].contains("plate: pagee"), qPrintable(errors[0]));
    // A key this version does not read is named: it is not saved (a later version's data would go without a word).
    QCOMPARE(errors[1], QStringLiteral("project.stylos holds keys this version of Stylos does not read; they are left "
                                       "out and will not be saved: mystery"));
    QVERIFY(reopened.octree(1));

    // Saving does not lose the section the user may want to mend.
    QVERIFY2(reopened.saveAs(path, &error), qPrintable(error));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.readAll().contains("\"pagee\": \"A4\""));
    QVERIFY(tasks.waitForIdle(10000));
}

void SceneDocumentTest::aBadProjectKeepsTheCurrentOne()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    doc.addFragment(fragment("a"), m_octree);
    const Scene before = doc.scene();
    const QString bad = stylos::test::writeFile(m_dir.path(), "bad.stylos", "{\"format\": \"stylos-project\", \"version\": 7}");
    QString error;
    QVERIFY(!doc.open(bad, &error));
    QVERIFY2(error.startsWith("Could not load bad.stylos: this format is not supported."), qPrintable(error));
    QVERIFY(error.contains("version 7"));
    QCOMPARE(doc.scene(), before);
    QVERIFY(!doc.open(m_dir.filePath("none.stylos"), &error));
    QVERIFY2(error.startsWith("Could not load none.stylos: the file does not exist."), qPrintable(error));
    QCOMPARE(doc.undoStack()->count(), 1);
}

void SceneDocumentTest::undoingARemovalDuringLoadingReopensTheOctree()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    const FragmentId a = doc.addFragment(fragment("a"), m_octree);
    QString error;
    QVERIFY(doc.saveAs(m_dir.filePath("reload.stylos"), &error));

    SceneDocument reopened(tasks);
    QSignalSpy loaded(&reopened, &SceneDocument::loadingFinished);
    QVERIFY(reopened.open(m_dir.filePath("reload.stylos"), &error));
    QVERIFY(reopened.isLoading());
    QVERIFY(reopened.removeFragment(a)); // before its octree arrived
    QVERIFY(!reopened.isLoading());
    reopened.undoStack()->undo();
    QVERIFY(reopened.isLoading()); // opened again for the restored fragment
    QVERIFY(tasks.waitForIdle(10000));
    QVERIFY(reopened.octree(a));
    QVERIFY(!reopened.fragment(a)->octreeMissing);
    QVERIFY(!loaded.isEmpty());
}

void SceneDocumentTest::assembliesMoveTheirFragmentsAndUndoExactly()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    const FragmentId drum = doc.addFragment(fragment("drum"), m_octree);
    const FragmentId a = doc.addFragment(fragment("piece a"), m_octree);
    const FragmentId b = doc.addFragment(fragment("piece b"), m_octree);
    doc.setFragmentPose(a, Pose::fromTranslationAngles({{1.0, 0.0, 0.0}, {0.0, 0.0, 0.25}}));
    doc.setFragmentPose(b, Pose::fromTranslationAngles({{2.0, 0.5, 0.0}, {0.0, 0.0, -0.5}}));
    const Scene before = doc.scene();
    const Pose worldA = doc.worldPose(a), worldB = doc.worldPose(b);
    const int steps = doc.undoStack()->count();

    QSignalSpy structure(&doc, &SceneDocument::structureChanged);
    const auto id = doc.newAssembly(QStringLiteral("Drum 1 reconstruction"), {a, b});
    QCOMPARE(id, stylos::core::scene::AssemblyId(1));
    QCOMPARE(doc.undoStack()->count(), steps + 1); // one step
    QCOMPARE(structure.size(), 1);
    QCOMPARE(doc.scene().membersOf(id), (std::vector<FragmentId>{a, b}));
    QVERIFY(doc.worldPose(a).approxEqual(worldA, 1e-12)); // moved in, in place
    QVERIFY(doc.worldPose(b).approxEqual(worldB, 1e-12));
    QVERIFY(doc.assembly(id)->pose.approxEqual(worldA, 0.0)); // its frame at the first member's

    // Moving the assembly moves both members by the same motion; the drum stays.
    const Pose shift = Pose::translation({0.0, 0.0, 3.0});
    QVERIFY(doc.setAssemblyPose(id, shift * doc.assembly(id)->pose));
    QVERIFY(doc.worldPose(a).approxEqual(shift * worldA, 1e-12));
    QVERIFY(doc.worldPose(b).approxEqual(shift * worldB, 1e-12));
    QCOMPARE(doc.worldPose(drum), Pose());
    // A world pose set on a member is stored relative to the assembly.
    QVERIFY(doc.setFragmentWorldPose(a, worldA));
    QVERIFY(doc.worldPose(a).approxEqual(worldA, 1e-12));
    QVERIFY(doc.setAssemblyDrum(id, drum));
    QCOMPARE(doc.drumFor(a), drum);
    QCOMPARE(doc.drumFor(drum), stylos::core::scene::NoFragment);
    // Hidden with its assembly; renamed; one member taken out, in place.
    QVERIFY(doc.setAssemblyVisible(id, false));
    QVERIFY(!doc.isShown(a));
    QVERIFY(doc.isShown(drum));
    QVERIFY(doc.renameAssembly(id, QStringLiteral("Drum 1")));
    QCOMPARE(doc.assembly(id)->name, std::string("Drum 1"));
    const Pose placedB = doc.worldPose(b);
    QVERIFY(doc.moveToAssembly({b}, stylos::core::scene::NoAssembly));
    QVERIFY(doc.worldPose(b).approxEqual(placedB, 1e-12));
    QCOMPARE(doc.scene().membersOf(id), (std::vector<FragmentId>{a}));
    QVERIFY(doc.removeAssembly(id));
    QVERIFY(doc.scene().assemblies().empty());
    QCOMPARE(doc.fragment(a)->assembly, stylos::core::scene::NoAssembly);

    // Undo everything: the scene before, exactly; redo everything: the same end again.
    const Scene after = doc.scene();
    while (doc.undoStack()->index() > steps) doc.undoStack()->undo();
    QCOMPARE(doc.scene(), before);
    while (doc.undoStack()->canRedo()) doc.undoStack()->redo();
    QCOMPARE(doc.scene(), after);

    // Edits that change nothing or name nothing push nothing.
    const int now = doc.undoStack()->count();
    QVERIFY(!doc.removeAssembly(42));
    QVERIFY(!doc.moveToAssembly({a}, 42));
    QCOMPARE(doc.newAssembly(QStringLiteral("  "), {a}), stylos::core::scene::NoAssembly);
    QCOMPARE(doc.undoStack()->count(), now);
}

void SceneDocumentTest::anAssemblySurvivesSaveAndReopen()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    const FragmentId drum = doc.addFragment(fragment("drum"), m_octree);
    const FragmentId a = doc.addFragment(fragment("piece"), m_octree);
    doc.setFragmentPose(a, Pose::fromTranslationAngles({{0.3, 0.1, 0.2}, {0.1, 0.2, 0.3}}));
    const auto id = doc.newAssembly(QStringLiteral("Δελφοί"), {a});
    doc.setAssemblyDrum(id, drum);
    doc.setAssemblyPose(id, Pose::fromTranslationAngles({{5.0, 0.0, 0.0}, {0.0, 0.0, 1.0}}));
    const QString path = m_dir.filePath("assembly.stylos");
    QString error;
    QVERIFY2(doc.saveAs(path, &error), qPrintable(error));
    SceneDocument reopened(tasks);
    QVERIFY2(reopened.open(path, &error), qPrintable(error));
    QCOMPARE(reopened.scene(), doc.scene());
    QCOMPARE(reopened.worldPose(a), doc.worldPose(a));
    QCOMPARE(reopened.drumFor(a), drum);
}

void SceneDocumentTest::theDockingDrumSurvivesSaveAndReopen()
{
    // Docked against a drum without an assembly: the drum whose axis the fragment unrolls about was not saved, so the
    // reopened project unrolled the fragment about an axis of its own (other radius, turned upside down).
    TaskManager tasks;
    SceneDocument doc(tasks);
    const FragmentId drum = doc.addFragment(fragment("drum"), m_octree);
    const FragmentId piece = doc.addFragment(fragment("piece"), m_octree);
    const QString path = m_dir.filePath("docking-drum.stylos");
    QString error;
    QVERIFY2(doc.saveAs(path, &error), qPrintable(error));
    QVERIFY(!doc.isModified());
    QSignalSpy modified(&doc, &SceneDocument::modifiedChanged);
    QVERIFY(doc.setDockingDrum(drum));
    QVERIFY(doc.isModified()); // the file no longer holds it: saving is asked for
    QCOMPARE(modified.size(), 1);
    QCOMPARE(modified.at(0).at(0).toBool(), true);
    QVERIFY2(doc.save(&error), qPrintable(error));
    QVERIFY(!doc.isModified());

    SceneDocument reopened(tasks);
    QSignalSpy drumChanged(&reopened, &SceneDocument::dockingDrumChanged);
    QVERIFY2(reopened.open(path, &error), qPrintable(error));
    QCOMPARE(reopened.dockingDrum(), drum);
    QCOMPARE(reopened.drumFor(piece), drum);
    QVERIFY(!drumChanged.isEmpty());
    QCOMPARE(drumChanged.last().at(0).toULongLong(), quint64(drum));
    QVERIFY(!reopened.isModified());

    // Removing the drum unsets it, and undoing the removal does not bring the setting back: still modified.
    QVERIFY(reopened.removeFragment(drum));
    QCOMPARE(reopened.dockingDrum(), stylos::core::scene::NoFragment);
    reopened.undoStack()->undo();
    QVERIFY(reopened.fragment(drum));
    QCOMPARE(reopened.dockingDrum(), stylos::core::scene::NoFragment);
    QVERIFY(reopened.isModified());
    // Removed with another fragment in one step (a macro): the project is said modified at its end.
    QVERIFY2(reopened.save(&error), qPrintable(error));
    QVERIFY(reopened.setDockingDrum(drum));
    QVERIFY2(reopened.save(&error), qPrintable(error));
    QVERIFY(!reopened.isModified());
    QSignalSpy told(&reopened, &SceneDocument::modifiedChanged);
    reopened.beginMacro([] { return QStringLiteral("Remove 2 fragments"); });
    QVERIFY(reopened.removeFragment(drum));
    QVERIFY(reopened.removeFragment(piece));
    reopened.endMacro();
    QVERIFY(reopened.isModified());
    QVERIFY(!told.isEmpty());
    QCOMPARE(told.last().at(0).toBool(), true);
    // A new project has none.
    QVERIFY(doc.setDockingDrum(drum));
    doc.newProject();
    QCOMPARE(doc.dockingDrum(), stylos::core::scene::NoFragment);
}


void SceneDocumentTest::savingCopiesTheOctreesIntoTheFolderSoItTravels()
{
    const QString cache = m_dir.filePath("travel-cache");
    const QString elsewhere = m_dir.filePath("travel-elsewhere");
    const QString site = m_dir.filePath("travel-site");
    for (const QString& folder : {cache, elsewhere, site}) QVERIFY(QDir().mkpath(folder));
    const QString imported = stylos::test::makeOctreeFile(cache, "import.poct");
    const QString built = stylos::test::makeOctreeFile(elsewhere, "built.poct");
    TaskManager tasks;
    SceneDocument doc(tasks);
    doc.setOctreeCacheFolder(cache);
    Fragment f = fragment("import");
    f.octreePath = imported.toStdString();
    const FragmentId a = doc.addFragment(f, m_octree);
    f.name = "built";
    f.octreePath = built.toStdString();
    const FragmentId b = doc.addFragment(f, m_octree);

    // Left where they are: only the cache's octree comes.
    QString error;
    QVERIFY2(doc.saveAs(site + "/first.stylos", &error, SceneDocument::OctreeCopies::CacheOnly), qPrintable(error));
    const QString canonicalSite = QFileInfo(site).canonicalFilePath();
    QCOMPARE(QString::fromStdString(doc.fragment(a)->octreePath.string()), canonicalSite + "/import.poct");
    QCOMPARE(QString::fromStdString(doc.fragment(b)->octreePath.string()), built);
    QVERIFY(QFile::exists(imported)); // the cache's copy waits for the cache cleaner

    // All: the other one comes too, and the folder travels whole.
    QSignalSpy changed(&doc, &SceneDocument::fragmentChanged);
    QVERIFY2(doc.saveAs(site + "/column.stylos", &error), qPrintable(error));
    QCOMPARE(changed.size(), 1);
    QCOMPARE(changed.at(0).at(0).toULongLong(), b);
    QCOMPARE(QString::fromStdString(doc.fragment(b)->octreePath.string()), canonicalSite + "/built.poct");
    QVERIFY(!doc.isModified());

    const QString usb = m_dir.filePath("travel-usb");
    QVERIFY(QDir().mkpath(usb));
    for (const QString& name : QDir(site).entryList(QDir::Files)) QVERIFY(QFile::copy(site + "/" + name, usb + "/" + name));
    QVERIFY(QDir(site).removeRecursively());
    QVERIFY(QDir(elsewhere).removeRecursively());
    QVERIFY(QDir(cache).removeRecursively());
    SceneDocument reopened(tasks);
    QSignalSpy loaded(&reopened, &SceneDocument::loadingFinished);
    QVERIFY2(reopened.open(usb + "/column.stylos", &error), qPrintable(error));
    QVERIFY(loaded.wait(10000));
    QCOMPARE(loaded.at(0).at(0).toStringList(), QStringList());
    QVERIFY(reopened.octree(a));
    QVERIFY(reopened.octree(b));
    QCOMPARE(reopened.octree(b)->totalCells(), m_octree->totalCells());
    QVERIFY(tasks.waitForIdle(10000));
}

STYLOS_WIDGET_TEST_MAIN(SceneDocumentTest)
#include "SceneDocumentTest.moc"
