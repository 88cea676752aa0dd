#include "stylos/widgets/document/DemoScene.h"

#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/synth/DemoProject.h"
#include "tasks/ErrorText.h"
#include "stylos/widgets/document/SceneDocument.h"
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

DemoScene::Names DemoScene::names()
{
    Names names;
    for (const Item& item : items()) names.items << item.name;
    names.axis = tr("Axis");
    names.flute = tr("Flute %1");
    names.assembly = tr("Drum 1 reconstruction");
    return names;
}

bool DemoScene::applyNames(core::scene::Scene& scene, const QString& folder, const Names& to, const Names* from)
{
    const auto items = DemoScene::items();
    bool changed = false;
    const auto give = [&changed, from](std::string& name, const QString& before, const QString& after) {
        if (from && QString::fromStdString(name) != before) return; // renamed by the user
        if (name == after.toStdString()) return;
        name = after.toStdString();
        changed = true;
    };
    const QDir dir(folder);
    bool demo = false;
    for (const core::scene::Fragment& f : scene.fragments()) {
        const QFileInfo octree(QString::fromStdString(f.octreePath.string()));
        int item = -1;
        for (std::size_t i = 0; i < items.size(); ++i)
            if (octree.fileName() == items[i].fileName && QDir(octree.absolutePath()) == dir) item = static_cast<int>(i);
        if (item < 0) continue;
        demo = true;
        core::scene::Fragment* mine = scene.find(f.id);
        give(mine->name, from ? from->items.value(item) : QString(), to.items.value(item));
        int flute = 0;
        for (core::scene::Guide& g : mine->guides) {
            if (g.kind == core::scene::GuideKind::Axis) give(g.name, from ? from->axis : QString(), to.axis);
            else {
                ++flute;
                give(g.name, from ? from->flute.arg(flute) : QString(), to.flute.arg(flute));
            }
        }
    }
    // The demo's one assembly (only in a scene of the demo's fragments).
    if (demo)
        for (const core::scene::Assembly& a : scene.assemblies())
            give(scene.findAssembly(a.id)->name, from ? from->assembly : QString(), to.assembly);
    return changed;
}

void DemoScene::localiseProject()
{
    m_shown = names();
    auto project = core::scene::ProjectFile::load(projectPath().toStdString());
    if (!project) return; // the document's open() will say what is wrong
    if (applyNames(project->scene, m_directory, m_shown))
        (void)core::scene::ProjectFile::save(project->scene, projectPath().toStdString()); // the cache only
}

void DemoScene::relabel(SceneDocument& document)
{
    if (m_shown.items.isEmpty() || QFileInfo(document.projectPath()).absoluteFilePath() != QFileInfo(projectPath()).absoluteFilePath()) return;
    const Names before = m_shown, after = names();
    m_shown = after;
    document.relabel([&](core::scene::Scene& scene) { applyNames(scene, m_directory, after, &before); });
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
        QTimer::singleShot(0, this, [this] {
            localiseProject();
            Q_EMIT ready(projectPath());
        });
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
        localiseProject(); // the language may have changed while it was made
        Q_EMIT ready(projectPath());
        return;
    }
    const core::Error& error = *outcome.error;
    Q_EMIT failed(tr("Could not prepare the demo scene: %1: %2.").arg(outcome.file, ErrorText::reason(error.code)) +
                  QLatin1Char('\n') + QString::fromStdString(error.message));
}

} // namespace stylos::widgets
