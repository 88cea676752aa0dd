#pragma once
/** @file
 * @brief "Fit drum guides" and "Delete guides" for the window: start() runs a GuideFitJob on a fragment
 *        that has an opened octree (on the document's TaskManager through FragmentJobs, so the Tasks dock
 *        lists it with Cancel, a new project cancels it and a stale result is dropped), and a result becomes
 *        the fragment's guides as one undo step ("Fit the guides of NAME"); a failure comes back as failed()
 *        with the translated message, and nothing changes. GUI thread only.
 */
#include "stylos/widgets/docking/GuideFitJob.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/FragmentJobs.h"

#include <QFuture>
#include <QObject>

namespace stylos::widgets {

class GuideFitRunner : public QObject {
    Q_OBJECT

public:
    using FragmentId = SceneDocument::FragmentId;

    /** @p document is not owned and must outlive the runner. */
    explicit GuideFitRunner(SceneDocument& document, QObject* parent = nullptr);

    /** @brief Starts fitting the guides of @p id; false (nothing started) when it does not exist, has no opened
     *         octree or is being fitted already. */
    bool start(FragmentId id, const core::dock::GuideOptions& options = {});
    /** @brief Removes every guide of @p id as one undo step; false when it has none. */
    bool deleteGuides(FragmentId id);
    bool isRunning(FragmentId id) const { return m_jobs.isRunning(id); }

Q_SIGNALS:
    /** @brief The fragment's guides were replaced by the fitted ones (one undo step). */
    void fitted(quint64 id, const stylos::widgets::GuideFitResult& result);
    /** @brief A fit failed: @p message is translated and names the fragment and the reason. */
    void failed(quint64 id, const QString& message);
    /** @brief A fit was cancelled (from the Tasks dock): @p message says so, translated. */
    void cancelled(quint64 id, const QString& message);

private:
    void delivered(FragmentId id, const QFuture<GuideFitResult>& future);

    SceneDocument& m_document;
    FragmentJobs m_jobs;
};

} // namespace stylos::widgets
