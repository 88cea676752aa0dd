// FragmentJobs: per-fragment jobs keyed by fragment id and octree file. A job still running when another
// project opens (whose fragment 1 is another file) is cancelled and delivers nothing; nor does one whose
// fragment was removed; a current one is delivered. Through DeveloppeeLink: a développée computing when
// another project opens never attaches to the new project's fragment 1.
#include "DeveloppeeLink.h"
#include "DrumOctreeFixture.h"
#include "WidgetTestSupport.h"

#include "stylos/core/scene/ProjectFile.h"
#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/tasks/FragmentJobs.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QDir>
#include <QSemaphore>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <atomic>
#include <memory>

using stylos::widgets::DeveloppeePanel;
using stylos::widgets::FragmentJobs;
using stylos::widgets::SceneDocument;
using stylos::widgets::TaskManager;

namespace {

/** A project of one fragment (id 1) reading @p octree, saved as @p path. */
void writeProject(const QString& path, const std::filesystem::path& octree, const char* name)
{
    stylos::core::scene::Scene scene;
    stylos::core::scene::Fragment fragment;
    fragment.name = name;
    fragment.octreePath = octree;
    scene.add(std::move(fragment));
    QVERIFY(stylos::core::scene::ProjectFile::save(scene, path.toStdString()).ok());
}

bool openAndWait(SceneDocument& document, const QString& path)
{
    QSignalSpy loaded(&document, &SceneDocument::loadingFinished);
    if (!document.open(path)) return false;
    return loaded.wait(30000) && document.octree(1) != nullptr;
}

/** A job that waits until released, then gives @p value. */
struct HeldJob {
    std::shared_ptr<QSemaphore> gate;
    int value;
    void operator()(QPromise<int>& promise, stylos::core::ProgressSink&) const
    {
        gate->acquire();
        promise.addResult(value);
    }
};

} // namespace

class FragmentJobsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void aCurrentJobIsDelivered();
    void anotherProjectCancelsAndDropsTheJob();
    void aRemovedFragmentsJobIsDropped();
    void aDeveloppeeNeverAttachesToTheNextProject();

private:
    QTemporaryDir m_dir;
    QString m_projectA, m_projectB;
};

void FragmentJobsTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    // Project A: a fine drum (its skydome développée takes seconds); project B: another file, also fragment 1.
    QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("a")) && QDir(m_dir.path()).mkpath(QStringLiteral("b")));
    const auto a = stylos::test::makeDrumOctree(m_dir.filePath(QStringLiteral("a")), 0.004, 9);
    const auto b = stylos::test::makeDrumOctree(m_dir.filePath(QStringLiteral("b")), 0.01, 7);
    m_projectA = m_dir.filePath(QStringLiteral("a.stylos"));
    m_projectB = m_dir.filePath(QStringLiteral("b.stylos"));
    writeProject(m_projectA, a.poct, "Drum A");
    writeProject(m_projectB, b.poct, "Drum B");
}

void FragmentJobsTest::aCurrentJobIsDelivered()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    QVERIFY(openAndWait(document, m_projectA));
    FragmentJobs jobs(document);
    QSignalSpy ended(&jobs, &FragmentJobs::ended);
    auto gate = std::make_shared<QSemaphore>();
    int delivered = 0;
    QVERIFY(jobs.start<int>(1, QStringLiteral("held"), HeldJob{gate, 42},
                            [&](quint64 id, const QFuture<int>& f) { delivered = int(id) * 1000 + f.result(); }));
    QVERIFY(jobs.isRunning(1));
    // One job per fragment; none for a fragment that does not exist.
    QVERIFY(!jobs.start<int>(1, QStringLiteral("again"), HeldJob{gate, 1}, [](quint64, const QFuture<int>&) {}));
    QVERIFY(!jobs.start<int>(99, QStringLiteral("none"), HeldJob{gate, 1}, [](quint64, const QFuture<int>&) {}));
    gate->release();
    QVERIFY(ended.wait(10000));
    QCOMPARE(delivered, 1042);
    QCOMPARE(ended.at(0).at(0).toULongLong(), 1ull);
    QCOMPARE(ended.at(0).at(1).toBool(), true);
    QVERIFY(!jobs.isRunning(1));
}

void FragmentJobsTest::anotherProjectCancelsAndDropsTheJob()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    QVERIFY(openAndWait(document, m_projectA));
    FragmentJobs jobs(document);
    QSignalSpy ended(&jobs, &FragmentJobs::ended);
    auto gate = std::make_shared<QSemaphore>();
    bool delivered = false;
    QVERIFY(jobs.start<int>(1, QStringLiteral("held"), HeldJob{gate, 7},
                            [&](quint64, const QFuture<int>&) { delivered = true; }));
    QSignalSpy idle(&tasks, &TaskManager::idle);
    QVERIFY(openAndWait(document, m_projectB)); // fragment 1 again, another file
    QVERIFY(!jobs.isRunning(1));
    gate->release(); // the old job now finishes: its result must go nowhere
    QTRY_VERIFY_WITH_TIMEOUT(tasks.count() == 0, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(ended.size(), 1, 10000);
    QCOMPARE(ended.at(0).at(1).toBool(), false);
    QVERIFY(!delivered);
}

void FragmentJobsTest::aRemovedFragmentsJobIsDropped()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    QVERIFY(openAndWait(document, m_projectA));
    FragmentJobs jobs(document);
    QSignalSpy ended(&jobs, &FragmentJobs::ended);
    auto gate = std::make_shared<QSemaphore>();
    bool delivered = false;
    QVERIFY(jobs.start<int>(1, QStringLiteral("held"), HeldJob{gate, 7},
                            [&](quint64, const QFuture<int>&) { delivered = true; }));
    QVERIFY(document.removeFragment(1));
    QVERIFY(!jobs.isRunning(1));
    gate->release();
    QTRY_COMPARE_WITH_TIMEOUT(ended.size(), 1, 10000);
    QCOMPARE(ended.at(0).at(1).toBool(), false);
    QVERIFY(!delivered);
}

void FragmentJobsTest::aDeveloppeeNeverAttachesToTheNextProject()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    QVERIFY(openAndWait(document, m_projectA));
    DeveloppeePanel dock;
    stylos::app::DeveloppeeLink link(document, dock, nullptr);
    link.setFragment(1);
    auto slow = dock.settings();
    slow.directions = stylos::widgets::DeveloppeeSettings::MaxDirections; // seconds: still running below
    dock.setSettings(slow);
    link.compute();
    QVERIFY(link.isComputing(1));
    QCOMPARE(tasks.count(), 1);

    QVERIFY(openAndWait(document, m_projectB));
    link.setFragment(1);
    QVERIFY(!link.isComputing(1));
    QTRY_VERIFY_WITH_TIMEOUT(tasks.count() == 0, 60000);
    QTest::qWait(50); // any queued delivery
    QVERIFY(!document.developpee(1));
    QVERIFY(!dock.view()->hasDeveloppee());

    // A développée computed now belongs to project B's file.
    dock.setSettings(stylos::widgets::DeveloppeeSettings{});
    QSignalSpy changed(&document, &SceneDocument::developpeeChanged);
    link.compute();
    QVERIFY(changed.wait(60000));
    QVERIFY(document.developpee(1));
    QCOMPARE(document.developpee(1)->octreePath, QString::fromStdString(document.fragment(1)->octreePath.string()));
    QVERIFY(document.developpee(1)->octreePath.contains(QStringLiteral("/b/")));
}

STYLOS_WIDGET_TEST_MAIN(FragmentJobsTest)
#include "FragmentJobsTest.moc"
