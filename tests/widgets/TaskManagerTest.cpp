// TaskManager and TaskListWidget: several jobs at once, each with its row, progress and Cancel; results on
// the GUI thread; queued jobs wait for a worker; waitForIdle for automation.
#include "WidgetTestSupport.h"

#include "stylos/widgets/tasks/TaskListWidget.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QThread>

#include <atomic>
#include <memory>

using stylos::core::ProgressSink;
using stylos::widgets::TaskListWidget;
using stylos::widgets::TaskManager;

namespace {

/** Reports @p fraction, then runs until cancelled (or released); records what it saw. */
struct HeldJob {
    double fraction = 0.5;
    int result = 0;
    std::shared_ptr<std::atomic<bool>> running = std::make_shared<std::atomic<bool>>(false);
    std::shared_ptr<std::atomic<bool>> release = std::make_shared<std::atomic<bool>>(false);
    std::shared_ptr<std::atomic<bool>> sawCancel = std::make_shared<std::atomic<bool>>(false);

    void operator()(QPromise<int>& promise, ProgressSink& progress) const
    {
        running->store(true);
        progress.update(fraction);
        while (!release->load()) {
            if (progress.isCancelRequested()) {
                sawCancel->store(true);
                return;
            }
            QThread::msleep(2);
        }
        progress.update(1.0);
        promise.addResult(result);
    }
};

} // namespace

class TaskManagerTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void twoJobsRunAtOnceWithResultsOnTheGuiThread();
    void eachTaskHasARowWithProgress();
    void cancelButtonStopsOnlyItsTask();
    void jobsBeyondThePoolWait();
    void waitForIdleTimesOutOnAStuckJob();
};

void TaskManagerTest::twoJobsRunAtOnceWithResultsOnTheGuiThread()
{
    TaskManager manager;
    QVERIFY(manager.maxConcurrent() >= 2);
    // Each job waits until both are running: this only ends if they run at the same time.
    auto started = std::make_shared<std::atomic<int>>(0);
    auto job = [started](int value) {
        return [started, value](QPromise<int>& promise, ProgressSink& progress) {
            started->fetch_add(1);
            for (int i = 0; i < 5000 && started->load() < 2; ++i) QThread::msleep(1);
            progress.update(0.5);
            promise.addResult(started->load() == 2 ? value : -1);
        };
    };
    QSignalSpy added(&manager, &TaskManager::taskAdded);
    QSignalSpy finished(&manager, &TaskManager::taskFinished);
    QSignalSpy idle(&manager, &TaskManager::idle);
    auto* first = manager.start<int>("first", job(10));
    auto* second = manager.start<int>("second", job(20));
    QCOMPARE(manager.count(), 2);
    QCOMPARE(added.size(), 2);
    const TaskManager::TaskId firstId = manager.taskOf(first);
    const TaskManager::TaskId secondId = manager.taskOf(second);
    QVERIFY(firstId != 0 && secondId != 0 && firstId != secondId);
    QCOMPARE(manager.tasks(), (QList<TaskManager::TaskId>{firstId, secondId}));
    QCOMPARE(manager.label(secondId), QString("second"));

    QList<int> results;
    bool onGuiThread = true;
    for (auto* watcher : {first, second}) {
        connect(watcher, &QFutureWatcherBase::finished, this, [&, watcher] {
            onGuiThread = onGuiThread && QThread::currentThread() == qApp->thread();
            results << watcher->result();
        });
    }
    QVERIFY(manager.waitForIdle(10000));
    std::sort(results.begin(), results.end());
    QCOMPARE(results, (QList<int>{10, 20}));
    QVERIFY(onGuiThread);
    QCOMPARE(finished.size(), 2);
    QCOMPARE(finished.at(0).at(1).toBool(), false);
    QVERIFY(manager.isIdle());
    QCOMPARE(manager.taskOf(first), TaskManager::TaskId(0));
    QTRY_COMPARE(idle.size(), 1);
}

