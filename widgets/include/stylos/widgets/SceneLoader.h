#pragma once
/** @file
 * @brief Loads point files in the background, one after the other: streams each file through its
 *        reader in batches, counting points and accumulating bounds and attributes, never keeping the
 *        points. Each file's summary (or its error) is delivered on the GUI thread as soon as it is read.
 */
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"
#include "stylos/widgets/ScanSummary.h"

#include <QObject>
#include <QStringList>

#include <filesystem>
#include <optional>

namespace stylos::widgets {

class TaskRunner;

class SceneLoader : public QObject {
    Q_OBJECT

public:
    /** One file's outcome, as the worker produces it. */
    struct FileResult {
        ScanSummary summary;               ///< path always set; the rest when loaded
        std::optional<core::Error> error;  ///< set when the file could not be read
    };

    /** Uses @p runner (not owned) to run its tasks. */
    explicit SceneLoader(TaskRunner& runner, QObject* parent = nullptr);

    /** Starts loading @p paths; false (and nothing happens) when the runner is busy or @p paths is empty. */
    bool load(const QStringList& paths);

    /**
     * @brief Reads @p path to the end, synchronously (the worker's job, public for tests and tools).
     *        Progress goes to @p progress mapped onto [@p from, @p to]. Cancelled when it asks to stop.
     */
    static core::Result<ScanSummary> scanFile(const std::filesystem::path& path, core::ProgressSink* progress,
                                              double from = 0.0, double to = 1.0);

Q_SIGNALS:
    void fileLoaded(const stylos::widgets::ScanSummary& summary);
    /** @p message is translated and names the file and the reason. */
    void fileFailed(const QString& path, const QString& message);
    /** The whole load ended: @p loaded and @p failed files, or it was cancelled part-way. */
    void finished(int loaded, int failed, bool cancelled);

private:
    void deliver(const FileResult& result);

    TaskRunner& m_runner;
    int m_loaded = 0;
    int m_failed = 0;
};

} // namespace stylos::widgets
