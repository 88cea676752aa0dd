#pragma once
/** @file
 * @brief "Compute skydome" for the window in one call: start() runs one SkydomeJob per given fragment that
 *        has an opened octree (on the document's TaskManager, so the Tasks dock lists them with Cancel),
 *        and when a job succeeds hands its re-opened octree to SceneDocument::replaceOctree(), whose
 *        octreeChanged() the 3D view already follows. Failures come back as failed() with the translated
 *        message naming the file. A fragment whose skydome is already being computed is skipped. The jobs
 *        run through FragmentJobs: a new or opened project cancels them (their files untouched), and a
 *        result is applied only while the fragment still exists with the same octree file.
 *        GUI thread only.
 */
#include "stylos/widgets/tasks/FragmentJobs.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/skydome/SkydomeJob.h"

#include <QFuture>
#include <QList>
#include <QObject>

namespace stylos::widgets {

class SkydomeRunner : public QObject {
    Q_OBJECT

public:
    using FragmentId = SceneDocument::FragmentId;

    /** @p document is not owned and must outlive the runner. */
    explicit SkydomeRunner(SceneDocument& document, QObject* parent = nullptr);

    /**
     * @brief Starts a skydome task for each of @p ids that exists, has an opened octree and has no skydome
     *        task running. Returns the number of tasks started (0: nothing to do, nothing signalled).
     */
    int start(const QList<FragmentId>& ids, const SkydomeOptions& options = {});
    /** @brief True while a skydome task of @p id runs or waits. */
    bool isRunning(FragmentId id) const { return m_jobs.isRunning(id); }
    /** @brief Tasks running or waiting. */
    int count() const { return m_jobs.count(); }

Q_SIGNALS:
    /** @brief The fragment's octree now has its "ambient" layer (replaceOctree() was called). */
    void computed(quint64 id, const stylos::widgets::SkydomeResult& result);
    /** @brief A job failed: @p message is translated and names the file and the reason. */
    void failed(quint64 id, const QString& message);

private:
    void delivered(FragmentId id, const QFuture<SkydomeResult>& future);

    SceneDocument& m_document;
    FragmentJobs m_jobs;
};

} // namespace stylos::widgets
