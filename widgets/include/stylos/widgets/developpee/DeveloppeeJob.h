#pragma once
/** @file
 * @brief The développée of one fragment, computed in the background by the core's one entry point
 *        (core::developpee::computeDeveloppee, as `stylos-cli unroll`: the same settings give the same
 *        pixels) and turned into a grey + alpha QImage, without writing any file.
 *
 * Use: `tasks.start<DeveloppeeResult>(job.label(), job)` (TaskManager): the job adds one
 * result, or none when cancelled; a failure is a result whose error() is a translated message naming the
 * file and the reason. Progress: reading to 0.15, fitting to 0.4, unrolling to 0.7, shading to 1.
 * Memory: the cloud (24 bytes a leaf with normals) until the unroll is done, then the field (5 bytes a
 * pixel), the shading (5 bytes a pixel), the image (4 bytes a pixel) and, for a `.poct`, the pixel ↔ leaf
 * index of the annotation painting (8 bytes a leaf, 4 a pixel; core::annotation::PixelLeafIndex).
 * Thread-safety: the job is a value; run() and operator() are reentrant and touch no widget.
 * Everything in the result is in the octree's frame (the fragment's own), metres.
 */
#include "stylos/core/annotation/AssemblyLeafIndex.h"
#include "stylos/core/annotation/PixelLeafIndex.h"
#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/shading/ShadedImage.h"
#include "stylos/core/unroll/SurfaceFit.h"
#include "stylos/core/unroll/UnrollMap.h"
#include "stylos/core/unroll/Unroller.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"
#include "stylos/widgets/developpee/DeveloppeeSettings.h"

#include <QCoreApplication>
#include <QImage>
#include <QPromise>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace stylos::widgets {

/** @brief Wall time of each step, seconds (the core's; shading includes the QImage). */
using DeveloppeeTimings = core::developpee::DeveloppeeTimings;

/** @brief What the job hands back: a développée, or an error message. Cheap to copy (shared data). */
struct DeveloppeeResult {
    quint64 fragmentId = 0;
    QString octreePath;
    DeveloppeeSettings settings;
    /** Format_ARGB32_Premultiplied: grey where the field has a height, transparent (0) where it is Empty;
     *  row 0 at the top, as the UnrollMap. */
    QImage image;
    /** The unrolled heights (metres) and states, same size as the image; null on failure. */
    std::shared_ptr<const core::shading::HeightField> heights;
    /** The shading at full precision ([0, 1] floats, e.g. for a 16-bit plate); null on failure. */
    std::shared_ptr<const core::shading::ShadedImage> shaded;
    std::optional<core::unroll::UnrollMap> map; ///< pixel ↔ 3D (octree frame); empty on failure
    core::unroll::FitReport fit;
    core::unroll::UnrollReport unroll;
    /** An assembly's développée (AssemblyDeveloppeeJob): the fragment each pixel shows (row-major, the image's
     *  size; 0 for the drum or none); null for one fragment's. */
    std::shared_ptr<const std::vector<std::uint64_t>> pieceAt;
    /** The pixel ↔ leaf index of the fragment's octree on this développée's grid (annotation painting and its
     *  overlay); null when the source is not a `.poct` or for an assembly's développée. */
    std::shared_ptr<const core::annotation::PixelLeafIndex> leafIndex;
    /** An assembly's développée: the pixel ↔ leaf index of each piece (the drum as id 0, each fragment by its id, as
     *  in pieceAt) with the pose and octree each was indexed with; null for one fragment's or without octrees. */
    std::shared_ptr<const core::annotation::AssemblyLeafIndex> assemblyIndex;
    DeveloppeeTimings timings;
    double heightNoise = 0.0;     ///< skydome: σ of the height noise measured, metres
    double smoothing = 0.0;       ///< skydome: the Gaussian σ the heights were smoothed with, metres (0: raw)
    /** Empty on success; a translated message naming the file and the reason otherwise. */
    QString error;
    std::optional<core::ErrorCode> errorCode;

    bool ok() const { return error.isEmpty() && map.has_value(); }
};

class DeveloppeeJob {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::DeveloppeeJob)

public:
    /** @param octreePath the fragment's `.poct` (any point file works too) */
    DeveloppeeJob(QString octreePath, quint64 fragmentId, DeveloppeeSettings settings);

    /** @brief "Développée of NAME" (translated), the task's label. */
    QString label() const;

    /** @brief The task body: adds run()'s result, a failure as a result with error(), nothing when cancelled. */
    void operator()(QPromise<DeveloppeeResult>& promise, core::ProgressSink& progress) const;

    /**
     * @brief Runs the whole chain on the calling thread. Errors: the core's (NotFound, Unreadable, Malformed,
     *        Truncated, Empty, OutOfBudget; InvalidArgument when the surface does not fit or the settings are
     *        out of range), Cancelled when @p progress asks for it.
     */
    core::Result<DeveloppeeResult> run(core::ProgressSink* progress = nullptr) const;

    /** @brief "Could not compute the développée of NAME: REASON.\nDETAIL" (translated). */
    static QString errorText(const QString& path, const core::Error& error);
    /** @brief Grey (value · 255, rounded) with alpha = coverage, premultiplied; a null image for a 0-pixel one. */
    static QImage toImage(const core::shading::ShadedImage& shaded);

private:
    QString m_path;
    quint64 m_fragmentId;
    DeveloppeeSettings m_settings;
};

} // namespace stylos::widgets
