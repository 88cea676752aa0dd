#pragma once
/** @file
 * @brief The contact readout of one fragment in the background: its `.poct` read as one point per leaf (with the
 *        leaves' normals), then core::dock::measureContact against the drum's fitted guides at a pose (fragment
 *        file frame → drum file frame): the largest interpenetration and the gap distribution of its outer face;
 *        and, for each other fragment of its assembly given, core::dock::measureFragmentContact against its leaves.
 *        Use: through FragmentJobs (ContactMonitor): one result, or none when cancelled; a failure is a result
 *        whose error is a translated message. Thread-safety: the job is a value; run() is reentrant and touches
 *        no widget and no document.
 */
#include "stylos/core/dock/ContactReadout.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Geometry>

#include <QCoreApplication>
#include <QPromise>
#include <QString>

#include <memory>
#include <vector>

namespace stylos::widgets {

/** @brief The contact with another fragment of the assembly (core::dock::measureFragmentContact). */
struct MemberContact {
    quint64 id = 0;
    QString name;
    core::dock::ContactReadout readout;
    QString error; ///< empty on success (translated)
};

struct ContactJobResult {
    quint64 fragmentId = 0;
    quint64 drumId = 0;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity(); ///< the pose measured (fragment file → drum file)
    core::dock::ContactReadout readout;
    std::vector<MemberContact> members; ///< against the other fragments given (setOthers), in their order
    QString error; ///< empty on success

    bool ok() const { return error.isEmpty(); }
};

class ContactJob {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::ContactJob)

public:
    /** @param guides the drum's fitted guides, with a profile (not null). */
    ContactJob(QString octreePath, quint64 fragmentId, quint64 drumId,
               std::shared_ptr<const core::dock::DrumGuides> guides, const Eigen::Isometry3d& pose, QString name = {});

    /** @brief Another fragment of the assembly to measure against: its octree, id, name, and its file frame →
     *         this fragment's file frame. */
    struct Other {
        QString octreePath;
        quint64 id = 0;
        QString name;
        Eigen::Isometry3d toFragment = Eigen::Isometry3d::Identity();
    };
    /** @brief Also measures the contact with each of @p others (an unreadable one reports its error alone). */
    void setOthers(std::vector<Other> others) { m_others = std::move(others); }

    /** @brief "Contact of NAME with the drum" (translated), the task's label. */
    QString label() const;
    void operator()(QPromise<ContactJobResult>& promise, core::ProgressSink& progress) const;
    /** @brief Errors: loadPointCloud's and measureContact's, Cancelled. */
    core::Result<ContactJobResult> run(core::ProgressSink* progress = nullptr) const;

private:
    QString m_path;
    quint64 m_fragmentId, m_drumId;
    std::shared_ptr<const core::dock::DrumGuides> m_guides;
    Eigen::Isometry3d m_pose;
    QString m_name;
    std::vector<Other> m_others;
};

} // namespace stylos::widgets
