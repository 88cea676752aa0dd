#include "stylos/widgets/SkydomeRunner.h"

#include "stylos/widgets/TaskManager.h"

#include <QFutureWatcher>

namespace stylos::widgets {

SkydomeRunner::SkydomeRunner(SceneDocument& document, QObject* parent) : QObject(parent), m_document(document)
{
    // Another project: its fragments may reuse the ids, and the old files need no layer any more.
    connect(&m_document, &SceneDocument::sceneAboutToBeReset, this, [this] {
        for (auto& [id, watcher] : m_running)
            if (watcher) watcher->cancel();
        m_running.clear();
    });
}

int SkydomeRunner::start(const QList<FragmentId>& ids, const SkydomeOptions& options)
{
    int started = 0;
    for (const FragmentId id : ids) {
        const core::scene::Fragment* f = m_document.fragment(id);
        if (!f || !m_document.octree(id) || isRunning(id)) continue;
        const SkydomeJob job(QString::fromStdString(f->octreePath.string()), id, options, QString::fromStdString(f->name));
        auto* watcher = m_document.tasks().start<SkydomeResult>(job.label(), job);
        m_running[id] = watcher;
        connect(watcher, &QFutureWatcherBase::finished, this, [this, id, watcher] { ended(id, watcher); });
        ++started;
    }
    return started;
}

void SkydomeRunner::ended(FragmentId id, QFutureWatcherBase* watcher)
{
    const auto it = m_running.find(id);
    if (it == m_running.end() || it->second != watcher) return; // dropped by a reset
    m_running.erase(it);
    auto* typed = static_cast<QFutureWatcher<SkydomeResult>*>(watcher);
    if (typed->isCanceled() || typed->future().resultCount() == 0) return;
    const SkydomeResult result = typed->result();
    if (!result.ok()) {
        Q_EMIT failed(id, result.error);
        return;
    }
    const core::scene::Fragment* f = m_document.fragment(id);
    if (!f || QString::fromStdString(f->octreePath.string()) != result.octreePath) return; // gone meanwhile
    if (m_document.replaceOctree(id, result.octree)) Q_EMIT computed(id, result);
}

} // namespace stylos::widgets
