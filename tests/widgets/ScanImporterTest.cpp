// ScanImporter: scans become packed octrees in background tasks and fragments through the undo stack;
// a broken file gives one message naming it; a cancelled import adds nothing and leaves no file; the
// file dialog's filter and what a drop accepts come from core::io's one list of extensions.
#include "SceneTestSupport.h"
#include "WidgetTestSupport.h"

#include "ProjectActions.h"

#include "stylos/core/octree/PackedOctree.h"
#include "stylos/widgets/document/ScanImporter.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/document/SceneTreeModel.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QFile>
#include <atomic>
#include <memory>
#include <QThread>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

using stylos::core::synth::SyntheticKind;
using stylos::widgets::ScanImporter;
using stylos::widgets::SceneDocument;
using stylos::widgets::SceneTreeModel;
using stylos::widgets::TaskManager;

class ScanImporterTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void importsTwoScansAtOnce();
    void importsIntoTheProjectFolderOnceSaved();
    void anUndoneImportLeavesNoOctreeOnceTheProjectCloses();
    void opensAPoctDirectly();
    void aSaveDuringAnImportCopiesNoOctreeOntoItsName();
    void twoWorkbenchesImportingOneNameTakeTwoFiles();
    void aBrokenFileIsNamedAndNothingIsAdded();
    void skippedPointsAreSaid();
    void mergedScansAreSaid();
    void cancelLeavesNothing();
    void dialogsAndDropsUseTheCoreListOfExtensions();

private:
    /** A fresh folder for one test's outputs. */
    QString freshFolder(const QString& name) const;

    QTemporaryDir m_dir;
    QString m_scans;
    QString m_fragmentScan;  ///< a fragment, ~5 k points, with normals
    QString m_drumScan;      ///< a drum at 2 cm, ~10 k points, without normals (estimated on import)
    stylos::core::octree::BuildOptions m_options;
};

void ScanImporterTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_scans = freshFolder("scans");
    m_fragmentScan = stylos::test::generateScanFile(m_scans, "fragment.ply", SyntheticKind::Fragment, 0.01, true);
    m_drumScan = stylos::test::generateScanFile(m_scans, "drum.ply", SyntheticKind::Drum, 0.02, false);
    m_options.depth = 6;
    m_options.threads = 1;
}

QString ScanImporterTest::freshFolder(const QString& name) const
{
    const QString path = m_dir.filePath(name);
    if (!QDir().mkpath(path)) qFatal("cannot create %s", qPrintable(path));
    return path;
}

void ScanImporterTest::importsTwoScansAtOnce()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    SceneTreeModel tree(doc);
    ScanImporter importer(doc, tasks);
    importer.setBuildOptions(m_options);
    const QString cache = freshFolder("cache-two");
    importer.setCacheDirectory(cache);
    QCOMPARE(importer.outputDirectory(), cache);
    QSignalSpy imported(&importer, &ScanImporter::fragmentImported);
    QSignalSpy finished(&importer, &ScanImporter::importsFinished);

    QCOMPARE(importer.importFiles({m_fragmentScan, m_drumScan}), 2);
    QCOMPARE(tasks.count(), 2);
    QCOMPARE(importer.pending(), 2);
    QVERIFY(doc.scene().empty()); // nothing until the octrees are built
    QVERIFY(tasks.waitForIdle(30000));

    QCOMPARE(imported.size(), 2);
    QCOMPARE(finished.size(), 1);
    QCOMPARE(finished.at(0).at(0).toStringList(), QStringList());
    QCOMPARE(tree.rowCount(), 2);
    QStringList names{tree.data(tree.index(0, 0)).toString(), tree.data(tree.index(1, 0)).toString()};
    names.sort();
    QCOMPARE(names, (QStringList{"drum", "fragment"}));
    QCOMPARE(stylos::test::filesUnder(cache), (QStringList{"drum.poct", "fragment.poct"}));
    for (const auto& f : doc.scene().fragments()) {
        QCOMPARE(QString::fromStdString(f.octreePath.string()), cache + "/" + QString::fromStdString(f.name) + ".poct");
        QCOMPARE(QString::fromStdString(f.sourcePath.string()), m_scans + "/" + QString::fromStdString(f.name) + ".ply");
        QVERIFY(doc.octree(f.id));
        QCOMPARE(doc.octree(f.id)->depth(), 6);
    }
    QCOMPARE(doc.undoStack()->count(), 2);
    QVERIFY(doc.undoStack()->text(0).startsWith("Import "));
    // Undo removes the fragment, not its octree file; redo brings it back.
    doc.undoStack()->undo();
    QCOMPARE(tree.rowCount(), 1);
    doc.undoStack()->redo();
    QCOMPARE(tree.rowCount(), 2);

    // The same scan again gets its own file.
    QCOMPARE(importer.importFiles({m_fragmentScan}), 1);
    QVERIFY(tasks.waitForIdle(30000));
    QCOMPARE(stylos::test::filesUnder(cache), (QStringList{"drum.poct", "fragment-2.poct", "fragment.poct"}));
}

