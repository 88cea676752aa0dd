#pragma once
/** @file
 * @brief The embedded demo scene: a fluted drum, two fragments and an omphalos, generated once by the
 *        core's synthetic scan generator into the user's cache directory, then reused. Generation runs as a
 *        background task with progress and Cancel.
 */
#include "stylos/core/synth/SyntheticScan.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <vector>

namespace stylos::widgets {

class TaskRunner;

class DemoScene : public QObject {
    Q_OBJECT

public:
    /** One file of the demo scene. */
    struct Item {
        QString fileName;
        core::synth::SyntheticKind kind;
        std::uint64_t seed;
    };

    /** Coarse sampling (metres) so that generation takes seconds, not minutes. */
    static constexpr double Spacing = 0.0025;

    /** Uses @p runner (not owned); files go to @p directory, or to defaultDirectory() when empty. */
    explicit DemoScene(TaskRunner& runner, const QString& directory = {}, QObject* parent = nullptr);

    /** QStandardPaths::CacheLocation + "/demo". */
    static QString defaultDirectory();
    static std::vector<Item> items();

    QString directory() const { return m_directory; }
    /** The demo files' paths, whether they exist yet or not. */
    QStringList paths() const;
    /** True when every demo file exists (they are written atomically: existing means complete). */
    bool isGenerated() const;

    /**
     * @brief Emits ready() with the paths, at once (queued) when the files exist, otherwise after generating
     *        the missing ones in the background. False when the runner is busy.
     */
    bool prepare();

Q_SIGNALS:
    void ready(const QStringList& paths);
    /** @p message is translated and says what failed. */
    void failed(const QString& message);
    void cancelled();

private:
    TaskRunner& m_runner;
    QString m_directory;
};

} // namespace stylos::widgets
