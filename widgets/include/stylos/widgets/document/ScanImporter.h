#pragma once
/** @file
 * @brief File › Import scans: for each chosen file a background task (TaskManager, with progress and
 *        Cancel) builds its packed octree with core::octree::buildOctreeFile — into the project's folder,
 *        or into a cache folder while the project has never been saved — opens it, then adds the fragment
 *        through the undo stack ("Import NAME"). The scans are read in the import frame set with
 *        setImportFrame() (up axis, unit, offset: the octree is Z up, in metres), which the fragment keeps
 *        (Fragment::importFrame, saved in the project). A `.poct` is opened directly, as it is. Each failure becomes one
 *        translated message naming the file and the reason; a cancelled import adds nothing and leaves no
 *        file behind. GUI thread only; the window never waits for an import.
 */
#include "stylos/core/io/ImportFrame.h"
#include "stylos/core/octree/OctreeBuild.h"

#include "stylos/core/scene/Pose.h"

#include <QObject>
#include <QSet>
#include <QString>
#include <QStringList>

class QFutureWatcherBase;

namespace stylos::core::octree {
class PackedOctree;
}

namespace stylos::widgets {

class SceneDocument;
class TaskManager;

class ScanImporter : public QObject {
    Q_OBJECT

public:
    /** Adds to @p document and runs on @p tasks (neither owned; both must outlive the importer). */
    ScanImporter(SceneDocument& document, TaskManager& tasks, QObject* parent = nullptr);

    /** @brief Octree build settings for the next imports (default: BuildOptions' defaults). */
    void setBuildOptions(const core::octree::BuildOptions& options) { m_options = options; }
    const core::octree::BuildOptions& buildOptions() const { return m_options; }

    /** @brief How the next imports' scans are read (default: the identity, Z up in metres). */
    void setImportFrame(const core::io::ImportFrame& frame) { m_frame = frame; }
    const core::io::ImportFrame& importFrame() const { return m_frame; }

    /** @brief Where octrees go while the project is unsaved: the document's octreeCacheFolder() (default: the
     *         user cache's "octrees" folder), which saving copies them out of and the cache cleaner empties. */
    void setCacheDirectory(const QString& directory);
    QString cacheDirectory() const;
    /** @brief Where the next import's octree goes: the project's folder, or the cache folder. */
    QString outputDirectory() const;

    /**
     * @brief Starts one task per file of @p paths (absolute or relative to the working folder). Returns
     *        the number of tasks started; a file that cannot even start (no output folder) is reported
     *        through importFailed() at once.
     */
    int importFiles(const QStringList& paths);
    /** @brief Imports still running or waiting. */
    int pending() const { return static_cast<int>(m_pending.size()); }

    /**
     * @brief The file dialog's name filter: every importable extension (core::io::importableExtensions(),
     *        every point format Stylos knows, LAZ included, and `.poct`), then `.poct` alone, then all files.
     */
    static QString fileFilter();
    /** @brief Whether @p path's extension is a point format Stylos knows or `.poct` (what a drop onto the window
     *         accepts). A known format it cannot read (LAZ) is accepted so that its import says what to do. */
    static bool canImport(const QString& path);

Q_SIGNALS:
    /** @brief A fragment was added (one undo step). */
    void fragmentImported(quint64 id);
    /** @brief Something the user should know of an import that succeeded (@p message translated, naming the file):
     *  points skipped for NaN or infinite coordinates. */
    void importNote(quint64 id, const QString& message);
    /** @brief @p message is translated and names the file and the reason. */
    void importFailed(const QString& path, const QString& message);
    /** @brief Every pending import ended; @p errors holds their messages (empty on full success). */
    void importsFinished(const QStringList& errors);

private:
    /**
     * The octree's name in the output folder, taken on disk at once: an empty file is created there (exclusively,
     * so that another Stylos importing a scan of the same name into the same cache takes the next name) and the
     * finished octree is renamed over it. Empty when the folder cannot be created or written.
     */
    QString reserveOutput(const QString& input);
    void importEnded(const QString& input, const QString& output, const core::io::ImportFrame& frame,
                     QFutureWatcherBase* watcher);
    void fail(const QString& input, const QString& message);
    /** Where a scan with @p octree goes among the fragments open now (core::scene::placeImport). */
    core::scene::Pose placement(const core::octree::PackedOctree& octree) const;

    SceneDocument& m_document;
    TaskManager& m_tasks;
    core::octree::BuildOptions m_options;
    core::io::ImportFrame m_frame;
    QSet<QFutureWatcherBase*> m_pending;
    QStringList m_errors;
};

} // namespace stylos::widgets
