#include "stylos/widgets/DeveloppeeJob.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/shading/ContrastStretch.h"
#include "stylos/core/shading/HeightShading.h"
#include "stylos/core/shading/LightShading.h"
#include "stylos/core/shading/SkydomeShading.h"
#include "stylos/widgets/ErrorText.h"
#include "stylos/widgets/JobResult.h"
#include "stylos/core/util/SubProgress.h"

#include <QFileInfo>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace stylos::widgets {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

core::Error cancelled(const QString& path)
{
    return core::Error{core::ErrorCode::Cancelled, path.toStdString() + ": cancelled"};
}

} // namespace

DeveloppeeJob::DeveloppeeJob(QString octreePath, quint64 fragmentId, DeveloppeeSettings settings)
    : m_path(std::move(octreePath)), m_fragmentId(fragmentId), m_settings(std::move(settings))
{
}

QString DeveloppeeJob::label() const { return tr("Développée of %1").arg(QFileInfo(m_path).fileName()); }

QString DeveloppeeJob::errorText(const QString& path, const core::Error& error)
{
    return tr("Could not compute the développée of %1: %2.").arg(QFileInfo(path).fileName(), ErrorText::reason(error.code)) +
           QLatin1Char('\n') + QString::fromStdString(error.message);
}

QImage DeveloppeeJob::toImage(const core::shading::ShadedImage& shaded)
{
    if (shaded.width <= 0 || shaded.height <= 0) return {};
    QImage image(shaded.width, shaded.height, QImage::Format_ARGB32_Premultiplied);
    if (image.isNull()) return {}; // could not allocate
    for (int row = 0; row < shaded.height; ++row) {
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(row));
        for (int column = 0; column < shaded.width; ++column) {
            if (!shaded.covered(column, row)) {
                line[column] = 0;
                continue;
            }
            const int grey = static_cast<int>(std::lround(std::clamp(shaded.value(column, row), 0.0f, 1.0f) * 255.0f));
            line[column] = qRgba(grey, grey, grey, 255);
        }
    }
    return image;
}

core::Result<core::shading::ShadedImage> DeveloppeeJob::shade(const core::shading::HeightField& field,
                                                              const DeveloppeeSettings& settings,
                                                              core::ProgressSink* progress)
{
    switch (settings.shading) {
    case DeveloppeeShading::Height: return core::shading::shadeHeight(field);
    case DeveloppeeShading::Light: return core::shading::shadeLight(field, settings.light);
    case DeveloppeeShading::Skydome: break;
    }
    core::shading::SkydomeOptions options;
    options.directions = settings.directions;
    auto sky = core::shading::shadeSkydome(field, options, progress);
    if (sky && settings.stretch) {
        if (auto range = core::shading::stretchContrast(*sky); !range) return range.error();
    }
    return sky;
}

core::Result<DeveloppeeResult> DeveloppeeJob::run(core::ProgressSink* progress) const
{
    const auto start = Clock::now();
    const std::string source = m_path.toStdString();
    if (const QString problem = m_settings.problem(); !problem.isEmpty())
        return core::Error{core::ErrorCode::InvalidArgument, source + ": " + problem.toStdString()};
    DeveloppeeResult result;
    result.fragmentId = m_fragmentId;
    result.octreePath = m_path;
    result.settings = m_settings;

    core::cloud::PointCloud cloud;
    {
        core::SubProgress step(progress, 0.0, 0.15);
        auto loaded = core::cloud::loadPointCloud(source, {}, &step);
        if (!loaded) return loaded.error();
        cloud = std::move(loaded).value();
    }
    result.timings.load = secondsSince(start);

    core::unroll::FitOptions fitOptions;
    fitOptions.kind = m_settings.surface;
    if (m_settings.axis) {
        core::unroll::Axis axis = *m_settings.axis;
        axis.direction.normalize();
        fitOptions.axis = axis;
    }
    core::SubProgress fitStep(progress, 0.15, 0.4);
    auto fit = core::unroll::fitSurface(cloud, fitOptions, &fitStep);
    if (!fit) return fit.error();
    result.fit = *fit;
    result.timings.fit = fit->seconds;

    core::unroll::UnrollOptions unrollOptions;
    if (m_settings.pixelSize > 0.0) unrollOptions.pixelSize = m_settings.pixelSize;
    // Automatic on a .poct: its points are leaf centres, whose heights step by the leaf edge; at one edge
    // per pixel the shading reads those steps as relief (salt and pepper), at three the carving shows.
    else if (cloud.spacing > 0.0) unrollOptions.pixelSize = PoctPixelEdges * cloud.spacing;
    core::SubProgress unrollStep(progress, 0.4, 0.7);
    auto unrolled = core::unroll::unrollCloud(cloud, fit->surface, unrollOptions, &unrollStep);
    if (!unrolled) return unrolled.error();
    cloud = {}; // the points are no longer needed: give the memory back before shading
    result.unroll = unrolled->report;
    result.timings.unroll = unrolled->report.seconds;

    const auto shadingStart = Clock::now();
    core::SubProgress shadeStep(progress, 0.7, 0.98);
    auto shaded = shade(unrolled->field, m_settings, &shadeStep);
    if (!shaded) return shaded.error();
    if (progress && progress->isCancelRequested()) return cancelled(m_path);
    result.image = toImage(*shaded);
    if (result.image.isNull() && shaded->width > 0)
        return core::Error{core::ErrorCode::OutOfBudget,
                           source + ": the image of " + std::to_string(shaded->width) + " x " +
                               std::to_string(shaded->height) + " pixels cannot be allocated"};
    result.timings.shading = secondsSince(shadingStart);
    result.heights = std::make_shared<const core::shading::HeightField>(std::move(unrolled->field));
    result.map = std::move(unrolled->map);
    result.timings.total = secondsSince(start);
    if (progress) progress->update(1.0);
    return result;
}

void DeveloppeeJob::operator()(QPromise<DeveloppeeResult>& promise, core::ProgressSink& progress) const
{
    deliverJobResult(promise, progress, [this](core::ProgressSink* sink) { return run(sink); },
                     [this](const core::Error& error) {
        DeveloppeeResult failed;
        failed.fragmentId = m_fragmentId;
        failed.octreePath = m_path;
        failed.settings = m_settings;
        failed.error = errorText(m_path, error);
        failed.errorCode = error.code;
        return failed;
    });
}

} // namespace stylos::widgets
