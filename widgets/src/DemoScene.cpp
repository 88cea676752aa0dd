#include "stylos/widgets/DemoScene.h"

#include "stylos/widgets/ErrorText.h"
#include "stylos/widgets/TaskRunner.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTimer>

#include <optional>

namespace stylos::widgets {

namespace {

/** A step's outcome: nothing on success, the error otherwise. */
using StepError = std::optional<core::Error>;

/** Maps one item's progress onto its share [from, to] of the whole generation. */
class StepProgress final : public core::ProgressSink {
public:
    StepProgress(core::ProgressSink& parent, double from, double to) : m_parent(parent), m_from(from), m_to(to) {}
    void update(double fraction) override { m_parent.update(m_from + (m_to - m_from) * fraction); }
    bool isCancelRequested() const override { return m_parent.isCancelRequested(); }

private:
    core::ProgressSink& m_parent;
    double m_from;
    double m_to;
};

} // namespace

DemoScene::DemoScene(TaskRunner& runner, const QString& directory, QObject* parent)
    : QObject(parent), m_runner(runner), m_directory(directory.isEmpty() ? defaultDirectory() : directory)
{
}

QString DemoScene::defaultDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/demo");
}

std::vector<DemoScene::Item> DemoScene::items()
{
    using core::synth::SyntheticKind;
    return {{QStringLiteral("drum.ply"), SyntheticKind::Drum, 1},
            {QStringLiteral("fragment-a.ply"), SyntheticKind::Fragment, 2},
            {QStringLiteral("fragment-b.ply"), SyntheticKind::Fragment, 3},
            {QStringLiteral("omphalos.ply"), SyntheticKind::Omphalos, 4}};
}

QStringList DemoScene::paths() const
{
    QStringList result;
    for (const Item& item : items()) result << QDir(m_directory).filePath(item.fileName);
    return result;
}

bool DemoScene::isGenerated() const
{
    for (const QString& path : paths())
        if (!QFileInfo(path).isFile()) return false;
    return true;
}

bool DemoScene::prepare()
{
    if (m_runner.isBusy()) return false;
    if (isGenerated()) {
        // Queued, so callers see the same asynchronous contract whether or not the files exist.
        QTimer::singleShot(0, this, [this] { Q_EMIT ready(paths()); });
        return true;
    }
    if (!QDir().mkpath(m_directory)) {
        QTimer::singleShot(0, this, [this] {
            Q_EMIT failed(tr("Could not create the demo folder %1.").arg(QDir::toNativeSeparators(m_directory)));
        });
        return true;
    }

    std::vector<std::pair<std::filesystem::path, Item>> todo;
    for (const Item& item : items()) {
        const QString path = QDir(m_directory).filePath(item.fileName);
        if (!QFileInfo(path).isFile()) todo.emplace_back(path.toStdString(), item);
    }
    auto* watcher = m_runner.start<StepError>(
        tr("Generating the demo scene"), [todo](QPromise<StepError>& promise, core::ProgressSink& progress) {
            const double n = static_cast<double>(todo.size());
            for (std::size_t i = 0; i < todo.size(); ++i) {
                core::synth::SyntheticOptions options;
                options.spacing = Spacing;
                options.seed = todo[i].second.seed;
                StepProgress step(progress, double(i) / n, double(i + 1) / n);
                auto report = core::synth::generateScan(todo[i].second.kind, options, todo[i].first, &step);
                if (!report) {
                    promise.addResult(StepError(report.error()));
                    return;
                }
            }
            promise.addResult(StepError());
        });
    if (!watcher) return false;
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] {
        if (watcher->isCanceled() || watcher->future().resultCount() == 0) {
            Q_EMIT cancelled();
            return;
        }
        const StepError error = watcher->result();
        if (!error) Q_EMIT ready(paths());
        else if (error->code == core::ErrorCode::Cancelled) Q_EMIT cancelled();
        else
            Q_EMIT failed(tr("Could not generate the demo scene: %1.").arg(ErrorText::reason(error->code)) +
                          QLatin1Char('\n') + QString::fromStdString(error->message));
    });
    return true;
}

} // namespace stylos::widgets