void ScanImporterTest::importsIntoTheProjectFolderOnceSaved()
{
    TaskManager tasks;
    SceneDocument doc(tasks);
    ScanImporter importer(doc, tasks);
    importer.setBuildOptions(m_options);
    importer.setCacheDirectory(freshFolder("cache-unused"));
    const QString project = freshFolder("project");
    QString error;
    QVERIFY(doc.saveAs(project + "/site.stylos", &error));
    QCOMPARE(importer.outputDirectory(), project);
    QCOMPARE(importer.importFiles({m_fragmentScan}), 1);
    QVERIFY(tasks.waitForIdle(30000));
    QCOMPARE(doc.scene().size(), 1u);
    QCOMPARE(QString::fromStdString(doc.scene().fragments()[0].octreePath.string()), project + "/fragment.poct");
    QVERIFY(doc.isModified());
    QVERIFY(doc.save(&error));
    QCOMPARE(stylos::test::filesUnder(project), (QStringList{"fragment.poct", "site.stylos"}));
    QCOMPARE(stylos::test::filesUnder(importer.cacheDirectory()), QStringList());
}

void ScanImporterTest::anUndoneImportLeavesNoOctreeOnceTheProjectCloses()
{
    TaskManager tasks;
    const QString project = freshFolder("undone");
    const QString kept = freshFolder("undone-kept");
    QString error;
    {
        SceneDocument doc(tasks);
        ScanImporter importer(doc, tasks);
        importer.setBuildOptions(m_options);
        importer.setCacheDirectory(freshFolder("cache-undone"));
        QVERIFY(doc.saveAs(project + "/site.stylos", &error));
        // Imported, undone: the file stays while the import can be redone...
        QCOMPARE(importer.importFiles({m_fragmentScan}), 1);
        QVERIFY(tasks.waitForIdle(30000));
        QCOMPARE(doc.scene().size(), 1u);
        doc.undoStack()->undo();
        QCOMPARE(doc.scene().size(), 0u);
        QCOMPARE(stylos::test::filesUnder(project), (QStringList{"fragment.poct", "site.stylos"}));
        doc.undoStack()->redo();
        QVERIFY(doc.octree(doc.scene().fragments()[0].id));
        doc.undoStack()->undo();
        // ... and goes when the project closes (a new one here).
        doc.newProject();
        QCOMPARE(stylos::test::filesUnder(project), QStringList{"site.stylos"});

        // Imported and saved: a project file references it, it stays; so does a file the project only opened.
        QVERIFY(doc.saveAs(kept + "/site.stylos", &error));
        QCOMPARE(importer.importFiles({m_fragmentScan, m_drumScan}), 2);
        QVERIFY(tasks.waitForIdle(60000));
        QCOMPARE(doc.scene().size(), 2u);
        QVERIFY(doc.save(&error));
        doc.newProject();
        QCOMPARE(stylos::test::filesUnder(kept), (QStringList{"drum.poct", "fragment.poct", "site.stylos"}));
        QVERIFY(doc.open(kept + "/site.stylos", &error));
        QVERIFY(tasks.waitForIdle(30000));
        doc.newProject();
        QCOMPARE(stylos::test::filesUnder(kept), (QStringList{"drum.poct", "fragment.poct", "site.stylos"}));

        // Saved, then the import undone and saved again: no project file references it any more.
        QVERIFY(doc.open(kept + "/site.stylos", &error));
        QVERIFY(tasks.waitForIdle(30000));
        QCOMPARE(importer.importFiles({m_fragmentScan}), 1);
        QVERIFY(tasks.waitForIdle(30000));
        QVERIFY(doc.save(&error));
        QCOMPARE(stylos::test::filesUnder(kept),
                 (QStringList{"drum.poct", "fragment-2.poct", "fragment.poct", "site.stylos"}));
        doc.undoStack()->undo();
        QVERIFY(doc.save(&error));
        // A new import drops the undone one's redo step: fragment-2 goes at once (no project file names it now).
        // Imported into the unsaved changes and undone: gone when the document goes, as at a close.
        QCOMPARE(importer.importFiles({m_drumScan}), 1);
        QVERIFY(tasks.waitForIdle(30000));
        QCOMPARE(stylos::test::filesUnder(kept), (QStringList{"drum-2.poct", "drum.poct", "fragment.poct", "site.stylos"}));
        doc.undoStack()->undo();
        QCOMPARE(stylos::test::filesUnder(kept), (QStringList{"drum-2.poct", "drum.poct", "fragment.poct", "site.stylos"}));
    }
    QCOMPARE(stylos::test::filesUnder(kept), (QStringList{"drum.poct", "fragment.poct", "site.stylos"}));

    // Imported, saved, then removed with Delete and saved again: the user removed the fragment, not its file (its
    // labels may be in it); it stays. An import undone whose step a new edit discards goes at once.
    const QString removed = freshFolder("removed");
    {
        SceneDocument doc(tasks);
        ScanImporter importer(doc, tasks);
        importer.setBuildOptions(m_options);
        QVERIFY(doc.saveAs(removed + "/site.stylos", &error));
        QCOMPARE(importer.importFiles({m_fragmentScan}), 1);
        QVERIFY(tasks.waitForIdle(30000));
        QVERIFY(doc.save(&error));
        QVERIFY(doc.removeFragment(doc.scene().fragments()[0].id));
        QVERIFY(doc.save(&error));
        QCOMPARE(importer.importFiles({m_drumScan}), 1);
        QVERIFY(tasks.waitForIdle(30000));
        doc.undoStack()->undo();
        QCOMPARE(stylos::test::filesUnder(removed), (QStringList{"drum.poct", "fragment.poct", "site.stylos"}));
        doc.undoStack()->undo(); // the removal undone: the fragment is back
        QCOMPARE(doc.scene().size(), 1u);
        // A new edit drops the redo branch, the drum's import with it: its octree goes at once.
        QVERIFY(doc.renameFragment(doc.scene().fragments()[0].id, QStringLiteral("piece")));
        QCOMPARE(stylos::test::filesUnder(removed), (QStringList{"fragment.poct", "site.stylos"}));
        QVERIFY(doc.removeFragment(doc.scene().fragments()[0].id));
        QVERIFY(doc.save(&error));
        doc.newProject();
    }
    QCOMPARE(stylos::test::filesUnder(removed), (QStringList{"fragment.poct", "site.stylos"}));
}

