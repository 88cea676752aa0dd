#pragma once
/** @file
 * @brief Runs one long core job at a time on the global thread pool (QtConcurrent::run + QPromise) and
 *        publishes its progress and end on the GUI thread through a QFutureWatcher. Never spins an event
 *        loop: callers react to signals. Workers never touch widgets; results are applied on the GUI thread
 *        by whoever connects to the watcher that start() returns.
 */
#include "stylos/widgets/PromiseProgress.h"

#include <QFutureWatcher>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QtConcurrent/QtConcurrentRun>

#include <utility>

namespace stylos::widgets {

class TaskRunner : public QObject {
    Q_OBJECT

public:
    explicit TaskRunner(QObject* parent = nullptr);
    ~TaskRunner() override;

    /** True while a task runs (from start() until its finished() has been delivered). */
    bool isBusy() const { return m_current != nullptr; }
    /** The running task's label, empty when idle. */
    QString currentLabel() const { return m_label; }

    /**
     * @brief Starts @p job, a callable `void(QPromise<T>&, core::ProgressSink&)`, on a worker thread.
     *        The job adds its results to the promise (one or several); the sink reports progress and
     *        cancellation. Returns the task's watcher, owned by the runner and deleted after its
     *        finished() signal: connect to resultReadyAt()/finished() right away, on the GUI thread.
     *        Returns nullptr when another task is running (one task at a time).
     */
    template <typename T, typename Job>
    QFutureWatcher<T>* start(const QString& label, Job job)
    {
        if (isBusy()) return nullptr;
        auto* watcher = new QFutureWatcher<T>(this);
        attach(watcher, label);
        watcher->setFuture(QtConcurrent::run([job = std::move(job)](QPromise<T>& promise) mutable {
            promise.setProgressRange(0, ProgressScale);
            PromiseProgress<T> sink(promise);
            job(promise, static_cast<core::ProgressSink&>(sink));
        }));
        return watcher;
    }

public Q_SLOTS:
    /** Asks the running task to stop; it ends at its next progress check with no further results. */
    void cancel();
    /** Cancels the running task and blocks until its worker has returned (for shutdown only). */
    void cancelAndWait();

Q_SIGNALS:
    void started(const QString& label);
    /** Progress of the running task in per-mille (0..ProgressScale). */
    void progressChanged(int perMille);
    /** The running task ended (normally, with an error in its result, or cancelled). */
    void finished(bool cancelled);

private:
    void attach(QFutureWatcherBase* watcher, const QString& label);

    QPointer<QFutureWatcherBase> m_current;
    QString m_label;
};

} // namespace stylos::widgets
