#pragma once
/** @file
 * @brief "Dock to flutes" on one fragment in the background: its `.poct` read as one point per leaf (with the
 *        leaves' normals), then docked against the drum's fitted guides (DrumGuidesCache) by the core's one entry
 *        point, core::dock::dockFragment, as `stylos-cli dock`: from the start pose (fragment file frame → drum file
 *        frame) to the docked pose in the same frames, with the RMS, the flute shift, the unobservable unknowns and
 *        the uncertainty of the free ones.
 *
 * Use: through FragmentJobs (DockRunner): one result, or none when cancelled; a failure (an unreadable file, no
 * readable flutes on the fragment, a start too far from the drum, no convergence) is a result whose error is a
 * translated message naming the fragment and the reason. Progress: reading to 0.2, docking to 1.
 * Thread-safety: the job is a value (the guides are shared, immutable); run() and operator() are reentrant and
 * touch no widget and no document.
 */
#include "stylos/core/dock/DockRegistration.h"
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Geometry>

#include <QCoreApplication>
#include <QPromise>
#include <QLocale>
#include <QString>

#include <memory>

namespace stylos::widgets {

/** @brief What the job hands back: the docked pose and how well it is fixed, or an error message. */
struct DockJobResult {
    quint64 fragmentId = 0;
    quint64 drumId = 0;
    Eigen::Isometry3d start = Eigen::Isometry3d::Identity(); ///< fragment file frame → drum file frame, as given
    core::dock::DockResult dock;                             ///< dock.pose: the docked pose, same frames
    double seconds = 0.0;                                    ///< wall time of the whole job
    double drumRms = 0.0; ///< the drum's own RMS against its flute profile (the guides'), metres; 0: unknown
    /** Empty on success; a translated message naming the fragment and the reason otherwise. */
    QString error;

    bool ok() const { return error.isEmpty(); }
};

class DockJob {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::DockJob)

public:
    /** @param guides the drum's fitted guides, with a profile (not null). @param name shown in the label and the
     *         messages (the fragment's name); empty: the file name. */
    DockJob(QString octreePath, quint64 fragmentId, quint64 drumId, std::shared_ptr<const core::dock::DrumGuides> guides,
            const Eigen::Isometry3d& start, core::dock::DockOptions options, QString name = {});

    /** @brief "Dock NAME to the flutes" (translated), the task's label. */
    QString label() const;

    /** @brief The task body: adds run()'s result, a failure as a result with error, nothing when cancelled. */
    void operator()(QPromise<DockJobResult>& promise, core::ProgressSink& progress) const;
    /** @brief Runs on the calling thread. Errors: loadPointCloud's and dockFragment's, Cancelled; @p failure, when
     *         given, receives dockFragment's reason as values. */
    core::Result<DockJobResult> run(core::ProgressSink* progress = nullptr, core::dock::DockFailure* failure = nullptr) const;

    /** @brief Why the dock failed and what to do, in the user's language, for the reasons @p failure names (too far
     *         from the drum, no readable flutes…); otherwise "Could not dock NAME: REASON.\nDETAIL" (translated).
     *         Numbers in @p locale: the task passes the one of the GUI thread when the job was made (QLocale's
     *         default is not to be read on a worker while a language switch sets it). */
    static QString errorText(const QString& name, const core::Error& error, const core::dock::DockFailure& failure = {},
                             const QLocale& locale = QLocale());
    /** @brief One line for the log: RMS, points, flute shift, the uncertainty of each free unknown (degrees,
     *         millimetres) and what the flutes do not fix (translated). */
    static QString summary(const QString& name, const DockJobResult& result);

private:
    QString m_path;
    quint64 m_fragmentId, m_drumId;
    std::shared_ptr<const core::dock::DrumGuides> m_guides;
    Eigen::Isometry3d m_start;
    core::dock::DockOptions m_options;
    QString m_name;
    QLocale m_locale; ///< the GUI thread's when the job was made, for the error's numbers
};

} // namespace stylos::widgets
