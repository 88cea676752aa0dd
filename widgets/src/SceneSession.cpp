#include "stylos/widgets/SceneSession.h"

#include "stylos/widgets/DemoScene.h"
#include "stylos/widgets/SceneLoader.h"
#include "stylos/widgets/SceneSummaryModel.h"
#include "stylos/widgets/TaskRunner.h"

namespace stylos::widgets {

SceneSession::SceneSession(const QString& demoDirectory, QObject* parent)
    : QObject(parent), m_runner(new TaskRunner(this)), m_model(new SceneSummaryModel(this)),
      m_loader(new SceneLoader(*m_runner, this)), m_demo(new DemoScene(*m_runner, demoDirectory, this))
{
    connect(m_loader, &SceneLoader::fileLoaded, m_model, &SceneSummaryModel::addScan);
    connect(m_loader, &SceneLoader::fileFailed, this, [this](const QString& path, const QString& message) {
        m_errors << message;
        Q_EMIT fileFailed(path, message);
    });
    connect(m_loader, &SceneLoader::finished, this, [this](int, int, bool cancelled) { finish(cancelled); });

    connect(m_demo, &DemoScene::ready, this, [this](const QStringList& paths) {
        m_model->clear();
        if (!m_loader->load(paths)) finish(false);
    });
    connect(m_demo, &DemoScene::failed, this, [this](const QString& message) {
        m_errors << message;
        finish(false);
    });
    connect(m_demo, &DemoScene::cancelled, this, [this] { finish(true); });
}

SceneSession::~SceneSession()
{
    // Stop the worker before the loader and the demo it reports to are destroyed.
    m_runner->cancelAndWait();
}

bool SceneSession::isBusy() const
{
    return m_pending || m_runner->isBusy();
}

bool SceneSession::openFiles(const QStringList& paths)
{
    if (paths.isEmpty() || isBusy()) return false;
    m_errors.clear();
    m_pending = m_loader->load(paths);
    return m_pending;
}

bool SceneSession::openDemo()
{
    if (isBusy()) return false;
    m_errors.clear();
    m_pending = m_demo->prepare();
    return m_pending;
}

void SceneSession::finish(bool cancelled)
{
    const QStringList errors = m_errors;
    m_errors.clear();
    m_pending = false;
    Q_EMIT operationFinished(errors, cancelled);
}

} // namespace stylos::widgets
