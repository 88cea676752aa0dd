#pragma once
/** @file
 * @brief The loaded scene for this foundation stage: owns the task runner, the loader, the demo scene and
 *        the summary model, and chains their steps (generate the demo, then load it). Emits one
 *        operationFinished() per user request, with every error met, so the window can report them once.
 */
#include <QObject>
#include <QStringList>

namespace stylos::widgets {

class DemoScene;
class SceneLoader;
class SceneSummaryModel;
class TaskRunner;

class SceneSession : public QObject {
    Q_OBJECT

public:
    /** The demo goes to @p demoDirectory, or to DemoScene::defaultDirectory() when empty. */
    explicit SceneSession(const QString& demoDirectory = {}, QObject* parent = nullptr);
    ~SceneSession() override;

    TaskRunner& runner() const { return *m_runner; }
    SceneSummaryModel& model() const { return *m_model; }
    DemoScene& demo() const { return *m_demo; }
    bool isBusy() const;

    /** Loads @p paths and adds them to the scene. False when a task is already running. */
    bool openFiles(const QStringList& paths);
    /** Replaces the scene by the demo scene (generated first if needed). False when busy. */
    bool openDemo();

Q_SIGNALS:
    /** One file could not be loaded; @p message is translated and names it. */
    void fileFailed(const QString& path, const QString& message);
    /**
     * The request ended: @p errors holds a translated message per failure (empty on full success);
     * @p cancelled when the user stopped it.
     */
    void operationFinished(const QStringList& errors, bool cancelled);

private:
    void finish(bool cancelled);

    TaskRunner* m_runner;
    SceneSummaryModel* m_model;
    SceneLoader* m_loader;
    DemoScene* m_demo;
    QStringList m_errors;
    bool m_pending = false; ///< a request runs, possibly between two of its tasks
};

} // namespace stylos::widgets
