#include "stylos/widgets/developpee/DeveloppeeJob.h"

#include "stylos/core/util/Stopwatch.h"

#include "stylos/core/annotation/LabelRaster.h"
#include "stylos/core/image/ImageWriter.h"
#include "stylos/core/octree/PackedOctree.h"

#include "tasks/ErrorText.h"
#include "tasks/JobResult.h"

#include <QFileInfo>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace stylos::widgets {

namespace {

using core::Clock;
using core::secondsSince;

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
            const int grey = core::image::shadeToByte(shaded.value(column, row));
            line[column] = qRgba(grey, grey, grey, 255);
        }
    }
    return image;
}

core::Result<DeveloppeeResult> DeveloppeeJob::run(core::ProgressSink* progress) const
{
    const std::string source = m_path.toStdString();
    if (const QString problem = m_settings.problem(); !problem.isEmpty())
        return core::Error{core::ErrorCode::InvalidArgument, source + ": " + problem.toStdString()};
    DeveloppeeResult result;
    result.fragmentId = m_fragmentId;
    result.octreePath = m_path;
    result.settings = m_settings;

    auto made = core::developpee::computeDeveloppee(source, m_settings.options(), progress);
    if (!made) return made.error();
    if (progress && progress->isCancelRequested()) return cancelled(m_path);
    const auto imageStart = Clock::now();
    result.image = toImage(made->shaded);
    if (result.image.isNull() && made->shaded.width > 0)
        return core::Error{core::ErrorCode::OutOfBudget,
                           source + ": the image of " + std::to_string(made->shaded.width) + " x " +
                               std::to_string(made->shaded.height) + " pixels cannot be allocated"};
    result.fit = made->fit;
    result.unroll = made->unroll;
    result.timings = made->timings;
    result.heightNoise = made->heightNoise;
    result.smoothing = made->smoothing;
    const double imageSeconds = secondsSince(imageStart);
    result.timings.shading += imageSeconds;
    result.timings.total += imageSeconds;
    result.heights = std::make_shared<const core::shading::HeightField>(std::move(made->field));
    result.shaded = std::make_shared<const core::shading::ShadedImage>(std::move(made->shaded));
    result.map = std::move(made->map);
    if (QFileInfo(m_path).suffix().compare(QStringLiteral("poct"), Qt::CaseInsensitive) == 0) {
        // The pixel ↔ leaf index for painting: once per développée, here in the background. Painting labels the
        // surface the développée shows (core::annotation::paintDepth): not a fragment's inner break face.
        if (auto octree = core::octree::PackedOctree::open(source)) {
            auto pixels = core::annotation::leafPixels(*octree, *result.map, nullptr, core::annotation::paintDepth(result.map->pixelSize()));
            if (!pixels && pixels.error().code == core::ErrorCode::Cancelled) return pixels.error();
            if (pixels) {
                auto index = core::annotation::PixelLeafIndex::build(*pixels, result.map->width(), result.map->height());
                // Filled pixels and gaps of the leaves' grid show their nearest leaves' class, not unpainted specks.
                if (result.heights->states().size() == index.pixelCount()) index.lendLeaves(result.heights->states());
                result.leafIndex = std::make_shared<const core::annotation::PixelLeafIndex>(std::move(index));
            }
        }
    }
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