void ScanImporterTest::aSaveDuringAnImportCopiesNoOctreeOntoItsName()
{
    // An octree elsewhere named fragment.poct is in the scene; a scan named fragment.ply is being imported into the
    // project's folder (as fragment.poct) when the project is saved: the save's copy takes fragment-2.poct, so the
    // finished import does not replace it (the project named the wrong scan).
    const QString elsewhere = freshFolder("race-elsewhere");
    const QString poct = stylos::test::makeOctreeFile(elsewhere, "fragment.poct");
    const QString project = freshFolder("race");
    TaskManager tasks;
    SceneDocument doc(tasks);
    ScanImporter importer(doc, tasks);
    importer.setBuildOptions(m_options);
    importer.setCacheDirectory(freshFolder("cache-race"));
    QString error;
    QVERIFY(doc.saveAs(project + "/site.stylos", &error));
    QCOMPARE(importer.importFiles({poct}), 1);
    QVERIFY(tasks.waitForIdle(30000));
    QCoreApplication::processEvents();
    QCOMPARE(doc.scene().size(), 1u);
    const auto direct = doc.scene().fragments()[0].id;
    QCOMPARE(importer.importFiles({m_fragmentScan}), 1); // building fragment.poct in the project's folder
    QVERIFY(doc.save(&error)); // before the import ends (its end is delivered by the event loop)
    QCOMPARE(QString::fromStdString(doc.fragment(direct)->octreePath.string()), project + "/fragment-2.poct");
    QVERIFY(tasks.waitForIdle(30000));
    QCoreApplication::processEvents();
    QCOMPARE(doc.scene().size(), 2u);
    QCOMPARE(QString::fromStdString(doc.scene().fragments()[1].octreePath.string()), project + "/fragment.poct");
    QCOMPARE(stylos::test::filesUnder(project), (QStringList{"fragment-2.poct", "fragment.poct", "site.stylos"}));
    const auto bytes = [](const QString& path) {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    };
    QVERIFY(!bytes(poct).isEmpty());
    QCOMPARE(bytes(project + "/fragment-2.poct"), bytes(poct));
}

