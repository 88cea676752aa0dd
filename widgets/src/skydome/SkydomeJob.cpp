#include "stylos/widgets/skydome/SkydomeJob.h"

#include "stylos/core/ao/SkydomeLayer.h"
#include "tasks/ErrorText.h"
#include "tasks/JobResult.h"

#include <QFileInfo>

#include <algorithm>
#include <chrono>
#include <utility>

namespace stylos::widgets {

namespace {

using Clock = std::chrono::steady_clock;
namespace ao = core::ao;
namespace oct = core::octree;

} // namespace

core::ao::AoOptions SkydomeOptions::aoOptions() const
{
    core::ao::AoOptions options;
    options.directions = directions;
    options.method = method;
    options.threads = threads;
    return options;
}

SkydomeJob::SkydomeJob(QString octreePath, quint64 fragmentId, SkydomeOptions options, QString name)
    : m_path(std::move(octreePath)), m_fragmentId(fragmentId), m_options(options), m_name(std::move(name))
{
}

QString SkydomeJob::label() const
{
    return tr("Skydome of %1").arg(m_name.isEmpty() ? QFileInfo(m_path).fileName() : m_name);
}

QString SkydomeJob::errorText(const QString& path, const core::Error& error)
{
    return tr("Could not compute the skydome of %1: %2.").arg(QFileInfo(path).fileName(), ErrorText::reason(error.code)) +
           QLatin1Char('\n') + QString::fromStdString(error.message);
}

core::Result<SkydomeResult> SkydomeJob::run(core::ProgressSink* progress) const
{
    const auto start = Clock::now();
    const std::filesystem::path path = m_path.toStdString();
    SkydomeResult result;
    result.fragmentId = m_fragmentId;
    result.octreePath = m_path;
    result.directions = m_options.directions;

    // Reading: the octree (mapped, checksums verified) and the cells of the level.
    auto opened = oct::PackedOctree::open(path);
    if (!opened) return opened.error();
    const oct::PackedOctree& octree = *opened;
    core::ao::SkydomeLayerOptions layer;
    layer.ao = m_options.aoOptions();
    layer.level = m_options.level;
    {
        // In place and atomically: a cancel before the write (at 0.9) leaves the file as it was.
        auto made = ao::computeSkydomeLayer(octree, path, layer, progress);
        if (!made) return made.error();
        result.level = made->level;
        result.cells = made->cells;
        result.leaves = made->leaves;
    }

    // The updated file, for the document (the old mapping stays valid for whoever still holds it).
    auto reopened = oct::PackedOctree::open(path);
    if (!reopened) return reopened.error();
    result.octree = std::make_shared<const oct::PackedOctree>(std::move(reopened).value());
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (progress) progress->update(1.0);
    return result;
}

void SkydomeJob::operator()(QPromise<SkydomeResult>& promise, core::ProgressSink& progress) const
{
    deliverJobResult(promise, progress, [this](core::ProgressSink* sink) { return run(sink); },
                     [this](const core::Error& error) {
        SkydomeResult failed;
        failed.fragmentId = m_fragmentId;
        failed.octreePath = m_path;
        failed.directions = m_options.directions;
        failed.error = errorText(m_path, error);
        failed.errorCode = error.code;
        return failed;
    });
}

} // namespace stylos::widgets
