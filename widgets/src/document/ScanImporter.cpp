#include "stylos/widgets/document/ScanImporter.h"

#include "stylos/core/io/PointFileFormat.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/scene/ImportPlacement.h"
#include "stylos/core/view/GuideGeometry.h"
#include "tasks/ErrorText.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <climits>

#include <optional>

namespace stylos::widgets {

namespace {

/** What an import task hands back (nothing at all when cancelled). */
struct ImportResult {
    SceneDocument::OctreePtr octree;
    std::optional<core::Error> error;
    std::uint64_t skippedPoints = 0; ///< non-finite points the reader dropped
    std::uint32_t scans = 0;         ///< scans whose points' normals were estimated apart (0: one cloud)
};

bool isPoct(const QString& path)
{
    return core::io::hasPoctExtension(path.toStdString());
}

} // namespace

ScanImporter::ScanImporter(SceneDocument& document, TaskManager& tasks, QObject* parent)
    : QObject(parent), m_document(document), m_tasks(tasks)
{
    // An import that ends after the project was replaced must not land in the new one.
    connect(&document, &SceneDocument::sceneAboutToBeReset, this, [this] {
        for (QFutureWatcherBase* watcher : std::as_const(m_pending)) watcher->cancel();
    });
}

void ScanImporter::setCacheDirectory(const QString& directory)
{
    m_document.setOctreeCacheFolder(directory);
}

QString ScanImporter::cacheDirectory() const
{
    return m_document.octreeCacheFolder();
}

QString ScanImporter::outputDirectory() const
{
    const QString folder = m_document.projectFolder();
    return folder.isEmpty() ? m_document.octreeCacheFolder() : folder;
}

QString ScanImporter::fileFilter()
{
    // Every point format Stylos knows, the ones it cannot read (LAZ) too: choosing one gives the reader's
    // message (what to do instead), where a filter without it would drop the file without a word.
    QStringList patterns;
    for (const core::io::PointFileExtension& e : core::io::pointFileExtensions())
        patterns << QStringLiteral("*.") + QString::fromLatin1(e.extension.data(), qsizetype(e.extension.size()));
    patterns << QStringLiteral("*.poct");
    return tr("Scans and octrees (%1)").arg(patterns.join(QLatin1Char(' '))) + QStringLiteral(";;") +
           tr("Packed octrees (*.poct)") + QStringLiteral(";;") + tr("All files (*)");
}

bool ScanImporter::canImport(const QString& path)
{
    const std::filesystem::path file = path.toStdString();
    return core::io::hasPoctExtension(file) || core::io::formatFromExtension(file) != core::io::PointFormat::Unknown;
}

int ScanImporter::importFiles(const QStringList& paths)
{
    int started = 0;
    for (const QString& path : paths) {
        const QString input = QFileInfo(path).absoluteFilePath();
        const bool direct = isPoct(input);
        QString output;
        if (!direct) {
            output = reserveOutput(input);
            if (output.isEmpty()) {
                fail(input, tr("Could not import %1: the folder %2 cannot be created or written to.")
                                .arg(QFileInfo(input).fileName(), QDir::toNativeSeparators(outputDirectory())));
                continue;
            }
        }
        const std::filesystem::path in = input.toStdString();
        const std::filesystem::path out = output.toStdString();
        const core::octree::BuildOptions options = m_options;
        core::io::ReadOptions read;
        if (!direct) read.frame = m_frame;
        auto* watcher = m_tasks.start<ImportResult>(
            tr("Importing %1").arg(QFileInfo(input).fileName()),
            [in, out, options, read, direct](QPromise<ImportResult>& promise, core::ProgressSink& progress) {
                ImportResult result;
                if (!direct) {
                    auto built = core::octree::buildOctreeFile(in, out, options, &progress, read);
                    if (!built && built.error().code == core::ErrorCode::Cancelled) return;
                    if (!built) {
                        result.error = built.error();
                        promise.addResult(std::move(result));
                        return;
                    }
                    result.skippedPoints = built->skippedPoints;
                    result.scans = built->normalsEstimated ? built->normalScans : 0;
                }
                auto opened = core::octree::PackedOctree::open(direct ? in : out);
                if (progress.isCancelRequested()) return; // the GUI side removes the file
                if (opened) result.octree = std::make_shared<const core::octree::PackedOctree>(std::move(opened).value());
                else result.error = opened.error();
                progress.update(1.0);
                promise.addResult(std::move(result));
            });
        m_pending.insert(watcher);
        connect(watcher, &QFutureWatcherBase::finished, this,
                [this, input, output, frame = read.frame, watcher] { importEnded(input, output, frame, watcher); });
        ++started;
    }
    if (m_pending.isEmpty() && !m_errors.isEmpty()) {
        // Only failures that could not even start: still report the batch's end after this returns.
        QMetaObject::invokeMethod(this, [this] {
            if (m_pending.isEmpty() && !m_errors.isEmpty()) Q_EMIT importsFinished(std::exchange(m_errors, {}));
        }, Qt::QueuedConnection);
    }
    return started;
}

QString ScanImporter::reserveOutput(const QString& input)
{
    const QString folder = outputDirectory();
    if (!QDir().mkpath(folder)) return {};
    const QString stem = QFileInfo(input).completeBaseName();
    for (int n = 1;; ++n) {
        const QString candidate = QDir(folder).absoluteFilePath(
            n == 1 ? stem + QStringLiteral(".poct") : QStringLiteral("%1-%2.poct").arg(stem).arg(n));
        if (QFileInfo::exists(candidate) || m_document.isOctreePathReserved(candidate)) continue;
        // Created only if absent, in one step: no other process can take the name between the test and here.
        QFile placeholder(candidate);
        if (!placeholder.open(QIODevice::WriteOnly | QIODevice::NewOnly)) {
            if (QFileInfo::exists(candidate)) continue; // another Stylos took it just now
            return {};                                  // the folder cannot be written
        }
        placeholder.close();
        m_document.reserveOctreePath(candidate); // neither another import nor a save meanwhile takes this name
        return candidate;
    }
}

void ScanImporter::importEnded(const QString& input, const QString& output, const core::io::ImportFrame& frame,
                               QFutureWatcherBase* watcher)
{
    m_pending.remove(watcher);
    if (!output.isEmpty()) m_document.releaseOctreePath(output);
    auto* typed = static_cast<QFutureWatcher<ImportResult>*>(watcher);
    const bool delivered = !typed->isCanceled() && typed->future().resultCount() > 0;
    const ImportResult result = delivered ? typed->result() : ImportResult{};
    if (!delivered || !result.octree) {
        // Cancelled (possibly after the file was written) or failed: leave nothing behind.
        if (!output.isEmpty() && QFileInfo::exists(output)) QFile::remove(output);
    }
    if (delivered && result.error) {
        const core::Error& error = *result.error;
        fail(input, tr("Could not import %1: %2.").arg(QFileInfo(input).fileName(), ErrorText::reason(error.code)) +
                        QLatin1Char('\n') + QString::fromStdString(error.message));
    } else if (delivered && result.octree) {
        core::scene::Fragment fragment;
        fragment.name = QFileInfo(input).completeBaseName().toStdString();
        fragment.octreePath = (output.isEmpty() ? input : output).toStdString();
        if (!output.isEmpty()) fragment.sourcePath = input.toStdString();
        fragment.importFrame = frame;
        fragment.colour = core::scene::defaultFragmentColour(m_document.scene().size());
        fragment.pose = placement(*result.octree);
        const auto id = m_document.addFragment(std::move(fragment), result.octree,
                                               [file = QFileInfo(input).fileName()] { return tr("Import %1").arg(file); });
        if (!output.isEmpty()) m_document.noteImportedOctree(output); // removed if this import is undone for good
        Q_EMIT fragmentImported(id);
        if (result.skippedPoints > 0) // said, as stylos-cli says it: no point dropped silently
            Q_EMIT importNote(id, tr("%1: %Ln point(s) with NaN or infinite coordinates skipped", nullptr,
                                     int(std::min<std::uint64_t>(result.skippedPoints, std::uint64_t(INT_MAX))))
                                      .arg(QFileInfo(input).fileName()));
        if (result.scans >= 2) // an E57 or PTX of several scans, or a cloud with a scan column: not merged unsaid
            Q_EMIT importNote(id, tr("%1 holds %Ln scan(s), merged into one fragment; each point's normal was "
                                     "estimated from its own scan's points", nullptr, int(result.scans))
                                      .arg(QFileInfo(input).fileName()));
    }
    if (m_pending.isEmpty()) Q_EMIT importsFinished(std::exchange(m_errors, {}));
}

core::scene::Pose ScanImporter::placement(const core::octree::PackedOctree& octree) const
{
    std::vector<core::scene::PlacedExtent> placed;
    for (const core::scene::Fragment& f : m_document.scene().fragments())
        if (const auto opened = m_document.octree(f.id))
            placed.push_back({core::view::occupiedBounds(*opened), m_document.worldPose(f.id)});
    return core::scene::placeImport(placed, core::view::occupiedBounds(octree));
}

void ScanImporter::fail(const QString& input, const QString& message)
{
    m_errors << message;
    Q_EMIT importFailed(input, message);
}

} // namespace stylos::widgets
