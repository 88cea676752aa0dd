#include "stylos/widgets/skydome/SkydomeRunner.h"

namespace stylos::widgets {

SkydomeRunner::SkydomeRunner(SceneDocument& document, QObject* parent)
    : QObject(parent), m_document(document), m_jobs(document)
{
}

int SkydomeRunner::start(const QList<FragmentId>& ids, const SkydomeOptions& options)
{
    int started = 0;
    for (const FragmentId id : ids) {
        const core::scene::Fragment* f = m_document.fragment(id);
        if (!f || !m_document.octree(id) || isRunning(id)) continue;
        const SkydomeJob job(QString::fromStdString(f->octreePath.string()), id, options, QString::fromStdString(f->name));
        const auto deliver = [this](FragmentId key, const QFuture<SkydomeResult>& future) { delivered(key, future); };
        if (m_jobs.start<SkydomeResult>(id, job.label(), job, deliver)) ++started;
    }
    return started;
}

void SkydomeRunner::delivered(FragmentId id, const QFuture<SkydomeResult>& future)
{
    if (future.isCanceled() || future.resultCount() == 0) return;
    const SkydomeResult result = future.result();
    if (!result.ok()) {
        Q_EMIT failed(id, result.error);
        return;
    }
    if (m_document.replaceOctree(id, result.octree)) Q_EMIT computed(id, result);
}

} // namespace stylos::widgets
