#pragma once
/** @file
 * @brief "Fit drum guides" on one fragment in the background: its `.poct` read as one point per leaf
 *        (core::cloud::loadPointCloud), the guides of an intact drum fitted by the core's one entry point
 *        (core::dock::fitDrumGuides, as `stylos-cli guides`), and turned into the fragment's guides in its own
 *        frame: one Axis guide (the leading cylinder's axis, its point at the lower bed) and one Groove guide
 *        per flute (the flute's bottom line), named "Axis" and "Flute 1"… (translated).
 *
 * Use: `tasks.start<GuideFitResult>(job.label(), job)` or through FragmentJobs (GuideFitRunner): one result,
 * or none when cancelled; a failure (an unreadable file, not a drum, no flutes found) is a result whose error
 * is a translated message naming the file and the reason. Progress: reading to 0.3, the fit to 1.
 * Memory: 24 bytes a leaf, and the fit's (see DrumGuides.h). Thread-safety: the job is a value; run() and
 * operator() are reentrant and touch no widget and no document.
 */
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/scene/Fragment.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <QCoreApplication>
#include <QPromise>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace stylos::widgets {

/** @brief What the job hands back: the guides for the fragment, or an error message. */
struct GuideFitResult {
    quint64 fragmentId = 0;
    QString octreePath;
    std::vector<core::scene::Guide> guides; ///< Axis first, then the flutes in order; empty on failure
    int flutes = 0;
    double radius = 0.0;                    ///< leading radius, metres
    double fluteDepth = 0.0;                ///< metres
    double rms = 0.0;                       ///< metres
    double seconds = 0.0;                   ///< wall time of the whole job
    /** The fitted guides themselves, flute profile included (what docking needs); null on failure. */
    std::shared_ptr<const core::dock::DrumGuides> drum;
    /** Empty on success; a translated message naming the file and the reason otherwise. */
    QString error;

    bool ok() const { return error.isEmpty() && !guides.empty(); }
};

class GuideFitJob {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::GuideFitJob)

public:
    /** @param name shown in the label (the fragment's name); empty: the file name. */
    GuideFitJob(QString octreePath, quint64 fragmentId, core::dock::GuideOptions options = {}, QString name = {});

    /** @brief "Drum guides of NAME" (translated), the task's label. */
    QString label() const;

    /** @brief The task body: adds run()'s result, a failure as a result with error, nothing when cancelled. */
    void operator()(QPromise<GuideFitResult>& promise, core::ProgressSink& progress) const;
    /** @brief Runs on the calling thread. Errors: loadPointCloud's and fitDrumGuides' (InvalidArgument for a
     *         cloud that is no fluted drum), Cancelled. */
    core::Result<GuideFitResult> run(core::ProgressSink* progress = nullptr) const;

    /** @brief The fragment's guides for fitted drum guides (same frame): the axis, then one groove per flute. */
    static std::vector<core::scene::Guide> toGuides(const core::dock::DrumGuides& guides);
    /** @brief "Could not fit the guides of NAME: REASON.\nDETAIL" (translated). */
    static QString errorText(const QString& path, const core::Error& error);

private:
    QString m_path;
    quint64 m_fragmentId;
    core::dock::GuideOptions m_options;
    QString m_name;
};

} // namespace stylos::widgets
