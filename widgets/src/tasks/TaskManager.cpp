#include "stylos/widgets/tasks/TaskManager.h"

#include <QEventLoop>
#include <QThread>
#include <QTimer>

#include <algorithm>

namespace stylos::widgets {

TaskManager::TaskManager(QObject* parent) : QObject(parent)
{
    m_pool.setObjectName(QStringLiteral("TaskManagerPool"));
    m_pool.setMaxThreadCount(std::max(2, QThread::idealThreadCount()));
}

TaskManager::~TaskManager()
{
    // A worker still running would report into a promise whose watcher is gone: stop them first.
    cancelAllAndWait();
    m_pool.waitForDone();
}

TaskManager::TaskId TaskManager::taskOf(const QFutureWatcherBase* watcher) const
{
    for (const auto& [id, task] : m_tasks)
        if (task.watcher == watcher) return id;
    return 0;
}

QList<TaskManager::TaskId> TaskManager::tasks() const
{
    QList<TaskId> ids;
    for (const auto& entry : m_tasks) ids.append(entry.first);
    return ids;
}

QString TaskManager::label(TaskId id) const
{
    const auto it = m_tasks.find(id);
    return it == m_tasks.end() ? QString() : it->second.label;
}

int TaskManager::progress(TaskId id) const
{
    const auto it = m_tasks.find(id);
    return it == m_tasks.end() ? 0 : it->second.progress;
}

bool TaskManager::isRunning(TaskId id) const
{
    const auto it = m_tasks.find(id);
    return it != m_tasks.end() && it->second.running;
}

void TaskManager::setMaxConcurrent(int count)
{
    m_pool.setMaxThreadCount(std::max(1, count));
}

bool TaskManager::waitForIdle(int timeoutMs)
{
    if (isIdle()) return true;
    QEventLoop loop;
    bool timedOut = false;
    QTimer timer;
    timer.setSingleShot(true);
    connect(&timer, &QTimer::timeout, &loop, [&] {
        timedOut = true;
        loop.quit();
    });
    connect(this, &TaskManager::idle, &loop, &QEventLoop::quit);
    connect(this, &TaskManager::taskFinished, &loop, [&] {
        if (isIdle()) loop.quit();
    });
    if (timeoutMs >= 0) timer.start(timeoutMs);
    while (!isIdle() && !timedOut) loop.exec();
    return isIdle();
}

void TaskManager::cancel(TaskId id)
{
    const auto it = m_tasks.find(id);
    if (it != m_tasks.end()) it->second.watcher->cancel();
}

void TaskManager::cancelAll()
{
    for (auto& entry : m_tasks) entry.second.watcher->cancel();
}

void TaskManager::cancelAllAndWait()
{
    cancelAll();
    for (auto& entry : m_tasks) entry.second.watcher->waitForFinished();
}

void TaskManager::attach(QFutureWatcherBase* watcher, const QString& label)
{
    const TaskId id = m_nextId++;
    m_tasks.emplace(id, Task{watcher, label, 0, false});
    // The watcher replays the future's initial range (0, 0) on connection; the job's own comes later.
    connect(watcher, &QFutureWatcherBase::progressRangeChanged, this, [this, id](int, int maximum) {
        auto it = m_tasks.find(id);
        if (maximum != ProgressScale || it == m_tasks.end() || it->second.running) return;
        it->second.running = true;
        Q_EMIT taskRunning(id);
    });
    connect(watcher, &QFutureWatcherBase::progressValueChanged, this, [this, id](int value) {
        auto it = m_tasks.find(id);
        if (it == m_tasks.end()) return;
        it->second.progress = value;
        Q_EMIT taskProgress(id, value);
    });
    // Connected before the caller's own handlers (start() returns the watcher afterwards).
    connect(watcher, &QFutureWatcherBase::finished, this, [this, id] { finish(id); });
    Q_EMIT taskAdded(id, label);
    Q_EMIT countChanged(count());
}

void TaskManager::finish(TaskId id)
{
    const auto it = m_tasks.find(id);
    if (it == m_tasks.end()) return;
    QFutureWatcherBase* watcher = it->second.watcher;
    const bool cancelled = watcher->isCanceled();
    m_tasks.erase(it);
    watcher->deleteLater();
    Q_EMIT taskFinished(id, cancelled);
    Q_EMIT countChanged(count());
    // After the caller's finished() handlers, which run next and may start more tasks.
    if (isIdle()) QMetaObject::invokeMethod(this, &TaskManager::emitIdleIfIdle, Qt::QueuedConnection);
}

void TaskManager::emitIdleIfIdle()
{
    if (isIdle()) Q_EMIT idle();
}

} // namespace stylos::widgets
