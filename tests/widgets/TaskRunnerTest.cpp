// TaskRunner and TaskStatusWidget: results and progress arrive on the GUI thread, one task at a time,
// and Cancel (from the API or from the status bar's button) stops a running job.
#include "WidgetTestSupport.h"

#include "stylos/widgets/TaskRunner.h"
#include "stylos/widgets/TaskStatusWidget.h"

#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QThread>

#include <atomic>

using stylos::core::ProgressSink;
using stylos::widgets::TaskRunner;
using stylos::widgets::TaskStatusWidget;

namespace {

/** A job that reports progress and runs until it is cancelled; records what it saw. */
struct EndlessJob {
    std::shared_ptr<std::atomic<bool>> sawCancel = std::make_shared<std::atomic<bool>>(false);
    std::shared_ptr<std::atomic<bool>> running = std::make_shared<std::atomic<bool>>(false);

    void operator()(QPromise<int>& promise, ProgressSink& progress) const
    {
        running->store(true);
        for (int i = 0; !progress.isCancelRequested(); ++i) {
            progress.update(std::min(0.9, i / 1000.0));
            QThread::msleep(1);
        }
        sawCancel->store(true);
        promise.addResult(-1); // dropped: a cancelled future takes no more results
    }
};

} // namespace

class TaskRunnerTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void deliversResultAndProgressOnGuiThread();
    void runsOneTaskAtATime();
    void cancelStopsARunningJob();
    void cancelButtonStopsTheTask();
};

void TaskRunnerTest::deliversResultAndProgressOnGuiThread()
{
    TaskRunner runner;
    QSignalSpy started(&runner, &TaskRunner::started);
    QSignalSpy progress(&runner, &TaskRunner::progressChanged);
    QSignalSpy finished(&runner, &TaskRunner::finished);
    auto* watcher = runner.start<int>("sum", [](QPromise<int>& promise, ProgressSink& sink) {
        int sum = 0;
        for (int i = 1; i <= 100; ++i) {
            sum += i;
            sink.update(i / 100.0);
        }
        promise.addResult(sum);
    });
    QVERIFY(watcher);
    QCOMPARE(runner.currentLabel(), QString("sum"));
    int result = 0;
    bool onGuiThread = false;
    connect(watcher, &QFutureWatcherBase::finished, this, [&] {
        onGuiThread = QThread::currentThread() == qApp->thread();
        result = watcher->result();
    });
    QVERIFY(finished.wait(10000));
    QCOMPARE(started.size(), 1);
    QCOMPARE(finished.first().at(0).toBool(), false);
    QTRY_COMPARE(result, 5050);
    QVERIFY(onGuiThread);
    QVERIFY(!runner.isBusy());
    QVERIFY(!progress.isEmpty());
    QCOMPARE(progress.last().at(0).toInt(), stylos::widgets::ProgressScale);
}

void TaskRunnerTest::runsOneTaskAtATime()
{
    TaskRunner runner;
    EndlessJob job;
    QVERIFY(runner.start<int>("first", job));
    QVERIFY(runner.isBusy());
    QVERIFY(!runner.start<int>("second", job));
    QSignalSpy finished(&runner, &TaskRunner::finished);
    runner.cancel();
    QVERIFY(finished.wait(10000));
    QVERIFY(runner.start<int>("third", [](QPromise<int>& p, ProgressSink&) { p.addResult(3); }));
    QVERIFY(finished.wait(10000));
}

void TaskRunnerTest::cancelStopsARunningJob()
{
    TaskRunner runner;
    EndlessJob job;
    auto* watcher = runner.start<int>("endless", job);
    QVERIFY(watcher);
    QTRY_VERIFY(job.running->load());
    QSignalSpy finished(&runner, &TaskRunner::finished);
    int results = -100;
    connect(watcher, &QFutureWatcherBase::finished, this, [&] { results = watcher->future().resultCount(); });
    runner.cancel();
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.first().at(0).toBool(), true);
    QVERIFY(job.sawCancel->load());
    QTRY_COMPARE(results, 0);
    QVERIFY(!runner.isBusy());
}

void TaskRunnerTest::cancelButtonStopsTheTask()
{
    TaskRunner runner;
    QWidget host;
    auto& status = *new TaskStatusWidget(runner, &host);
    host.show();
    QVERIFY(QTest::qWaitForWindowExposed(&host));
    QVERIFY(status.isHidden());

    EndlessJob job;
    QVERIFY(runner.start<int>("endless", job));
    QVERIFY(status.isVisible());
    QTRY_VERIFY(job.running->load());
    QTRY_VERIFY(status.progressBar()->value() > 0);

    QSignalSpy finished(&runner, &TaskRunner::finished);
    QTest::mouseClick(status.cancelButton(), Qt::LeftButton);
    QVERIFY(!status.cancelButton()->isEnabled());
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.first().at(0).toBool(), true);
    QVERIFY(job.sawCancel->load());
    QVERIFY(status.isHidden());
}

STYLOS_WIDGET_TEST_MAIN(TaskRunnerTest)
#include "TaskRunnerTest.moc"
