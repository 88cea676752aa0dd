#pragma once
/** @file
 * @brief The 3D skydome (ambient occlusion) of one fragment, computed in the background and stored in its
 *        own `.poct` by the core's one entry point, core::ao::computeSkydomeLayer (as `stylos-cli ao
 *        FRAGMENT.poct -o FRAGMENT.poct` and the demo): the cells of one level (by default
 *        core::ao::closedSurfaceLevel), their skydome, spread to the leaves and written as the "ambient"
 *        layer in place (a temporary file beside it, renamed over it). The updated file is then opened again and handed
 *        back, for SceneDocument::replaceOctree(); the 3D view's Ambient shading reads that layer.
 *
 * Use: `tasks.start<SkydomeResult>(job.label(), job)` (TaskManager or TaskRunner): the job adds one result,
 * or none when cancelled; a failure is a result whose error is a translated message naming the file and
 * the reason. Progress: computeSkydomeLayer's (reading the cells to 0.1, the skydome to 0.9, writing to
 * 1), then the re-opening.
 * Cancel: checked while reading and computing and once more just before the write; the file is then
 * untouched. The write itself (a copy of the file, a fraction of a second) cannot be interrupted: a cancel
 * arriving during it comes too late for the file, which gets the layer, while the task still gives no result.
 * An octree already opened from that file by the document stays valid meanwhile: it maps the old file,
 * which the rename unlinks but does not free while mapped (POSIX).
 * Memory: 32 bytes a cell of the level, 4 bytes a leaf, and the layer (4 bytes a leaf) while writing.
 * Thread-safety: the job is a value; run() and operator() are reentrant and touch no widget. Two jobs on
 * the same file at once both succeed, the last rename wins (SkydomeRunner starts one per fragment).
 */
#include "stylos/core/ao/AmbientOcclusion.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <QCoreApplication>
#include <QPromise>
#include <QString>

#include <memory>
#include <optional>

namespace stylos::widgets {

/** @brief The workbench's choices for the skydome (the CLI's, with fewer directions for speed). */
struct SkydomeOptions {
    int directions = 128;                                 ///< 1..65536, over the whole sphere
    std::optional<int> level;                             ///< octree level; none: core::ao::closedSurfaceLevel
    core::ao::AoMethod method = core::ao::AoMethod::DepthMap;
    unsigned threads = 0;                                 ///< 0: hardware concurrency

    /** @brief The core options these stand for (bias, weighting: the core's defaults). */
    core::ao::AoOptions aoOptions() const;
};

/** @brief What the job hands back: the re-opened octree with its "ambient" layer, or an error message. */
struct SkydomeResult {
    quint64 fragmentId = 0;
    QString octreePath;
    /** The updated file, opened again; null on failure. */
    std::shared_ptr<const core::octree::PackedOctree> octree;
    int level = 0;            ///< the level whose cells were shaded
    int directions = 0;
    quint64 cells = 0;        ///< cells at that level
    quint64 leaves = 0;       ///< values in the layer
    double seconds = 0.0;     ///< wall time of the whole job
    /** Empty on success; a translated message naming the file and the reason otherwise. */
    QString error;
    std::optional<core::ErrorCode> errorCode;

    bool ok() const { return error.isEmpty() && octree != nullptr; }
};

class SkydomeJob {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::SkydomeJob)

public:
    /**
     * @param octreePath the fragment's `.poct`, updated in place
     * @param name shown in the label (the fragment's name); empty: the file name
     */
    SkydomeJob(QString octreePath, quint64 fragmentId, SkydomeOptions options = {}, QString name = {});

    /** @brief "Skydome of NAME" (translated), the task's label. */
    QString label() const;
    const QString& octreePath() const { return m_path; }
    quint64 fragmentId() const { return m_fragmentId; }

    /** @brief The task body: adds run()'s result, a failure as a result with error, nothing when cancelled. */
    void operator()(QPromise<SkydomeResult>& promise, core::ProgressSink& progress) const;

    /**
     * @brief Runs the whole chain on the calling thread. Errors: the core's (NotFound, Unreadable, Truncated,
     *        Malformed, UnknownFormat… of opening the file; InvalidArgument for a level outside 0..depth or
     *        directions outside 1..65536; WriteFailed), Cancelled when @p progress asks for it before the write.
     */
    core::Result<SkydomeResult> run(core::ProgressSink* progress = nullptr) const;

    /** @brief "Could not compute the skydome of NAME: REASON.\nDETAIL" (translated). */
    static QString errorText(const QString& path, const core::Error& error);

private:
    QString m_path;
    quint64 m_fragmentId;
    SkydomeOptions m_options;
    QString m_name;
};

} // namespace stylos::widgets
