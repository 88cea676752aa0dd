#pragma once
/** @file
 * @brief Runs any number of long core jobs at once (the Tasks dock lists them): each job runs on the
 *        manager's own thread pool through QtConcurrent::run + QPromise, as TaskRunner's single job does,
 *        and its progress, end and results reach the GUI thread through a QFutureWatcher. Jobs beyond the
 *        pool's size wait in its queue ("waiting" until a worker picks them up). Never spins an event loop,
 *        except waitForIdle(), which tests and automation (--grab) call and production code does not.
 *        Thread-safety: GUI thread only; workers never touch the manager or widgets.
 */
#include "stylos/widgets/tasks/PromiseProgress.h"

#include <QFutureWatcher>
#include <QList>
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>

#include <map>
#include <utility>

namespace stylos::widgets {

class TaskManager : public QObject {
    Q_OBJECT

public:
    /** @brief A task's handle: unique within this manager, never reused, never 0. */
    using TaskId = quint64;

    explicit TaskManager(QObject* parent = nullptr);
    /** @brief Cancels every task and waits for the workers to return (their results are dropped). */
    ~TaskManager() override;

    /**
     * @brief Starts @p job, a callable `void(QPromise<T>&, core::ProgressSink&)`, on a worker thread.
     *        The job adds its results to the promise; the sink reports progress (its [0, 1] becomes the
     *        task's per-mille) and cancellation. Returns the task's watcher, owned by the manager and
     *        deleted after its finished() signal: connect to resultReadyAt()/finished() right away, on
     *        the GUI thread. The manager's own bookkeeping runs first, so in a finished() handler the
     *        task is already gone from tasks() and the handler may start further tasks.
     */
    template <typename T, typename Job>
    QFutureWatcher<T>* start(const QString& label, Job job)
    {
        auto* watcher = new QFutureWatcher<T>(this);
        attach(watcher, label);
        watcher->setFuture(QtConcurrent::run(&m_pool, [job = std::move(job)](QPromise<T>& promise) mutable {
            // The range is set when a worker picks the job up: the watcher's progressRangeChanged()
            // is how the manager tells a running task from a waiting one.
            promise.setProgressRange(0, ProgressScale);
            PromiseProgress<T> sink(promise);
            job(promise, static_cast<core::ProgressSink&>(sink));
        }));
        return watcher;
    }

    /** @brief The task started with @p watcher, or 0 when it is not (or no longer) one of ours. */
    TaskId taskOf(const QFutureWatcherBase* watcher) const;
    /** @brief Unfinished tasks, in start order. */
    QList<TaskId> tasks() const;
    int count() const { return static_cast<int>(m_tasks.size()); }
    bool isIdle() const { return m_tasks.empty(); }
    /** @brief The label given to start(); empty for an unknown task. */
    QString label(TaskId id) const;
    /** @brief Progress in per-mille (0..ProgressScale); 0 for an unknown task. */
    int progress(TaskId id) const;
    /** @brief True once a worker has picked the task up (false while it waits in the queue). */
    bool isRunning(TaskId id) const;

    /** @brief Most tasks running at once (the rest wait); at least 1. Default: max(2, ideal thread count). */
    void setMaxConcurrent(int count);
    int maxConcurrent() const { return m_pool.maxThreadCount(); }

    /**
     * @brief For tests and automation only: processes events until no task is left (or @p timeoutMs
     *        passes; negative: no limit). Returns isIdle(). Results are delivered meanwhile, as usual.
     */
    bool waitForIdle(int timeoutMs = -1);

public Q_SLOTS:
    /** @brief Asks task @p id to stop: it ends at its next progress check (or before it starts). */
    void cancel(TaskId id);
    /** @brief Asks every task to stop. */
    void cancelAll();
    /** @brief Cancels every task and blocks until their workers have returned (shutdown, reset). */
    void cancelAllAndWait();

Q_SIGNALS:
    /** @brief A task was started (it may wait for a worker). */
    void taskAdded(stylos::widgets::TaskManager::TaskId id, const QString& label);
    /** @brief A worker picked the task up. */
    void taskRunning(stylos::widgets::TaskManager::TaskId id);
    /** @brief Progress in per-mille (0..ProgressScale). */
    void taskProgress(stylos::widgets::TaskManager::TaskId id, int perMille);
    /** @brief The task ended (normally, with an error in its result, or cancelled); it is gone from tasks(). */
    void taskFinished(stylos::widgets::TaskManager::TaskId id, bool cancelled);
    /** @brief The number of tasks changed. */
    void countChanged(int count);
    /** @brief No task is left, once the finished() handlers of the last one have run and started none. */
    void idle();

private:
    struct Task {
        QFutureWatcherBase* watcher = nullptr;
        QString label;
        int progress = 0;
        bool running = false;
    };

    void attach(QFutureWatcherBase* watcher, const QString& label);
    void finish(TaskId id);
    void emitIdleIfIdle();

    QThreadPool m_pool;
    std::map<TaskId, Task> m_tasks;  ///< ordered by id, i.e. start order
    TaskId m_nextId = 1;
};

} // namespace stylos::widgets