void ScanImporterTest::twoWorkbenchesImportingOneNameTakeTwoFiles()
{
    // Two Stylos windows (two documents, nothing shared but the cache folder) import a scan named fragment.ply
    // each: the first's import waits behind another task, so nothing of its octree is written yet when the second
    // starts. The name is taken on disk at once (an empty file), so the second builds fragment-2.poct; before, both
    // built fragment.poct and the second's rename replaced the first's octree under its project.
    const QString cache = freshFolder("cache-two-windows");
    const QString otherScans = freshFolder("other-scans");
    const QString other =
        stylos::test::generateScanFile(otherScans, "fragment.ply", SyntheticKind::Drum, 0.02, false); // not the same scan
    std::atomic<bool> release{false}; // outlives the task managers, which wait for their tasks
    TaskManager firstTasks, secondTasks;
    firstTasks.setMaxConcurrent(1);
    const std::shared_ptr<void> releaseOnExit(nullptr, [&release](void*) { release = true; }); // a failed check too
    firstTasks.start<int>(QStringLiteral("busy"), [&release](QPromise<int>& promise, stylos::core::ProgressSink&) {
        while (!release.load()) QThread::msleep(5);
        promise.addResult(0);
    });
    SceneDocument firstDoc(firstTasks), secondDoc(secondTasks);
    ScanImporter first(firstDoc, firstTasks), second(secondDoc, secondTasks);
    for (ScanImporter* importer : {&first, &second}) {
        importer->setBuildOptions(m_options);
        importer->setCacheDirectory(cache);
    }
    QCOMPARE(first.importFiles({m_fragmentScan}), 1);
    QCOMPARE(stylos::test::filesUnder(cache), QStringList{"fragment.poct"}); // the name, taken before the build
    QCOMPARE(QFileInfo(cache + "/fragment.poct").size(), 0);
    QCOMPARE(second.importFiles({other}), 1);
    QVERIFY(secondTasks.waitForIdle(30000));
    release = true;
    QVERIFY(firstTasks.waitForIdle(30000));
    QCoreApplication::processEvents();
    QCOMPARE(firstDoc.scene().size(), 1u);
    QCOMPARE(secondDoc.scene().size(), 1u);
    const auto& a = firstDoc.scene().fragments()[0];
    const auto& b = secondDoc.scene().fragments()[0];
    QCOMPARE(QString::fromStdString(a.octreePath.string()), cache + "/fragment.poct");
    QCOMPARE(QString::fromStdString(b.octreePath.string()), cache + "/fragment-2.poct");
    QCOMPARE(stylos::test::filesUnder(cache), (QStringList{"fragment-2.poct", "fragment.poct"}));
    // Each file holds its own scan (the two octrees' cell counts differ), the one its document opened.
    const auto opened = [](const std::filesystem::path& path) { return stylos::core::octree::PackedOctree::open(path); };
    auto fragmentOctree = opened(a.octreePath), drumOctree = opened(b.octreePath);
    QVERIFY(fragmentOctree.ok() && drumOctree.ok());
    QCOMPARE(fragmentOctree->totalCells(), firstDoc.octree(a.id)->totalCells());
    QCOMPARE(drumOctree->totalCells(), secondDoc.octree(b.id)->totalCells());
    QVERIFY(fragmentOctree->totalCells() != drumOctree->totalCells());
}