void TaskManagerTest::eachTaskHasARowWithProgress()
{
    TaskManager manager;
    TaskListWidget list(manager);
    list.show();
    QCOMPARE(list.rowCount(), 0);
    QVERIFY(list.findChild<QLabel*>("taskListEmpty")->isVisibleTo(&list));

    HeldJob a, b;
    a.fraction = 0.25;
    b.fraction = 0.75;
    const auto idA = manager.taskOf(manager.start<int>("Importing a.ply", a));
    const auto idB = manager.taskOf(manager.start<int>("Importing b.ply", b));
    QCOMPARE(list.rowCount(), 2);
    QVERIFY(!list.findChild<QLabel*>("taskListEmpty")->isVisibleTo(&list));
    QCOMPARE(list.labelOf(idA)->text(), QString("Importing a.ply"));
    QCOMPARE(list.labelOf(idB)->text(), QString("Importing b.ply"));
    QTRY_COMPARE(list.progressBar(idA)->value(), 250);
    QTRY_COMPARE(list.progressBar(idB)->value(), 750);
    QCOMPARE(manager.progress(idA), 250);
    QVERIFY(manager.isRunning(idA) && manager.isRunning(idB));
    QCOMPARE(list.progressBar(idA)->format(), QString("%p%"));

    QSignalSpy finished(&manager, &TaskManager::taskFinished);
    a.release->store(true);
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.at(0).at(0).value<TaskManager::TaskId>(), idA);
    QCOMPARE(list.rowCount(), 1);
    QVERIFY(!list.progressBar(idA));
    b.release->store(true);
    QVERIFY(manager.waitForIdle(10000));
    QCOMPARE(list.rowCount(), 0);
    QVERIFY(list.findChild<QLabel*>("taskListEmpty")->isVisibleTo(&list));
}

void TaskManagerTest::cancelButtonStopsOnlyItsTask()
{
    TaskManager manager;
    TaskListWidget list(manager);
    list.show();
    HeldJob a, b;
    b.result = 7;
    const auto idA = manager.taskOf(manager.start<int>("a", a));
    auto* watcherB = manager.start<int>("b", b);
    const auto idB = manager.taskOf(watcherB);
    QTRY_VERIFY(a.running->load() && b.running->load());

    QSignalSpy finished(&manager, &TaskManager::taskFinished);
    QTest::mouseClick(list.cancelButton(idA), Qt::LeftButton);
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.size(), 1);
    QCOMPARE(finished.at(0).at(0).value<TaskManager::TaskId>(), idA);
    QCOMPARE(finished.at(0).at(1).toBool(), true);
    QVERIFY(a.sawCancel->load());
    QVERIFY(!b.sawCancel->load());
    QCOMPARE(manager.tasks(), QList<TaskManager::TaskId>{idB});
    QVERIFY(list.cancelButton(idB)->isEnabled());

    int result = 0;
    connect(watcherB, &QFutureWatcherBase::finished, this, [&] { result = watcherB->result(); });
    b.release->store(true);
    QVERIFY(manager.waitForIdle(10000));
    QCOMPARE(result, 7);
    QCOMPARE(finished.at(1).at(1).toBool(), false);
}

void TaskManagerTest::jobsBeyondThePoolWait()
{
    TaskManager manager;
    manager.setMaxConcurrent(1);
    TaskListWidget list(manager);
    HeldJob a, b;
    const auto idA = manager.taskOf(manager.start<int>("a", a));
    const auto idB = manager.taskOf(manager.start<int>("b", b));
    QTRY_VERIFY(manager.isRunning(idA));
    QVERIFY(!manager.isRunning(idB));
    QVERIFY(!b.running->load());
    QCOMPARE(list.progressBar(idB)->format(), QString("Waiting…"));

    // Cancelling a waiting task ends it without running it.
    QSignalSpy finished(&manager, &TaskManager::taskFinished);
    manager.cancel(idB);
    a.release->store(true);
    QVERIFY(manager.waitForIdle(10000));
    QCOMPARE(finished.size(), 2);
    QVERIFY(!b.running->load());
}

void TaskManagerTest::waitForIdleTimesOutOnAStuckJob()
{
    TaskManager manager;
    HeldJob a;
    manager.start<int>("stuck", a);
    QElapsedTimer timer;
    timer.start();
    QVERIFY(!manager.waitForIdle(200));
    QVERIFY(timer.elapsed() >= 150);
    manager.cancelAll();
    QVERIFY(manager.waitForIdle(10000));
    QVERIFY(a.sawCancel->load() || !a.running->load());
}

STYLOS_WIDGET_TEST_MAIN(TaskManagerTest)
#include "TaskManagerTest.moc"
