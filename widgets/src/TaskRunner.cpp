#include "stylos/widgets/TaskRunner.h"

namespace stylos::widgets {

TaskRunner::TaskRunner(QObject* parent) : QObject(parent) {}

TaskRunner::~TaskRunner()
{
    // A worker still running would report into a promise whose watcher is gone: stop it first.
    cancelAndWait();
}

void TaskRunner::cancel()
{
    if (m_current) m_current->cancel();
}

void TaskRunner::cancelAndWait()
{
    if (!m_current) return;
    m_current->cancel();
    m_current->waitForFinished();
}

void TaskRunner::attach(QFutureWatcherBase* watcher, const QString& label)
{
    m_current = watcher;
    m_label = label;
    connect(watcher, &QFutureWatcherBase::progressValueChanged, this, &TaskRunner::progressChanged);
    // Connected before the caller's own handlers, so the runner is idle again when they run and
    // they may start the next task from their finished() handler.
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] {
        const bool cancelled = watcher->isCanceled();
        if (m_current == watcher) {
            m_current = nullptr;
            m_label.clear();
        }
        watcher->deleteLater();
        Q_EMIT finished(cancelled);
    });
    Q_EMIT started(label);
    Q_EMIT progressChanged(0);
}

} // namespace stylos::widgets
