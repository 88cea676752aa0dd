#include "stylos/widgets/docking/GuideFitRunner.h"

namespace stylos::widgets {

GuideFitRunner::GuideFitRunner(SceneDocument& document, QObject* parent)
    : QObject(parent), m_document(document), m_jobs(document)
{
}

bool GuideFitRunner::start(FragmentId id, const core::dock::GuideOptions& options)
{
    const core::scene::Fragment* f = m_document.fragment(id);
    if (!f || !m_document.octree(id) || isRunning(id)) return false;
    const GuideFitJob job(QString::fromStdString(f->octreePath.string()), id, options, QString::fromStdString(f->name));
    const auto deliver = [this](FragmentId key, const QFuture<GuideFitResult>& future) { delivered(key, future); };
    return m_jobs.start<GuideFitResult>(id, job.label(), job, deliver) != nullptr;
}

bool GuideFitRunner::deleteGuides(FragmentId id)
{
    const core::scene::Fragment* f = m_document.fragment(id);
    if (!f || f->guides.empty()) return false;
    return m_document.setFragmentGuides(id, {},
                                       [this, id, n = QString::fromStdString(f->name)] {
                                           return tr("Delete the guides of %1").arg(m_document.nameOf(id, n));
                                       });
}

void GuideFitRunner::delivered(FragmentId id, const QFuture<GuideFitResult>& future)
{
    if (future.isCanceled() || future.resultCount() == 0) {
        if (const core::scene::Fragment* f = future.isCanceled() ? m_document.fragment(id) : nullptr)
            Q_EMIT cancelled(id, tr("Fitting the guides of %1 was cancelled").arg(m_document.nameOf(id, QString::fromStdString(f->name))));
        return;
    }
    const GuideFitResult result = future.result();
    if (!result.ok()) {
        Q_EMIT failed(id, result.error);
        return;
    }
    const core::scene::Fragment* f = m_document.fragment(id);
    if (!f) return;
    m_document.setFragmentGuides(id, result.guides,
                               [this, id, n = QString::fromStdString(f->name)] {
                                   return tr("Fit the guides of %1").arg(m_document.nameOf(id, n));
                               });
    Q_EMIT fitted(id, result);
}

} // namespace stylos::widgets
