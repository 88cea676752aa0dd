#pragma once
/** @file
 * @brief Keeps the contact readout of the current fragment against the docking drum up to date: after the
 *        fragment is chosen, after its pose or the drum's changes (a dock, a drag, an undo), after the drum or its
 *        guides change — debounced (delay(), 300 ms by default), then a ContactJob on the document's TaskManager
 *        through FragmentJobs; a job still running for an older pose is cancelled, and a result whose fragment,
 *        drum or relative pose is no longer the current one is dropped. The drum's guides come from the
 *        DrumGuidesCache (fitted first if needed). A fragment in an assembly is also measured against each other
 *        member (the drum aside), through their poses (members()); a member's move schedules a new readout.
 *        GUI thread only.
 */
#include "stylos/core/dock/ContactReadout.h"
#include "stylos/widgets/docking/ContactJob.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/FragmentJobs.h"

#include <Eigen/Geometry>

#include <QObject>
#include <QString>

#include <utility>
#include <vector>

class QTimer;

namespace stylos::widgets {

class DrumGuidesCache;

class ContactMonitor : public QObject {
    Q_OBJECT

public:
    using FragmentId = SceneDocument::FragmentId;
    enum class State {
        Off,       ///< no fragment, no docking drum with guides, or the fragment is the drum
        Computing, ///< a readout (or the drum's guides) is on its way
        Ready,     ///< readout() is the current fragment's at its current pose
        Failed,    ///< message() says why
    };

    /** @p document and @p cache are not owned and must outlive the monitor. */
    ContactMonitor(SceneDocument& document, DrumGuidesCache& cache, QObject* parent = nullptr);

    /** @brief The fragment whose contact is shown (NoFragment: none). */
    void setFragment(FragmentId id);
    FragmentId fragment() const { return m_fragment; }
    void setDelay(int milliseconds);
    int delay() const;

    State state() const { return m_state; }
    const core::dock::ContactReadout& readout() const { return m_readout; }
    /** @brief The contact with each other member of the fragment's assembly (in Ready), in display order. */
    const std::vector<MemberContact>& members() const { return m_members; }
    /** @brief Why the state is Failed (translated); empty otherwise. */
    QString message() const { return m_message; }
    /** @brief Readouts delivered so far (tests). */
    int deliveries() const { return m_deliveries; }

Q_SIGNALS:
    /** @brief state(), readout() or message() changed. */
    void changed();

private:
    void schedule();
    void measure();
    void delivered(const ContactJobResult& result);
    void setState(State state, const QString& message = {});
    /** The fragment's pose in the drum frame now; nullopt when there is no fragment or drum. */
    std::optional<Eigen::Isometry3d> relativePose() const;
    /** The other members of the fragment's assembly (not the drum) with their poses in its frame. */
    std::vector<ContactJob::Other> others() const;

    SceneDocument& m_document;
    DrumGuidesCache& m_cache;
    FragmentJobs m_jobs;
    QTimer* m_timer;
    FragmentId m_fragment = core::scene::NoFragment;
    State m_state = State::Off;
    core::dock::ContactReadout m_readout;
    std::vector<MemberContact> m_members;
    std::vector<std::pair<quint64, Eigen::Matrix4d>> m_measuredOthers; ///< of the job on its way
    QString m_message;
    int m_deliveries = 0;
};

} // namespace stylos::widgets