void ScanImporterTest::opensAPoctDirectly()
{
    const QString folder = freshFolder("direct");
    const QString poct = stylos::test::makeOctreeFile(folder, "piece.poct");
    const QStringList before = stylos::test::filesUnder(folder);
    TaskManager tasks;
    SceneDocument doc(tasks);
    ScanImporter importer(doc, tasks);
    importer.setCacheDirectory(freshFolder("cache-direct"));
    QCOMPARE(importer.importFiles({poct}), 1);
    QVERIFY(tasks.waitForIdle(30000));
    QCOMPARE(doc.scene().size(), 1u);
    const auto& f = doc.scene().fragments()[0];
    QCOMPARE(f.name, std::string("piece"));
    QCOMPARE(QString::fromStdString(f.octreePath.string()), poct);
    QVERIFY(f.sourcePath.empty());
    QVERIFY(doc.octree(f.id));
    QCOMPARE(stylos::test::filesUnder(folder), before);
    QCOMPARE(stylos::test::filesUnder(importer.cacheDirectory()), QStringList());
}

void ScanImporterTest::aBrokenFileIsNamedAndNothingIsAdded()
{
    const QString folder = freshFolder("broken");
    const QString broken = stylos::test::writeFile(folder, "broken.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nend_header\n0 0\n1\n");
    const QString notOctree = stylos::test::writeFile(folder, "fake.poct", "not an octree at all");
    TaskManager tasks;
    SceneDocument doc(tasks);
    ScanImporter importer(doc, tasks);
    importer.setBuildOptions(m_options);
    const QString cache = freshFolder("cache-broken");
    importer.setCacheDirectory(cache);
    QSignalSpy failed(&importer, &ScanImporter::importFailed);
    QSignalSpy finished(&importer, &ScanImporter::importsFinished);

    const QString laz = stylos::test::writeFile(folder, "site.laz", "LASF compressed");
    QCOMPARE(importer.importFiles({broken, notOctree, folder + "/absent.ply", laz}), 4);
    QVERIFY(tasks.waitForIdle(30000));
    QCOMPARE(failed.size(), 4);
    QCOMPARE(finished.size(), 1);
    const QStringList errors = finished.at(0).at(0).toStringList();
    QCOMPARE(errors.size(), 4);
    QString brokenMessage, fakeMessage, absentMessage, lazMessage;
    for (const auto& args : failed) {
        const QString path = args.at(0).toString();
        const QString message = args.at(1).toString();
        QVERIFY(errors.contains(message));
        if (path == broken) brokenMessage = message;
        if (path == notOctree) fakeMessage = message;
        if (path.endsWith("absent.ply")) absentMessage = message;
        if (path == laz) lazMessage = message;
    }
    // A LAZ among other scans is not dropped without a word: it says what to do.
    QVERIFY2(lazMessage.startsWith("Could not import site.laz: ") && lazMessage.contains("decompress it first"),
             qPrintable(lazMessage));
    QVERIFY2(brokenMessage.startsWith("Could not import broken.ply: "), qPrintable(brokenMessage));
    QVERIFY(brokenMessage.contains(broken)); // the core's detail names the full path
    QVERIFY2(fakeMessage.startsWith("Could not import fake.poct: the file format is not recognised."), qPrintable(fakeMessage));
    QVERIFY2(absentMessage.startsWith("Could not import absent.ply: the file does not exist."), qPrintable(absentMessage));
    QVERIFY(doc.scene().empty());
    QCOMPARE(doc.undoStack()->count(), 0);
    QCOMPARE(stylos::test::filesUnder(cache), QStringList());
}

