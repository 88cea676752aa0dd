#include "stylos/widgets/document/DemoScene.h"

#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/synth/DemoProject.h"
#include "tasks/ErrorText.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTimer>

#include <optional>

namespace stylos::widgets {

namespace {

using core::synth::SyntheticKind;

/** What the generation task hands back; nothing at all when it was cancelled. */
struct Outcome {
    std::optional<core::Error> error;
    QString file; ///< the file being made when it failed
};

/** The whole generation (core::synth::generateDemoProject), on a worker thread. Adds nothing to
 *  @p promise when cancelled. */
void generate(const core::synth::DemoRequest& request, QPromise<Outcome>& promise, core::ProgressSink& progress)
{
    const auto failure = core::synth::generateDemoProject(request, progress);
    if (!failure) {
        promise.addResult(Outcome{});
        return;
    }
    if (failure->error.code != core::ErrorCode::Cancelled)
        promise.addResult(Outcome{failure->error, QString::fromStdString(failure->file)});
}

/** What the old, PLY-only demo left in the folder. */
QStringList legacyFiles()
{
    QStringList names;
    for (const char* stem : {"drum", "fragment-a", "fragment-b", "omphalos"})
        names << QStringLiteral("%1.ply").arg(QLatin1String(stem))
              << QStringLiteral("%1.truth.json").arg(QLatin1String(stem));
    return names;
}

} // namespace

DemoScene::DemoScene(TaskManager& tasks, const QString& directory, QObject* parent)
    : QObject(parent), m_tasks(tasks), m_directory(directory.isEmpty() ? defaultDirectory() : directory)
{
}

DemoScene::~DemoScene()
{
    cancel();
}

QString DemoScene::defaultDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/demo");
}

std::vector<DemoScene::Item> DemoScene::items()
{
    return {{tr("Drum"), QStringLiteral("drum.poct"), SyntheticKind::Drum, 1},
            {tr("Fragment A"), QStringLiteral("fragment-a.poct"), SyntheticKind::Fragment, 2},
            {tr("Fragment B"), QStringLiteral("fragment-b.poct"), SyntheticKind::Fragment, 3},
            {tr("Omphalos"), QStringLiteral("omphalos.poct"), SyntheticKind::Omphalos, 4}};
}

QString DemoScene::projectPath() const
{
    return QDir(m_directory).absoluteFilePath(QStringLiteral("demo.stylos"));
}

QStringList DemoScene::paths() const
{
    QStringList result;
    for (const Item& item : items())
        result << QDir(m_directory).absoluteFilePath(item.fileName);
    return result;
}

QString DemoScene::stamp() const
{
    return QStringLiteral("stylos-demo %1\nspacing %2\ndirections %3\n")
        .arg(Version)
        .arg(m_spacing, 0, 'g', 17)
        .arg(SkyDirections);
}

bool DemoScene::isGenerated() const
{
    QFile stampFile(QDir(m_directory).filePath(QStringLiteral("demo.version")));
    if (!stampFile.open(QIODevice::ReadOnly) || QString::fromUtf8(stampFile.readAll()) != stamp()) return false;
    auto project = core::scene::ProjectFile::load(projectPath().toStdString());
    return project && project->problems.empty() && project->scene.size() == items().size();
}

bool DemoScene::prepare()
{
    if (isPreparing()) return false;
    if (isGenerated()) {
        // Queued, so callers see the same asynchronous contract whether or not the files exist.
        QTimer::singleShot(0, this, [this] { Q_EMIT ready(projectPath()); });
        return true;
    }
    if (!QDir().mkpath(m_directory)) {
        QTimer::singleShot(0, this, [this] {
            Q_EMIT failed(tr("Could not create the demo folder %1.").arg(QDir::toNativeSeparators(m_directory)));
        });
        return true;
    }
    // An incomplete or outdated cache goes first: until the new project is written, there is none.
    QDir dir(m_directory);
    for (const QString& name :
         QStringList{QStringLiteral("demo.stylos"), QStringLiteral("demo.version")} + legacyFiles())
        if (dir.exists(name)) dir.remove(name);

    core::synth::DemoRequest request;
    request.folder = m_directory.toStdString();
    for (const Item& item : items())
        request.items.push_back({item.name.toStdString(), item.fileName.toStdString(), item.kind, item.seed});
    request.spacing = m_spacing;
    request.skyDirections = SkyDirections;
    request.stamp = stamp().toStdString();
    request.axisName = tr("Axis").toStdString();
    request.fluteName = tr("Flute").toStdString();
    request.assemblyName = tr("Drum 1 reconstruction").toStdString();
    auto* watcher = m_tasks.start<Outcome>(
        tr("Preparing the demo scene"),
        [request = std::move(request)](QPromise<Outcome>& promise, core::ProgressSink& progress) {
            generate(request, promise, progress);
        });
    m_watcher = watcher;
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] { generationEnded(watcher); });
    return true;
}

void DemoScene::cancel()
{
    if (m_watcher) m_watcher->cancel();
}

void DemoScene::generationEnded(QFutureWatcherBase* watcher)
{
    m_watcher.clear();
    auto* typed = static_cast<QFutureWatcher<Outcome>*>(watcher);
    if (typed->future().resultCount() == 0) {
        Q_EMIT cancelled();
        return;
    }
    const Outcome outcome = typed->result();
    if (!outcome.error) {
        Q_EMIT ready(projectPath());
        return;
    }
    const core::Error& error = *outcome.error;
    Q_EMIT failed(tr("Could not prepare the demo scene: %1: %2.").arg(outcome.file, ErrorText::reason(error.code)) +
                  QLatin1Char('\n') + QString::fromStdString(error.message));
}

} // namespace stylos::widgets
