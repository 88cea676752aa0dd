#pragma once
/** @file
 * @brief The one runner of per-fragment background jobs (développée, skydome, and the jobs to come): each
 *        job is keyed by its fragment's id *and* the octree file it reads, runs on the document's
 *        TaskManager (so the Tasks dock lists it with Cancel), and is cancelled when the project is reset
 *        (another project opened, a new one) or its fragment removed. When a job ends, its result is handed
 *        to the caller's delivery only while the key is still current — the same fragment, with the same
 *        octree file, in the same project; a stale result (fragment ids start at 1 in every project) is
 *        dropped. One job per fragment at a time per runner.
 *
 * Use: `jobs.start<Result>(id, label, job, [](FragmentId id, const QFuture<Result>& f) { … })`: the
 * delivery runs on the GUI thread with the finished future (no result when the job was cancelled by the
 * user). ended() follows every job, delivered or not, so busy indicators can clear. GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QFutureWatcher>
#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>
#include <map>
#include <optional>

namespace stylos::widgets {

class FragmentJobs : public QObject {
    Q_OBJECT

public:
    using FragmentId = SceneDocument::FragmentId;

    /** @p document is not owned and must outlive the runner; jobs run on document.tasks(). */
    explicit FragmentJobs(SceneDocument& document, QObject* parent = nullptr);

    /**
     * @brief Starts @p job for fragment @p id, keyed by the fragment's current octree file. Returns the
     *        watcher, or nullptr (nothing started) when the fragment does not exist or already has a job here.
     */
    template <typename R, typename Job>
    QFutureWatcher<R>* start(FragmentId id, const QString& label, Job job,
                             std::function<void(FragmentId, const QFuture<R>&)> deliver)
    {
        const std::optional<QString> path = octreePathOf(id);
        if (!path || isRunning(id)) return nullptr;
        QFutureWatcher<R>* watcher = m_document.tasks().template start<R>(label, std::move(job));
        track(id, *path, watcher, [watcher, deliver = std::move(deliver)](FragmentId key) {
            deliver(key, watcher->future());
        });
        return watcher;
    }

    /** @brief True while a job of @p id runs or waits. */
    bool isRunning(FragmentId id) const { return m_running.count(id) != 0; }
    /** @brief Jobs running or waiting. */
    int count() const { return static_cast<int>(m_running.size()); }
    /** @brief Cancels the job of @p id, if any: its result will not be delivered. */
    void cancel(FragmentId id);
    /** @brief Cancels every job: none will be delivered. */
    void cancelAll();

Q_SIGNALS:
    /** @brief A job of @p id ended: delivered (@p delivered) or dropped (cancelled, stale, or its fragment gone). */
    void ended(quint64 id, bool delivered);

private:
    struct Entry {
        QPointer<QFutureWatcherBase> watcher;
        QString octreePath;
    };

    /** The fragment's octree file as a key; nullopt when there is no such fragment. */
    std::optional<QString> octreePathOf(FragmentId id) const;
    void track(FragmentId id, const QString& path, QFutureWatcherBase* watcher, std::function<void(FragmentId)> deliver);
    void finished(FragmentId id, QFutureWatcherBase* watcher, const std::function<void(FragmentId)>& deliver);

    SceneDocument& m_document;
    std::map<FragmentId, Entry> m_running;
};

} // namespace stylos::widgets
