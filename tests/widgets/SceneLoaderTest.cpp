// SceneLoader: streaming a file in the background gives its exact count and bounds; bad files give a
// translated message naming the file; per-file results arrive on the GUI thread.
#include "WidgetTestSupport.h"

#include "stylos/core/util/Progress.h"
#include "stylos/widgets/SceneLoader.h"
#include "stylos/widgets/TaskRunner.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QThread>

using stylos::widgets::ScanSummary;
using stylos::widgets::SceneLoader;
using stylos::widgets::TaskRunner;

class SceneLoaderTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void scanFileGivesExactCountAndBounds();
    void loadsInTheBackground();
    void badFileGivesMessageNamingIt_data();
    void badFileGivesMessageNamingIt();
    void goodAndBadFilesAreReportedSeparately();
    void refusesWhileBusy();

private:
    QTemporaryDir m_dir;
};

void SceneLoaderTest::scanFileGivesExactCountAndBounds()
{
    const QString path = stylos::test::writeFile(m_dir.path(), "four.ply", stylos::test::fourPointPly());
    stylos::core::SilentProgress progress;
    auto scanned = SceneLoader::scanFile(path.toStdString(), &progress);
    QVERIFY2(scanned.ok(), scanned.ok() ? "" : scanned.error().message.c_str());
    QCOMPARE(scanned->points, 4u);
    QCOMPARE(scanned->skipped, 0u);
    QCOMPARE(scanned->bounds, (std::array<double, 6>{-2.5, -1.0, 10.0, 3.0, 0.25, 12.0}));
    QVERIFY(scanned->format.startsWith("ply"));
    QVERIFY(scanned->attributes.isEmpty());
    QCOMPARE(progress.last(), 1.0);
}

void SceneLoaderTest::loadsInTheBackground()
{
    const QString path = stylos::test::writeFile(m_dir.path(), "tiny.ply", stylos::test::tinyPly());
    TaskRunner runner;
    SceneLoader loader(runner);
    QList<ScanSummary> loaded;
    bool onGuiThread = true;
    connect(&loader, &SceneLoader::fileLoaded, this, [&](const ScanSummary& summary) {
        onGuiThread = onGuiThread && QThread::currentThread() == qApp->thread();
        loaded << summary;
    });
    QSignalSpy finished(&loader, &SceneLoader::finished);
    QSignalSpy progress(&runner, &TaskRunner::progressChanged);

    QVERIFY(loader.load({path}));
    QVERIFY(runner.isBusy());
    QVERIFY(finished.wait(10000));
    QVERIFY(!runner.isBusy());

    QCOMPARE(finished.first().at(0).toInt(), 1); // loaded
    QCOMPARE(finished.first().at(1).toInt(), 0); // failed
    QCOMPARE(finished.first().at(2).toBool(), false);
    QVERIFY(onGuiThread);
    QCOMPARE(loaded.size(), 1);
    QCOMPARE(loaded[0].points, 3u);
    QCOMPARE(loaded[0].bounds, (std::array<double, 6>{0.0, 0.0, 0.0, 1.0, 1.0, 2.0}));
    QCOMPARE(loaded[0].path, QFileInfo(path).absoluteFilePath());
    QVERIFY(!progress.isEmpty());
}

void SceneLoaderTest::badFileGivesMessageNamingIt_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("reason");
    QTest::newRow("not a ply") << "broken.ply" << QByteArray("this is not a point file\n") << "malformed";
    QTest::newRow("truncated") << "short.ply"
                               << QByteArray("ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\n"
                                             "property float y\nproperty float z\nend_header\n0 0 0\n")
                               << "truncated";
    QTest::newRow("empty") << "empty.xyz" << QByteArray() << "empty";
    QTest::newRow("unknown") << "notes.doc" << QByteArray("hello") << "not recognised";
    QTest::newRow("missing") << "missing.ply" << QByteArray("-") << "does not exist";
}

void SceneLoaderTest::badFileGivesMessageNamingIt()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, content);
    QFETCH(QString, reason);
    const QString path = content == "-" ? m_dir.filePath(name) : stylos::test::writeFile(m_dir.path(), name, content);

    TaskRunner runner;
    SceneLoader loader(runner);
    QSignalSpy failed(&loader, &SceneLoader::fileFailed);
    QSignalSpy loaded(&loader, &SceneLoader::fileLoaded);
    QSignalSpy finished(&loader, &SceneLoader::finished);
    QVERIFY(loader.load({path}));
    QVERIFY(finished.wait(10000));

    QCOMPARE(loaded.size(), 0);
    QCOMPARE(failed.size(), 1);
    const QString message = failed.first().at(1).toString();
    QVERIFY2(message.contains(name), qPrintable(message));
    QVERIFY2(message.contains(reason, Qt::CaseInsensitive), qPrintable(message));
    QCOMPARE(finished.first().at(1).toInt(), 1);
}

void SceneLoaderTest::goodAndBadFilesAreReportedSeparately()
{
    const QString good = stylos::test::writeFile(m_dir.path(), "good.ply", stylos::test::tinyPly());
    const QString bad = stylos::test::writeFile(m_dir.path(), "bad.ply", "garbage");
    const QString other = stylos::test::writeFile(m_dir.path(), "other.ply", stylos::test::fourPointPly());
    TaskRunner runner;
    SceneLoader loader(runner);
    QSignalSpy failed(&loader, &SceneLoader::fileFailed);
    QSignalSpy loaded(&loader, &SceneLoader::fileLoaded);
    QSignalSpy finished(&loader, &SceneLoader::finished);
    QVERIFY(loader.load({good, bad, other}));
    QVERIFY(finished.wait(10000));
    QCOMPARE(loaded.size(), 2);
    QCOMPARE(failed.size(), 1);
    QCOMPARE(failed.first().at(0).toString(), QFileInfo(bad).absoluteFilePath());
    QCOMPARE(finished.first().at(0).toInt(), 2);
    QCOMPARE(finished.first().at(1).toInt(), 1);
}

void SceneLoaderTest::refusesWhileBusy()
{
    TaskRunner runner;
    SceneLoader loader(runner);
    QVERIFY(!loader.load({}));
    std::atomic<bool> release{false};
    auto* watcher = runner.start<int>("block", [&](QPromise<int>&, stylos::core::ProgressSink& progress) {
        while (!release && !progress.isCancelRequested()) QThread::msleep(1);
    });
    QVERIFY(watcher);
    QVERIFY(!loader.load({m_dir.filePath("tiny.ply")}));
    QSignalSpy finished(&runner, &TaskRunner::finished);
    release = true;
    QVERIFY(finished.wait(10000));
}

STYLOS_WIDGET_TEST_MAIN(SceneLoaderTest)
#include "SceneLoaderTest.moc"