void ScanImporterTest::skippedPointsAreSaid()
{
    // A scan with non-finite coordinates imports its other points and says how many it skipped, as stylos-cli does
    // (the workbench said only "Imported").
    const QString folder = freshFolder("nan");
    QByteArray text;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) text += QByteArray::number(i * 0.01) + ' ' + QByteArray::number(j * 0.01) + " 0\n";
    text += "nan 0 0\n0 inf 0\n0 0 -inf\n";
    const QString scan = stylos::test::writeFile(folder, "grid.xyz", text);
    TaskManager tasks;
    SceneDocument doc(tasks);
    ScanImporter importer(doc, tasks);
    importer.setBuildOptions(m_options);
    importer.setCacheDirectory(freshFolder("cache-nan"));
    QSignalSpy imported(&importer, &ScanImporter::fragmentImported);
    QSignalSpy notes(&importer, &ScanImporter::importNote);
    QCOMPARE(importer.importFiles({scan}), 1);
    QVERIFY(tasks.waitForIdle(30000));
    QCOMPARE(imported.size(), 1);
    QCOMPARE(notes.size(), 1);
    QCOMPARE(notes.at(0).at(0), imported.at(0).at(0));
    const QString note = notes.at(0).at(1).toString(); // "point(s)": the English plural comes with the translator
    QVERIFY2(note.startsWith(QStringLiteral("grid.xyz: 3 point")) &&
                 note.endsWith(QStringLiteral(" with NaN or infinite coordinates skipped")),
             qPrintable(note));
    QCOMPARE(doc.octree(imported.at(0).at(0).toULongLong())->description().points, 64u);
}

void ScanImporterTest::mergedScansAreSaid()
{
    // A PTX of two scans becomes one fragment, and the Log says so (it said only "Imported"), with the normals
    // estimated scan by scan; a file of one scan, or a cloud without scans, says nothing of scans.
    const QString folder = freshFolder("scans");
    const auto scanText = [](int scans) {
        QByteArray text;
        for (int s = 0; s < scans; ++s) {
            text += "1\n64\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
            for (int i = 0; i < 8; ++i)
                for (int j = 0; j < 8; ++j)
                    text += QByteArray::number(0.1 + i * 0.01 + s * 0.003) + ' ' + QByteArray::number(j * 0.01) + ' ' +
                            QByteArray::number(0.001 * s) + " 0.5\n";
        }
        return text;
    };
    const QString two = stylos::test::writeFile(folder, "stations.ptx", scanText(2));
    const QString one = stylos::test::writeFile(folder, "single.ptx", scanText(1));
    TaskManager tasks;
    SceneDocument doc(tasks);
    ScanImporter importer(doc, tasks);
    importer.setBuildOptions(m_options);
    importer.setCacheDirectory(freshFolder("cache-scans"));
    QSignalSpy imported(&importer, &ScanImporter::fragmentImported);
    QSignalSpy notes(&importer, &ScanImporter::importNote);
    QCOMPARE(importer.importFiles({two, one}), 2);
    QVERIFY(tasks.waitForIdle(30000));
    QCOMPARE(imported.size(), 2);
    QCOMPARE(notes.size(), 1);
    const quint64 id = notes.at(0).at(0).toULongLong();
    QCOMPARE(QString::fromStdString(doc.fragment(id)->name), QStringLiteral("stations"));
    QCOMPARE(doc.octree(id)->description().points, 128u);
    const QString note = notes.at(0).at(1).toString(); // "scan(s)": the English plural comes with the translator
    QVERIFY2(note.startsWith(QStringLiteral("stations.ptx holds 2 scan")) &&
                 note.endsWith(QStringLiteral(" merged into one fragment; each point's normal was estimated from its "
                                              "own scan's points")),
             qPrintable(note));
}

