#include "stylos/widgets/DemoScene.h"

#include "stylos/core/ao/AmbientOcclusion.h"
#include "stylos/core/ao/AoExport.h"
#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/synth/DrumShape.h"
#include "stylos/core/synth/FragmentShape.h"
#include "stylos/core/synth/OmphalosShape.h"
#include "stylos/core/synth/Random.h"
#include "stylos/core/synth/ScanSimulator.h"
#include "stylos/core/util/AtomicTextFile.h"
#include "stylos/widgets/ErrorText.h"
#include "stylos/widgets/TaskManager.h"
#include "stylos/core/util/SubProgress.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>

namespace stylos::widgets {

namespace {

namespace fs = std::filesystem;
using core::scene::Pose;
using core::synth::SyntheticKind;

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

/** What the generation task hands back; nothing at all when it was cancelled. */
struct Outcome {
    std::optional<core::Error> error;
    QString file; ///< the file being made when it failed
};

/** An item's synthetic object, in its own frame, and the azimuths the layout needs. */
struct DemoObject {
    std::unique_ptr<core::synth::SyntheticObject> object;
    double azimuth = 0.0; ///< drum: centre of its broken region; fragment: centre of its sector (radians)
};

/** The same objects generateScan() makes for this kind and seed (same random draws, same order). */
DemoObject makeObject(SyntheticKind kind, const core::synth::SyntheticOptions& options)
{
    using namespace core::synth;
    Random random(options.seed);
    DemoObject made;
    switch (kind) {
    case SyntheticKind::Drum: {
        const DrumParameters drum = DrumParameters::fromOptions(options, random);
        made.azimuth = drum.brokenCentre;
        made.object = std::make_unique<DrumShape>(drum);
        break;
    }
    case SyntheticKind::Fragment: {
        const DrumParameters drum = DrumParameters::fromOptions(options, random);
        const FragmentParameters fragment = FragmentParameters::random(drum, random);
        made.azimuth = fragment.thetaCentre;
        made.object = std::make_unique<FragmentShape>(drum, fragment);
        break;
    }
    case SyntheticKind::Omphalos:
        made.object = std::make_unique<OmphalosShape>(OmphalosParameters::random(random));
        break;
    }
    return made;
}

/** Simulates the scans of @p object (object frame, true normals) into the PLY @p path. */
core::Result<std::uint64_t> simulateScan(const core::synth::SyntheticObject& object,
                                         const core::synth::SyntheticOptions& options, const fs::path& path,
                                         core::ProgressSink& progress)
{
    core::io::PointSchema schema;
    schema.hasNormals = true;
    schema.scalarNames = {"scan_id"};
    core::io::PlyWriterOptions plyOptions;
    plyOptions.scalarTypes = {core::io::PlyScalarType::UInt8};
    plyOptions.positionType = core::io::PlyScalarType::Float32; // object frame, metres: float is plenty
    auto writer = core::io::PlyWriter::create(path, schema, plyOptions);
    if (!writer) return writer.error();
    core::synth::ScanSimulator simulator(object, options, Eigen::Affine3d::Identity(), options.seed);
    auto points = simulator.run(*writer, &progress);
    if (!points) return points.error();
    if (auto finished = writer->finish(); !finished) return finished.error();
    return points;
}

/** Leaf level whose cells are about @p spacing (the root box is about the object's size): a leaf then
 *  holds a point or two, and the skydome's closed-surface level is the leaf level or the one above. */
int depthFor(const core::synth::SyntheticObject& object, double spacing)
{
    const double size = std::max(2.0 * object.extent(), object.height());
    return std::clamp(static_cast<int>(std::lround(std::log2(size / spacing))), 4, 14);
}

Pose rotation(double x, double y, double z)
{
    core::scene::TranslationAngles value;
    value.angles = {x, y, z};
    return Pose::fromTranslationAngles(value);
}

/** @p rotation with the translation that puts the octree's lowest leaf on z = 0 and the middle of its
 *  leaves' footprint at (@p x, @p y). */
Pose placeOnGround(const core::octree::PackedOctree& octree, const Pose& rotation, double x, double y)
{
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::array<double, 3> lo{inf, inf, inf}, hi{-inf, -inf, -inf};
    octree.forEachCell(octree.depth(), [&](const core::octree::CellView& cell) {
        const std::array<double, 3> p = rotation.apply(cell.centre);
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
        return true;
    });
    return rotation.withTranslation({x - 0.5 * (lo[0] + hi[0]), y - 0.5 * (lo[1] + hi[1]), -lo[2]});
}

/**
 * The demo's layout (scene frame: z up, the default view looking along +y): the drum at the origin, its
 * broken region turned toward the viewer; fragment A upright on the ground to its right, its fluted face
 * toward the viewer; fragment B lying on its inner face, fluted face up, behind it; the omphalos to the left.
 */
Pose layout(std::size_t index, const DemoObject& made, const core::octree::PackedOctree& octree)
{
    switch (index) {
    case 0:
        return rotation(0, 0, -100 * kDegree - made.azimuth);
    case 1:
        return placeOnGround(octree, rotation(0, 0, -65 * kDegree - made.azimuth), 1.15, -0.3);
    case 2: {
        // Sector centre to +x, then outward (+x) up (+z), then a turn about the vertical.
        const Pose lying = rotation(0, 0, 25 * kDegree) * rotation(0, -kPi / 2, 0) * rotation(0, 0, -made.azimuth);
        return placeOnGround(octree, lying, 1.2, 0.55);
    }
    default:
        return Pose::translation({-1.4, 0.1, 0.0});
    }
}

/** The plain-data job: what the worker needs, copied from the GUI thread. */
struct Job {
    QString directory;
    std::vector<DemoScene::Item> items;
    double spacing = DemoScene::DefaultSpacing;
    std::string stamp;
    std::string axisName;
};

/** Relative time each item takes (measured), to share the progress bar. */
double itemWeight(SyntheticKind kind)
{
    switch (kind) {
    case SyntheticKind::Drum:
        return 10.0;
    case SyntheticKind::Omphalos:
        return 8.4;
    case SyntheticKind::Fragment:
        return 1.6;
    }
    return 1.0;
}

void removeFiles(const std::vector<fs::path>& files)
{
    std::error_code ignored;
    for (const fs::path& file : files)
        fs::remove(file, ignored);
}

/** The whole generation, on a worker thread. Adds nothing to @p promise when cancelled. */
void generate(const Job& job, QPromise<Outcome>& promise, core::ProgressSink& progress)
{
    const fs::path folder = job.directory.toStdString();
    QTemporaryDir scratch(QDir(job.directory).filePath(QStringLiteral(".demo-XXXXXX")));
    std::vector<fs::path> written; // removed again unless the project is written
    const auto fail = [&](const core::Error& error, const QString& file) {
        removeFiles(written);
        if (error.code != core::ErrorCode::Cancelled) promise.addResult(Outcome{error, file});
    };
    if (!scratch.isValid()) {
        fail(core::Error::at(core::ErrorCode::WriteFailed, job.directory.toStdString(), {},
                             scratch.errorString().toStdString()),
             job.directory);
        return;
    }
    const fs::path temp = scratch.path().toStdString();

    double total = 0.0;
    for (const auto& item : job.items)
        total += itemWeight(item.kind);
    double done = 0.0;
    core::scene::Scene scene;
    for (std::size_t i = 0; i < job.items.size(); ++i) {
        const DemoScene::Item& item = job.items[i];
        const double from = done / total, share = itemWeight(item.kind) / total;
        done += itemWeight(item.kind);
        const auto step = [&](double a, double b) {
            return core::SubProgress(&progress, from + a * share, from + b * share);
        };
        const fs::path ply = temp / (item.fileName.toStdString() + ".ply");
        const fs::path built = temp / item.fileName.toStdString();
        const fs::path output = folder / item.fileName.toStdString();

        core::synth::SyntheticOptions options;
        options.spacing = job.spacing;
        options.seed = item.seed;
        options.writeNormals = true;
        const DemoObject made = makeObject(item.kind, options);
        {
            core::SubProgress sink = step(0.0, 0.5);
            if (auto scanned = simulateScan(*made.object, options, ply, sink); !scanned)
                return fail(scanned.error(), item.fileName);
        }
        core::octree::BuildOptions build;
        build.depth = depthFor(*made.object, job.spacing);
        {
            core::SubProgress sink = step(0.5, 0.8);
            auto report = core::octree::buildOctreeFile(ply, built, build, &sink);
            std::error_code ignored;
            fs::remove(ply, ignored);
            if (!report) return fail(report.error(), item.fileName);
        }
        auto opened = core::octree::PackedOctree::open(built);
        if (!opened) return fail(opened.error(), item.fileName);
        const core::octree::PackedOctree& octree = opened.value();

        // The 3D skydome at the level where the cells still close the surface, spread to the leaves.
        std::vector<float> perLeaf;
        {
            core::SubProgress sink = step(0.8, 0.97);
            auto cells = core::ao::cellsAtLevel(octree, core::ao::closedSurfaceLevel(octree));
            if (!cells) return fail(cells.error(), item.fileName);
            core::ao::AoOptions ao;
            ao.directions = DemoScene::SkyDirections;
            auto values = core::ao::computeAmbientOcclusion(*cells, ao, &sink);
            if (!values) return fail(values.error(), item.fileName);
            perLeaf = core::ao::valuesPerLeaf(*cells, *values);
        }
        {
            core::SubProgress sink = step(0.97, 1.0);
            written.push_back(output);
            if (auto stored = core::ao::writeAmbientPoct(octree, perLeaf, output, &sink); !stored)
                return fail(stored.error(), item.fileName);
        }

        core::scene::Fragment fragment;
        fragment.name = item.name.toStdString();
        fragment.octreePath = output;
        fragment.pose = layout(i, made, octree);
        fragment.colour = core::scene::defaultFragmentColour(i);
        if (item.kind == SyntheticKind::Drum)
            fragment.guides.push_back({job.axisName, core::scene::GuideKind::Axis, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}});
        scene.add(std::move(fragment));
        if (progress.isCancelRequested()) return fail(core::Error{core::ErrorCode::Cancelled, {}}, item.fileName);
    }

    // The stamp, then the project: the project file's existence is what makes the cache complete.
    const fs::path stampPath = folder / "demo.version";
    const fs::path projectPath = folder / "demo.stylos";
    written.push_back(stampPath);
    if (auto s = core::writeTextFileAtomically(stampPath, job.stamp); !s) return fail(s.error(), "demo.version");
    if (progress.isCancelRequested()) return fail(core::Error{core::ErrorCode::Cancelled, {}}, {});
    if (auto s = core::scene::ProjectFile::save(scene, projectPath); !s) return fail(s.error(), "demo.stylos");
    progress.update(1.0);
    promise.addResult(Outcome{});
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

    Job job;
    job.directory = m_directory;
    job.items = items();
    job.spacing = m_spacing;
    job.stamp = stamp().toStdString();
    job.axisName = tr("Axis").toStdString();
    auto* watcher =
        m_tasks.start<Outcome>(tr("Preparing the demo scene"),
                               [job = std::move(job)](QPromise<Outcome>& promise, core::ProgressSink& progress) {
                                   generate(job, promise, progress);
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
