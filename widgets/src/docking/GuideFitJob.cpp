#include "stylos/widgets/docking/GuideFitJob.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/util/SubProgress.h"
#include "tasks/ErrorText.h"
#include "tasks/JobResult.h"

#include <QFileInfo>

#include <chrono>
#include <utility>

namespace stylos::widgets {

GuideFitJob::GuideFitJob(QString octreePath, quint64 fragmentId, core::dock::GuideOptions options, QString name)
    : m_path(std::move(octreePath)), m_fragmentId(fragmentId), m_options(std::move(options)), m_name(std::move(name))
{
}

QString GuideFitJob::label() const
{
    return tr("Drum guides of %1").arg(m_name.isEmpty() ? QFileInfo(m_path).fileName() : m_name);
}

QString GuideFitJob::errorText(const QString& path, const core::Error& error)
{
    return tr("Could not fit the guides of %1: %2.").arg(QFileInfo(path).fileName(), ErrorText::reason(error.code)) +
           QLatin1Char('\n') + QString::fromStdString(error.message);
}

std::vector<core::scene::Guide> GuideFitJob::toGuides(const core::dock::DrumGuides& fitted)
{
    using core::scene::Guide;
    using core::scene::GuideKind;
    std::vector<Guide> guides;
    guides.reserve(fitted.fluteLines.size() + 1);
    guides.push_back({tr("Axis").toStdString(), GuideKind::Axis, core::scene::toArray(fitted.axis.point),
                      core::scene::toArray(fitted.axis.direction.normalized())});
    for (std::size_t k = 0; k < fitted.fluteLines.size(); ++k) {
        const core::dock::FluteLine& line = fitted.fluteLines[k];
        guides.push_back({tr("Flute %1").arg(k + 1).toStdString(), GuideKind::Groove, core::scene::toArray(line.point),
                          core::scene::toArray(line.direction.normalized())});
    }
    return guides;
}

core::Result<GuideFitResult> GuideFitJob::run(core::ProgressSink* progress) const
{
    const auto start = std::chrono::steady_clock::now();
    core::SubProgress reading(progress, 0.0, 0.3);
    core::cloud::CloudLoadOptions load;
    load.keepNormals = true; // one point per leaf, with its normal
    auto cloud = core::cloud::loadPointCloud(m_path.toStdString(), load, &reading);
    if (!cloud) return cloud.error();
    cloud->source = m_path.toStdString();
    core::SubProgress fitting(progress, 0.3, 1.0);
    auto fitted = core::dock::fitDrumGuides(*cloud, m_options, &fitting);
    if (!fitted) return fitted.error();
    GuideFitResult result;
    result.fragmentId = m_fragmentId;
    result.octreePath = m_path;
    result.guides = toGuides(*fitted);
    result.flutes = fitted->flutes;
    result.radius = fitted->radius;
    result.fluteDepth = fitted->fluteDepth;
    result.rms = fitted->rms;
    result.drum = std::make_shared<const core::dock::DrumGuides>(*fitted);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (progress) progress->update(1.0);
    return result;
}

void GuideFitJob::operator()(QPromise<GuideFitResult>& promise, core::ProgressSink& progress) const
{
    deliverJobResult(promise, progress, [this](core::ProgressSink* sink) { return run(sink); },
                     [this](const core::Error& error) {
        GuideFitResult failed;
        failed.fragmentId = m_fragmentId;
        failed.octreePath = m_path;
        failed.error = errorText(m_name.isEmpty() ? m_path : m_name, error);
        return failed;
    });
}

} // namespace stylos::widgets