void ScanImporterTest::cancelLeavesNothing()
{
    // ~130 k points without normals: estimating them and building takes long enough to cancel.
    const QString folder = freshFolder("cancel");
    const QString big = stylos::test::generateScanFile(folder, "big.ply", SyntheticKind::Fragment, 0.002, false);
    const QStringList inputs = stylos::test::filesUnder(folder);
    TaskManager tasks;
    tasks.setMaxConcurrent(1); // the second import waits: both ways of cancelling are exercised
    SceneDocument doc(tasks);
    ScanImporter importer(doc, tasks);
    stylos::core::octree::BuildOptions options = m_options;
    options.depth = 10;
    importer.setBuildOptions(options);
    const QString cache = freshFolder("cache-cancel");
    importer.setCacheDirectory(cache);
    QSignalSpy failed(&importer, &ScanImporter::importFailed);
    QSignalSpy finished(&importer, &ScanImporter::importsFinished);
    QSignalSpy ended(&tasks, &TaskManager::taskFinished);

    QCOMPARE(importer.importFiles({big, m_fragmentScan}), 2);
    const auto ids = tasks.tasks();
    QCOMPARE(ids.size(), 2);
    QTRY_VERIFY_WITH_TIMEOUT(tasks.isRunning(ids[0]) && tasks.progress(ids[0]) > 0, 10000);
    QVERIFY(!tasks.isRunning(ids[1]));
    tasks.cancelAll();
    QVERIFY(tasks.waitForIdle(30000));
    QCOMPARE(ended.size(), 2);
    QVERIFY(ended.at(0).at(1).toBool() && ended.at(1).at(1).toBool()); // both ended cancelled
    QCOMPARE(finished.size(), 1);
    QCOMPARE(finished.at(0).at(0).toStringList(), QStringList());
    QCOMPARE(failed.size(), 0);
    QVERIFY(doc.scene().empty());
    QCOMPARE(doc.undoStack()->count(), 0);
    QCOMPARE(stylos::test::filesUnder(cache), QStringList());
    QCOMPARE(stylos::test::filesUnder(folder), inputs);
}

void ScanImporterTest::dialogsAndDropsUseTheCoreListOfExtensions()
{
    QCOMPARE(ScanImporter::fileFilter(),
             QStringLiteral("Scans and octrees (*.ply *.las *.e57 *.ptx *.xyz *.xyzn *.asc *.csv *.pts *.txt *.neu *.obj *.laz *.poct);;"
                            "Packed octrees (*.poct);;All files (*)"));
    QVERIFY(ScanImporter::canImport(QStringLiteral("/data/Drum.PLY")));
    QVERIFY(ScanImporter::canImport(QStringLiteral("scan.neu")));
    QVERIFY(ScanImporter::canImport(QStringLiteral("drum.poct")));
    QVERIFY(ScanImporter::canImport(QStringLiteral("site.E57")));
    QVERIFY(ScanImporter::canImport(QStringLiteral("site.ptx")));
    QVERIFY(ScanImporter::canImport(QStringLiteral("scan.laz"))); // refused on import, with what to do
    QVERIFY(!ScanImporter::canImport(QStringLiteral("notes.pdf")));
    // A drop takes projects and importable files, local ones only, in their order.
    auto local = [](const char* path) { return QUrl::fromLocalFile(QString::fromLatin1(path)); };
    const QList<QUrl> urls{local("/d/a.las"), local("/d/b.pdf"), QUrl(QStringLiteral("https://example.org/c.ply")),
                           local("/d/p.stylos"), local("/d/e.e57"), local("/d/f.Poct"), local("/d/g.laz")};
    QCOMPARE(stylos::app::ProjectActions::openableFiles(urls),
             (QStringList{QStringLiteral("/d/a.las"), QStringLiteral("/d/p.stylos"), QStringLiteral("/d/e.e57"),
                          QStringLiteral("/d/f.Poct"), QStringLiteral("/d/g.laz")}));
    QVERIFY(stylos::app::ProjectActions::openableFiles({local("/d/b.pdf")}).isEmpty());
}

STYLOS_WIDGET_TEST_MAIN(ScanImporterTest)
#include "ScanImporterTest.moc"
