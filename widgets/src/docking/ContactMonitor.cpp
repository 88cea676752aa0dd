#include "stylos/widgets/docking/ContactMonitor.h"

#include "stylos/core/scene/SceneEigen.h"
#include "stylos/widgets/docking/ContactJob.h"
#include "stylos/widgets/docking/DrumGuidesCache.h"

#include <QTimer>

namespace stylos::widgets {

ContactMonitor::ContactMonitor(SceneDocument& document, DrumGuidesCache& cache, QObject* parent)
    : QObject(parent), m_document(document), m_cache(cache), m_jobs(document), m_timer(new QTimer(this))
{
    m_timer->setSingleShot(true);
    m_timer->setInterval(300);
    connect(m_timer, &QTimer::timeout, this, &ContactMonitor::measure);
    const auto concerns = [this](quint64 id) {
        if (id == m_fragment || id == m_document.drumFor(m_fragment)) return true;
        const core::scene::Fragment *f = m_document.fragment(m_fragment), *other = m_document.fragment(id);
        return f && other && f->assembly != core::scene::NoAssembly && other->assembly == f->assembly;
    };
    connect(&m_document, &SceneDocument::fragmentChanged, this, [this, concerns](quint64 id) {
        if (concerns(id)) schedule();
    });
    connect(&m_document, &SceneDocument::octreeChanged, this, [this, concerns](quint64 id) {
        if (concerns(id)) schedule();
    });
    connect(&m_document, &SceneDocument::fragmentRemoved, this, [this](quint64 id) {
        if (id == m_fragment) m_fragment = core::scene::NoFragment;
        schedule();
    });
    connect(&m_document, &SceneDocument::dockingDrumChanged, this, &ContactMonitor::schedule);
    connect(&m_document, &SceneDocument::assemblyChanged, this, &ContactMonitor::schedule); // its drum or pose
    connect(&m_document, &SceneDocument::structureChanged, this, &ContactMonitor::schedule); // its members
    connect(&m_document, &SceneDocument::sceneReset, this, [this] { setFragment(core::scene::NoFragment); });
    connect(&m_cache, &DrumGuidesCache::ready, this, [this](quint64 drum) {
        if (drum == m_document.drumFor(m_fragment)) schedule();
    });
    connect(&m_cache, &DrumGuidesCache::failed, this, [this](quint64 drum, const QString& message) {
        if (drum == m_document.drumFor(m_fragment) && m_state == State::Computing) setState(State::Failed, message);
    });
}

void ContactMonitor::setFragment(FragmentId id)
{
    if (id == m_fragment) return;
    m_jobs.cancel(m_fragment);
    m_fragment = id;
    schedule();
}

void ContactMonitor::setDelay(int milliseconds) { m_timer->setInterval(milliseconds); }

int ContactMonitor::delay() const { return m_timer->interval(); }

std::optional<Eigen::Isometry3d> ContactMonitor::relativePose() const
{
    const core::scene::Fragment* f = m_document.fragment(m_fragment);
    const core::scene::Fragment* d = m_document.fragment(m_document.drumFor(m_fragment));
    if (!f || !d || f->id == d->id) return std::nullopt;
    return Eigen::Isometry3d(core::scene::toEigen(m_document.worldPose(d->id))).inverse() *
           Eigen::Isometry3d(core::scene::toEigen(m_document.worldPose(f->id)));
}

std::vector<ContactJob::Other> ContactMonitor::others() const
{
    std::vector<ContactJob::Other> list;
    const core::scene::Fragment* f = m_document.fragment(m_fragment);
    if (!f || f->assembly == core::scene::NoAssembly) return list;
    const FragmentId drum = m_document.drumFor(m_fragment);
    const Eigen::Isometry3d toFragment =
        Eigen::Isometry3d(core::scene::toEigen(m_document.worldPose(m_fragment))).inverse();
    for (FragmentId id : m_document.scene().membersOf(f->assembly)) {
        const core::scene::Fragment* other = m_document.fragment(id);
        if (id == m_fragment || id == drum || !other || !m_document.octree(id)) continue;
        list.push_back({QString::fromStdString(other->octreePath.string()), id, QString::fromStdString(other->name),
                        toFragment * Eigen::Isometry3d(core::scene::toEigen(m_document.worldPose(id)))});
    }
    return list;
}

void ContactMonitor::schedule()
{
    const core::scene::Fragment* d = m_document.fragment(m_document.drumFor(m_fragment));
    if (!relativePose() || !d || !DrumGuidesCache::guideOptionsOf(*d)) {
        m_timer->stop();
        m_jobs.cancel(m_fragment);
        setState(State::Off);
        return;
    }
    setState(State::Computing);
    m_timer->start();
}

void ContactMonitor::measure()
{
    const FragmentId drum = m_document.drumFor(m_fragment);
    const auto pose = relativePose();
    const core::scene::Fragment* f = m_document.fragment(m_fragment);
    if (!pose || !f) return setState(State::Off);
    if (!m_document.octree(m_fragment)) return; // octreeChanged() schedules again once it is open
    switch (m_cache.request(drum)) {
    case DrumGuidesCache::State::Ready: break;
    case DrumGuidesCache::State::Fitting: return; // ready() schedules again
    case DrumGuidesCache::State::Unavailable: return setState(State::Off);
    }
    m_jobs.cancel(m_fragment); // an older pose's readout is of no use any more
    ContactJob job(QString::fromStdString(f->octreePath.string()), m_fragment, drum, m_cache.guides(drum), *pose,
                   QString::fromStdString(f->name));
    auto list = others();
    m_measuredOthers.clear();
    for (const ContactJob::Other& other : list) m_measuredOthers.emplace_back(other.id, other.toFragment.matrix());
    job.setOthers(std::move(list));
    m_jobs.start<ContactJobResult>(m_fragment, job.label(), job, [this](FragmentId, const QFuture<ContactJobResult>& future) {
        if (!future.isCanceled() && future.resultCount() > 0) delivered(future.result());
    });
}

void ContactMonitor::delivered(const ContactJobResult& result)
{
    // Stale: another fragment, another drum, or a pose that has changed since (a new job is on its way).
    const auto pose = relativePose();
    if (result.fragmentId != m_fragment || result.drumId != m_document.drumFor(m_fragment) || !pose ||
        pose->matrix() != result.pose.matrix())
        return;
    std::vector<std::pair<quint64, Eigen::Matrix4d>> now;
    for (const ContactJob::Other& other : others()) now.emplace_back(other.id, other.toFragment.matrix());
    if (now != m_measuredOthers) return; // a member has moved since: its own readout is on its way
    ++m_deliveries;
    if (!result.ok()) return setState(State::Failed, result.error);
    m_readout = result.readout;
    m_members = result.members;
    setState(State::Ready);
}

void ContactMonitor::setState(State state, const QString& message)
{
    if (state == m_state && message == m_message && state != State::Ready) return;
    m_state = state;
    m_message = message;
    Q_EMIT changed();
}

} // namespace stylos::widgets
