#pragma once
/** @file
 * @brief The embedded demo: a project (`demo.stylos`) of four fragments — a fluted drum, two fragments of
 *        it and an omphalos — generated once by the core's synthetic scan generator into a cache folder,
 *        then reused. Each item's scan is simulated (fixed seed, in the object's own frame: axis +z, z = 0
 *        at the lower bed or base), built into a packed octree and given its 3D skydome as the octree's
 *        "ambient" layer, so the window shows skydome shading at once. The project lays the scene out:
 *        the drum at the origin (with its axis guide), the two fragments on the ground beside it (one
 *        upright, one lying on its inner face, fluted face up), the omphalos on the other side.
 *
 * Generation is ONE background task on a TaskManager ("Preparing the demo scene", progress and Cancel).
 * Every file is written atomically; the project file last, after a version stamp (`demo.version`):
 * complete means the stamp matches this code and spacing, `demo.stylos` exists and every `.poct` it names
 * exists. Anything else (an older PLY-only demo, a cancelled run, another spacing) is regenerated whole.
 * A cancelled or failed run removes what it wrote. The scan PLYs are temporary (a scratch folder inside
 * the demo folder, removed at the end).
 * Thread-safety: GUI thread only (the worker gets copies and touches nothing of this object).
 */
#include "stylos/core/scene/Scene.h"
#include "stylos/core/synth/SyntheticScan.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <vector>

class QFutureWatcherBase;

namespace stylos::widgets {

class SceneDocument;
class TaskManager;

class DemoScene : public QObject {
    Q_OBJECT

  public:
    /** @brief One fragment of the demo. */
    struct Item {
        QString name;     ///< translated ("Drum", "Fragment A"...)
        QString fileName; ///< its octree, in directory(): "drum.poct"...
        core::synth::SyntheticKind kind;
        std::uint64_t seed; ///< the generator's seed (fixed: the demo is always the same)
    };

    /** @brief Sampling of the scans, metres (about 2.3 M points in all; ~10 s on 2 busy cores). */
    static constexpr double DefaultSpacing = 0.002;
    /** @brief Bumped whenever the generated files change; an older cache is regenerated. */
    static constexpr int Version = 6; // 5: the drum comes annotated; 6: its skydome smoothed (SkydomeSmoothing.h)
    /** @brief Skydome directions (a Fibonacci sphere). */
    static constexpr int SkyDirections = 96;

    /** Runs on @p tasks (not owned; it must outlive this object); files go to @p directory, or to
     *  defaultDirectory() when empty. */
    explicit DemoScene(TaskManager& tasks, const QString& directory = {}, QObject* parent = nullptr);
    /** Cancels a generation still running (its files are removed by the worker). */
    ~DemoScene() override;

    /** @brief QStandardPaths::CacheLocation + "/demo". */
    static QString defaultDirectory();
    /** @brief The four items, in project order (names translated). */
    static std::vector<Item> items();
    /** @brief The names the demo gives, in the current language. */
    struct Names {
        QStringList items; ///< in items() order
        QString axis;      ///< the drum's axis guide
        QString flute;     ///< the flute guides: "%1" is the flute's number
        QString assembly;  ///< the reconstruction assembly
    };
    static Names names();
    /**
     * @brief Names the demo's fragments (by their octree in @p folder), guides and assembly in @p scene
     *        with @p to. With @p from, only the names still equal to those in @p from change (what the
     *        user renamed stays); without, every one does. Returns whether a name changed.
     */
    static bool applyNames(core::scene::Scene& scene, const QString& folder, const Names& to,
                           const Names* from = nullptr);
    /**
     * @brief After a change of language: when @p document is the demo project, gives its demo names the
     *        current language's (SceneDocument::relabel, not an undo step), except those the user renamed.
     */
    void relabel(SceneDocument& document);

    QString directory() const { return m_directory; }
    /** @brief directory() + "/demo.stylos", whether it exists yet or not. */
    QString projectPath() const;
    /** @brief The items' `.poct` paths, in items() order, whether they exist yet or not. */
    QStringList paths() const;
    /** @brief True when the cache is complete (see the file comment); reads the small project file. */
    bool isGenerated() const;

    /** @brief Scan spacing in metres (> 0) for the next generation; tests use a coarse one. It is part of
     *         the version stamp, so a cache made with another spacing is regenerated. */
    void setSpacing(double metres) { m_spacing = metres; }
    double spacing() const { return m_spacing; }

    /** @brief True while the generation task runs. */
    bool isPreparing() const { return !m_watcher.isNull(); }

    /**
     * @brief Emits ready(projectPath()) at once (queued) when isGenerated(); otherwise starts the
     *        generation task, which ends in ready(), failed() or cancelled(). Returns false (and does
     *        nothing) while a generation is already running.
     */
    bool prepare();

  public Q_SLOTS:
    /** @brief Cancels the running generation (cancelled() follows); nothing when none runs. */
    void cancel();

  Q_SIGNALS:
    /** @brief The project is complete at @p projectPath: open it with SceneDocument::open(). */
    void ready(const QString& projectPath);
    /** @brief @p message is translated and names the file and the reason. */
    void failed(const QString& message);
    void cancelled();

  private:
    QString stamp() const;
    /** Writes the current language's names into the cached project (made in another language, maybe). */
    void localiseProject();
    void generationEnded(QFutureWatcherBase* watcher);

    TaskManager& m_tasks;
    QString m_directory;
    double m_spacing = DefaultSpacing;
    QPointer<QFutureWatcherBase> m_watcher;
    Names m_shown; ///< the names last given to the project (relabel() replaces those)
};

} // namespace stylos::widgets
