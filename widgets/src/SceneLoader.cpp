#include "stylos/widgets/SceneLoader.h"

#include "stylos/core/io/PointFileSummary.h"
#include "stylos/widgets/ErrorText.h"
#include "stylos/widgets/TaskRunner.h"

#include <QFileInfo>

namespace stylos::widgets {

namespace {

/** Maps a file's own progress onto its share [from, to] of the whole load. */
class RangeProgress final : public core::ProgressSink {
public:
    RangeProgress(core::ProgressSink* parent, double from, double to) : m_parent(parent), m_from(from), m_to(to) {}
    void update(double fraction) override
    {
        if (m_parent) m_parent->update(m_from + (m_to - m_from) * fraction);
    }
    bool isCancelRequested() const override { return m_parent && m_parent->isCancelRequested(); }

private:
    core::ProgressSink* m_parent;
    double m_from;
    double m_to;
};

} // namespace

SceneLoader::SceneLoader(TaskRunner& runner, QObject* parent) : QObject(parent), m_runner(runner) {}

core::Result<ScanSummary> SceneLoader::scanFile(const std::filesystem::path& path, core::ProgressSink* progress,
                                                double from, double to)
{
    RangeProgress sink(progress, from, to);
    auto scanned = core::io::summarizePointFile(path, {}, &sink);
    if (!scanned) return scanned.error();

    ScanSummary summary;
    summary.path = QString::fromStdString(path.string());
    summary.format = QString::fromStdString(scanned->format);
    summary.points = scanned->points;
    summary.skipped = scanned->skipped;
    if (scanned->min && scanned->max) {
        const auto& lo = *scanned->min;
        const auto& hi = *scanned->max;
        summary.bounds = {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]};
    }
    for (const std::string& name : scanned->attributes) summary.attributes << QString::fromStdString(name);
    return summary;
}

bool SceneLoader::load(const QStringList& paths)
{
    if (paths.isEmpty()) return false;
    std::vector<std::filesystem::path> files;
    for (const QString& p : paths) files.emplace_back(QFileInfo(p).absoluteFilePath().toStdString());

    auto* watcher = m_runner.start<FileResult>(
        tr("Loading %n file(s)", nullptr, static_cast<int>(paths.size())),
        [files](QPromise<FileResult>& promise, core::ProgressSink& progress) {
            const double n = static_cast<double>(files.size());
            for (std::size_t i = 0; i < files.size(); ++i) {
                auto scanned = scanFile(files[i], &progress, double(i) / n, double(i + 1) / n);
                if (!scanned && scanned.error().code == core::ErrorCode::Cancelled) return;
                FileResult result;
                if (scanned) {
                    result.summary = std::move(*scanned);
                } else {
                    result.summary.path = QString::fromStdString(files[i].string());
                    result.error = scanned.error();
                }
                promise.addResult(std::move(result));
                if (progress.isCancelRequested()) return;
            }
        });
    if (!watcher) return false;

    m_loaded = 0;
    m_failed = 0;
    connect(watcher, &QFutureWatcherBase::resultReadyAt, this, [this, watcher](int index) {
        deliver(watcher->resultAt(index));
    });
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] {
        Q_EMIT finished(m_loaded, m_failed, watcher->isCanceled());
    });
    return true;
}

void SceneLoader::deliver(const FileResult& result)
{
    if (result.error) {
        ++m_failed;
        Q_EMIT fileFailed(result.summary.path, ErrorText::loadFailure(result.summary.path, *result.error));
    } else {
        ++m_loaded;
        Q_EMIT fileLoaded(result.summary);
    }
}

} // namespace stylos::widgets
