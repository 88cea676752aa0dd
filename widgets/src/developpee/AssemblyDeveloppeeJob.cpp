#include "stylos/widgets/developpee/AssemblyDeveloppeeJob.h"

#include "stylos/core/annotation/LabelRaster.h"
#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/developpee/AssemblyDeveloppee.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/SubProgress.h"

#include "tasks/JobResult.h"

#include <QFileInfo>

#include <utility>

namespace stylos::widgets {

AssemblyDeveloppeeJob::AssemblyDeveloppeeJob(QString drumPath, quint64 drumId, core::unroll::Axis axis,
                                             std::vector<Piece> pieces, DeveloppeeSettings settings, QString assemblyName)
    : m_drumPath(std::move(drumPath)), m_drumId(drumId), m_axis(std::move(axis)), m_pieces(std::move(pieces)),
      m_settings(std::move(settings)), m_name(std::move(assemblyName))
{
}

QString AssemblyDeveloppeeJob::label() const { return tr("Développée of %1").arg(m_name); }

core::Result<DeveloppeeResult> AssemblyDeveloppeeJob::run(core::ProgressSink* progress) const
{
    const std::string source = m_drumPath.toStdString();
    if (const QString problem = m_settings.problem(); !problem.isEmpty())
        return core::Error{core::ErrorCode::InvalidArgument, source + ": " + problem.toStdString()};
    core::SubProgress reading(progress, 0.0, 0.2);
    auto drum = core::cloud::loadPointCloud(source, {}, &reading);
    if (!drum) return drum.error();
    drum->source = source;
    std::vector<core::cloud::PointCloud> clouds;
    clouds.reserve(m_pieces.size());
    for (const Piece& p : m_pieces) {
        auto cloud = core::cloud::loadPointCloud(p.octreePath.toStdString());
        if (!cloud) return cloud.error();
        clouds.push_back(std::move(cloud).value());
    }
    std::vector<core::developpee::AssemblyPiece> pieces;
    for (std::size_t k = 0; k < m_pieces.size(); ++k) pieces.push_back({&clouds[k], m_pieces[k].toDrum, m_pieces[k].fragmentId});
    core::developpee::DeveloppeeOptions options = m_settings.options();
    options.axis = m_axis;
    options.radius = m_settings.radius; // the drum guides' leading radius, when known
    if (m_settings.radius) options.radiusSlope = m_settings.radiusSlope; // and their taper
    core::SubProgress computing(progress, 0.2, 0.9);
    auto made = core::developpee::computeAssemblyDeveloppee(*drum, pieces, options, progress ? &computing : nullptr);
    if (!made) return made.error();
    DeveloppeeResult result;
    result.fragmentId = m_drumId;
    result.octreePath = m_drumPath;
    result.settings = m_settings;
    result.image = DeveloppeeJob::toImage(made->developpee.shaded);
    result.fit = made->developpee.fit;
    result.unroll = made->developpee.unroll;
    result.timings = made->developpee.timings;
    result.heightNoise = made->developpee.heightNoise;
    result.smoothing = made->developpee.smoothing;
    result.heights = std::make_shared<const core::shading::HeightField>(std::move(made->developpee.field));
    result.shaded = std::make_shared<const core::shading::ShadedImage>(std::move(made->developpee.shaded));
    result.map = std::move(made->developpee.map);
    auto pieceAt = std::make_shared<const std::vector<std::uint64_t>>(std::move(made->pieceAt));
    result.pieceAt = pieceAt;
    core::SubProgress indexing(progress, 0.9, 1.0);
    auto index = leafIndex(*result.map, std::move(pieceAt), result.heights->states(), progress ? &indexing : nullptr);
    if (!index && index.error().code == core::ErrorCode::Cancelled) return index.error();
    if (index) result.assemblyIndex = std::make_shared<const core::annotation::AssemblyLeafIndex>(std::move(index).value());
    if (progress) progress->update(1.0);
    return result;
}

core::Result<core::annotation::AssemblyLeafIndex>
AssemblyDeveloppeeJob::leafIndex(const core::unroll::UnrollMap& map, std::shared_ptr<const std::vector<std::uint64_t>> pieceAt,
                                 std::span<const core::shading::PixelState> states, core::ProgressSink* progress) const
{
    // The drum (id 0 in pieceAt) and each fragment: their leaves, posed into the drum's frame, on the shared map.
    std::vector<core::annotation::AssemblyLeafIndex::PieceLeaves> pieces;
    const std::size_t count = m_pieces.size() + 1;
    for (std::size_t k = 0; k < count; ++k) {
        const QString path = k == 0 ? m_drumPath : m_pieces[k - 1].octreePath;
        if (QFileInfo(path).suffix().compare(QStringLiteral("poct"), Qt::CaseInsensitive) != 0)
            return core::Error{core::ErrorCode::Unsupported, path.toStdString() + ": not an octree, no leaves to paint"};
        auto octree = core::octree::PackedOctree::open(path.toStdString());
        if (!octree) return octree.error();
        const Eigen::Isometry3d pose = k == 0 ? Eigen::Isometry3d::Identity() : m_pieces[k - 1].toDrum;
        core::SubProgress part(progress, double(k) / double(count), double(k + 1) / double(count));
        // The surface the développée shows (core::annotation::paintDepth), as on a fragment's own développée.
        auto pixels = core::annotation::posedLeafPixels(*octree, pose, map, progress ? &part : nullptr,
                                                        core::annotation::paintDepth(map.pixelSize()));
        if (!pixels) return pixels.error();
        pieces.push_back({k == 0 ? 0 : m_pieces[k - 1].fragmentId, std::move(pixels).value(), pose, path.toStdString()});
    }
    // Lending only where the field's states are the image's (they are: one field, one map).
    if (states.size() != std::size_t(map.width()) * std::size_t(map.height())) states = {};
    return core::annotation::AssemblyLeafIndex::build(map.width(), map.height(), std::move(pieceAt), std::move(pieces), states);
}

void AssemblyDeveloppeeJob::operator()(QPromise<DeveloppeeResult>& promise, core::ProgressSink& progress) const
{
    deliverJobResult(promise, progress, [this](core::ProgressSink* sink) { return run(sink); },
                     [this](const core::Error& error) {
        DeveloppeeResult failed;
        failed.fragmentId = m_drumId;
        failed.octreePath = m_drumPath;
        failed.settings = m_settings;
        failed.error = DeveloppeeJob::errorText(m_drumPath, error);
        failed.errorCode = error.code;
        return failed;
    });
}

} // namespace stylos::widgets
