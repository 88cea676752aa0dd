#pragma once
/** @file
 * @brief The développée of an assembly in the background: the drum's and its docked fragments' octrees read
 *        as one point per leaf, the fragments carried into the drum's frame by where they stand in the scene,
 *        and core::developpee::computeAssemblyDeveloppee about the drum's axis guide. The result is the
 *        drum's DeveloppeeResult (its octree's frame; fragmentId the drum) with pieceAt saying which fragment
 *        each pixel shows, and assemblyIndex: the leaves of the drum and of each fragment at the pixels each shows
 *        (core::annotation::AssemblyLeafIndex, made here in the background; painting goes through it). Memory of
 *        the index: about 8 bytes a leaf. Thread-safety: the job is a value; run() is reentrant and touches no widget.
 */
#include "stylos/widgets/developpee/DeveloppeeJob.h"

#include <Eigen/Geometry>

#include <vector>

namespace stylos::widgets {

class AssemblyDeveloppeeJob {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::AssemblyDeveloppeeJob)

public:
    /** @brief A fragment of the assembly: its octree and where it stands in the drum's frame. */
    struct Piece {
        QString octreePath;
        Eigen::Isometry3d toDrum = Eigen::Isometry3d::Identity();
        quint64 fragmentId = 0;
    };

    /** @p axis: the drum's axis guide, in its octree's frame. */
    AssemblyDeveloppeeJob(QString drumPath, quint64 drumId, core::unroll::Axis axis, std::vector<Piece> pieces,
                          DeveloppeeSettings settings, QString assemblyName);

    /** @brief "Développée of NAME" (the assembly's name, translated), the task's label. */
    QString label() const;
    void operator()(QPromise<DeveloppeeResult>& promise, core::ProgressSink& progress) const;
    /** @brief Runs on the calling thread. Errors: the core's, naming the file. */
    core::Result<DeveloppeeResult> run(core::ProgressSink* progress = nullptr) const;

private:
    /** The pixel ↔ leaf index of the drum and every piece on @p map (the développée's), each piece lending its
     *  leaves to its pixels with a height in @p states but no leaf; Unsupported for a source that is not a `.poct`,
     *  the octree's errors, Cancelled. */
    core::Result<core::annotation::AssemblyLeafIndex> leafIndex(const core::unroll::UnrollMap& map,
                                                                std::shared_ptr<const std::vector<std::uint64_t>> pieceAt,
                                                                std::span<const core::shading::PixelState> states,
                                                                core::ProgressSink* progress) const;

    QString m_drumPath;
    quint64 m_drumId;
    core::unroll::Axis m_axis;
    std::vector<Piece> m_pieces;
    DeveloppeeSettings m_settings;
    QString m_name;
};

} // namespace stylos::widgets
