#include "stylos/widgets/docking/DockRunner.h"

#include "stylos/core/scene/SceneEigen.h"
#include "stylos/widgets/docking/DrumGuidesCache.h"

#include <QUndoStack>

namespace stylos::widgets {

namespace {

Eigen::Isometry3d isometry(const core::scene::Pose& pose)
{
    return Eigen::Isometry3d(core::scene::toEigen(pose));
}

} // namespace

DockRunner::DockRunner(SceneDocument& document, DrumGuidesCache& cache, QObject* parent)
    : QObject(parent), m_document(document), m_cache(cache), m_jobs(document)
{
    connect(&m_cache, &DrumGuidesCache::ready, this, [this](quint64 drum) { guidesReady(drum); });
    connect(&m_cache, &DrumGuidesCache::failed, this,
            [this](quint64 drum, const QString& message) { guidesFailed(drum, message); });
    connect(&m_document, &SceneDocument::fragmentAboutToBeRemoved, this, [this](quint64 id) {
        m_waiting.erase(id);
        m_launched.erase(id); // FragmentJobs cancels its job
        drumGone(id);
    });
    connect(&m_document, &SceneDocument::dockingDrumChanged, this, [this] {
        for (const auto& [id, launched] : std::map(m_launched))
            if (launched.drum != m_document.drumFor(id)) drumGone(launched.drum);
        for (auto it = m_waiting.begin(); it != m_waiting.end();)
            it = it->second != m_document.drumFor(it->first) ? m_waiting.erase(it) : std::next(it);
    });
    connect(&m_document, &SceneDocument::sceneAboutToBeReset, this, [this] {
        m_waiting.clear();
        m_launched.clear();
    });
}

bool DockRunner::canDock(FragmentId id) const
{
    const FragmentId drum = m_document.drumFor(id);
    const core::scene::Fragment* f = m_document.fragment(id);
    const core::scene::Fragment* d = m_document.fragment(drum);
    return f && d && id != drum && DrumGuidesCache::guideOptionsOf(*d).has_value();
}

bool DockRunner::start(FragmentId id)
{
    if (!canDock(id) || !m_document.octree(id) || isRunning(id)) return false;
    const FragmentId drum = m_document.drumFor(id);
    switch (m_cache.request(drum)) {
    case DrumGuidesCache::State::Ready: launch(id, drum); return true;
    case DrumGuidesCache::State::Fitting: m_waiting[id] = drum; return true;
    case DrumGuidesCache::State::Unavailable: return false;
    }
    return false;
}

void DockRunner::launch(FragmentId id, FragmentId drum)
{
    const core::scene::Fragment* f = m_document.fragment(id);
    const core::scene::Fragment* d = m_document.fragment(drum);
    auto guides = m_cache.guides(drum);
    if (!f || !d || !guides) return;
    core::dock::DockOptions options;
    options.locked = m_locked;
    // Where the fragment stands in the drum's frame: scene poses (each composed with its assembly's).
    const core::scene::Pose fragmentPose = m_document.worldPose(id), drumPose = m_document.worldPose(drum);
    const Eigen::Isometry3d start = isometry(drumPose).inverse() * isometry(fragmentPose);
    const DockJob job(QString::fromStdString(f->octreePath.string()), id, drum, std::move(guides), start, options,
                      QString::fromStdString(f->name));
    const Launched launched{drum, fragmentPose, drumPose};
    const auto deliver = [this](FragmentId key, const QFuture<DockJobResult>& future) { delivered(key, future); };
    if (m_jobs.start<DockJobResult>(id, job.label(), job, deliver)) m_launched[id] = launched;
}

void DockRunner::guidesReady(FragmentId drum)
{
    for (const auto& [id, waitingFor] : std::map(m_waiting)) {
        if (waitingFor != drum) continue;
        m_waiting.erase(id);
        if (m_cache.guides(drum)) launch(id, drum);
        else if (!start(id)) // the drum's guides changed while they were fitted: fit again
            Q_EMIT failed(id, tr("The docking drum changed while its guides were fitted"));
    }
}

void DockRunner::guidesFailed(FragmentId drum, const QString& message)
{
    for (const auto& [id, waitingFor] : std::map(m_waiting)) {
        if (waitingFor != drum) continue;
        m_waiting.erase(id);
        Q_EMIT failed(id, message);
    }
}

void DockRunner::drumGone(FragmentId drum)
{
    for (const auto& [id, launched] : std::map(m_launched))
        if (launched.drum == drum) {
            m_launched.erase(id);
            m_jobs.cancel(id);
        }
}

void DockRunner::delivered(FragmentId id, const QFuture<DockJobResult>& future)
{
    const auto it = m_launched.find(id);
    if (it == m_launched.end()) return;
    const Launched launched = it->second;
    m_launched.erase(it);
    if (future.isCanceled() || future.resultCount() == 0) {
        if (const core::scene::Fragment* f = future.isCanceled() ? m_document.fragment(id) : nullptr)
            Q_EMIT cancelled(id, tr("Docking %1 was cancelled").arg(m_document.nameOf(id, QString::fromStdString(f->name))));
        return;
    }
    const DockJobResult result = future.result();
    if (!result.ok()) {
        Q_EMIT failed(id, result.error);
        return;
    }
    const core::scene::Fragment* f = m_document.fragment(id);
    const core::scene::Fragment* d = m_document.fragment(launched.drum);
    if (!f || !d) return;
    const QString name = QString::fromStdString(f->name);
    if (m_document.worldPose(id) != launched.fragmentPose || m_document.worldPose(launched.drum) != launched.drumPose) {
        Q_EMIT failed(id, tr("%1 or the drum moved while it was docked: the dock was not applied").arg(name));
        return;
    }
    const Eigen::Isometry3d inScene = isometry(launched.drumPose) * result.dock.pose;
    const core::scene::Pose pose = core::scene::poseFromEigen(inScene.matrix());
    if (pose != launched.fragmentPose) {
        m_document.beginMacro([this, id, name] { return tr("Dock %1").arg(m_document.nameOf(id, name)); });
        m_document.setFragmentWorldPose(id, pose);
        m_document.endMacro();
    }
    Q_EMIT docked(id, result);
}

} // namespace stylos::widgets
