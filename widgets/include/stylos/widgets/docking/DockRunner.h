#pragma once
/** @file
 * @brief "Dock to flutes" for the window: start() docks a fragment against the guides of the document's docking
 *        drum. The drum's guides with their profile come from the DrumGuidesCache (fitted first when they are not
 *        there yet); the start pose is drumPose⁻¹ · fragmentPose (fragment frame → drum frame); a DockJob runs on
 *        the document's TaskManager through FragmentJobs (listed with Cancel; cancelled when the fragment goes, the
 *        project changes, or the drum goes or stops being the docking drum). On success the fragment's pose
 *        becomes drumPose · docked as ONE undo step ("Dock NAME"); a failure comes back as failed() with the
 *        translated message and nothing moves. A result is dropped (with a message) when the fragment or the drum
 *        moved while it ran. The locked unknowns (setLocked) stay out of the solve. GUI thread only.
 */
#include "stylos/core/dock/DockRegistration.h"
#include "stylos/widgets/docking/DockJob.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/FragmentJobs.h"

#include <QObject>
#include <QString>

#include <array>
#include <map>

namespace stylos::widgets {

class DrumGuidesCache;

class DockRunner : public QObject {
    Q_OBJECT

public:
    using FragmentId = SceneDocument::FragmentId;

    /** @p document and @p cache are not owned and must outlive the runner. */
    DockRunner(SceneDocument& document, DrumGuidesCache& cache, QObject* parent = nullptr);

    /** @brief True when @p id can be docked now: it exists, it is not the docking drum, and the docking drum has an
     *         Axis guide and at least 3 Groove guides. */
    bool canDock(FragmentId id) const;
    /** @brief Starts docking @p id; false (nothing started, failed() not emitted) when !canDock(id), its octree is
     *         not open or it is being docked already. */
    bool start(FragmentId id);
    bool isRunning(FragmentId id) const { return m_jobs.isRunning(id) || m_waiting.count(id) != 0; }

    void setLocked(core::dock::DockUnknown unknown, bool locked) { m_locked[std::size_t(unknown)] = locked; }
    bool isLocked(core::dock::DockUnknown unknown) const { return m_locked[std::size_t(unknown)]; }

Q_SIGNALS:
    /** @brief @p id was docked: its new pose is in the document (one undo step). */
    void docked(quint64 id, const stylos::widgets::DockJobResult& result);
    /** @brief Docking @p id failed or was dropped: @p message is translated and names the fragment and the reason. */
    void failed(quint64 id, const QString& message);
    /** @brief Docking @p id was cancelled (from the Tasks dock): @p message says so, translated. */
    void cancelled(quint64 id, const QString& message);

private:
    void launch(FragmentId id, FragmentId drum);
    void guidesReady(FragmentId drum);
    void guidesFailed(FragmentId drum, const QString& message);
    void delivered(FragmentId id, const QFuture<DockJobResult>& future);
    void drumGone(FragmentId drum);

    struct Launched {
        FragmentId drum = 0;
        core::scene::Pose fragmentPose, drumPose; ///< as they were when the job started
    };

    SceneDocument& m_document;
    DrumGuidesCache& m_cache;
    FragmentJobs m_jobs;
    std::array<bool, core::dock::DockUnknowns> m_locked{};
    std::map<FragmentId, FragmentId> m_waiting; ///< fragment → drum whose guides are being fitted
    std::map<FragmentId, Launched> m_launched;
};

} // namespace stylos::widgets
