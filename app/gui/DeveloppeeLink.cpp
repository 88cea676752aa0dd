#include "DeveloppeeLink.h"

#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/view/GuideGeometry.h"

#include "stylos/widgets/developpee/AssemblyDeveloppeeJob.h"
#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/developpee/DeveloppeeJob.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/docking/DrumGuidesCache.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QFuture>

#include <algorithm>

namespace stylos::app {

namespace {

/** The axis a fragment unrolls about, in its own frame: its first axis guide; without one, the axis guide of
 *  the drum it docks against (its assembly's, or the docking drum), carried into its frame — so a docked
 *  fragment unrolls about its drum's axis, at the drum's scale, not about a cylinder fitted to itself. */
std::optional<core::unroll::Axis> axisGuide(const widgets::SceneDocument& document, const core::scene::Fragment& fragment)
{
    const auto line = core::scene::unrollAxis(document.scene(), fragment.id, document.drumFor(fragment.id));
    if (!line) return std::nullopt;
    return core::unroll::Axis{line->origin, line->direction};
}

/** The flute lines drawn over a fragment's développée, in its own frame: its own groove guides; without any,
 *  those of the drum it docks against, carried into its frame (the drum's flutes where the fragment lies). */
std::vector<widgets::DeveloppeeView::GuideLine> fluteLines(const widgets::SceneDocument& document,
                                                           const core::scene::Fragment& fragment)
{
    const core::scene::Fragment* source = &fragment;
    core::scene::Pose toFragment;
    const bool own = std::any_of(fragment.guides.begin(), fragment.guides.end(),
                                 [](const core::scene::Guide& g) { return g.kind == core::scene::GuideKind::Groove; });
    if (!own) {
        const core::scene::FragmentId drumId = document.drumFor(fragment.id);
        source = drumId != fragment.id ? document.fragment(drumId) : nullptr;
        if (!source) return {};
        toFragment = document.worldPose(fragment.id).rigidInverse() * document.worldPose(drumId);
    }
    const Eigen::Matrix4d m = core::scene::toEigen(toFragment);
    std::vector<widgets::DeveloppeeView::GuideLine> lines;
    for (const core::scene::Guide& g : source->guides) {
        if (g.kind != core::scene::GuideKind::Groove) continue;
        const core::scene::GuideLine line = core::scene::guideLine(g);
        lines.push_back({m.topLeftCorner<3, 3>() * line.origin + m.topRightCorner<3, 1>(),
                         (m.topLeftCorner<3, 3>() * line.direction).normalized()});
    }
    return lines;
}

} // namespace

DeveloppeeLink::DeveloppeeLink(widgets::SceneDocument& document, widgets::DeveloppeePanel& dock,
                               widgets::ViewportWidget* viewport, QObject* parent)
    : QObject(parent), m_document(document), m_jobs(document), m_dock(dock), m_viewport(viewport)
{
    // Every job's end, delivered or dropped (stale, cancelled, fragment gone): the busy mark follows.
    connect(&m_jobs, &widgets::FragmentJobs::ended, this, [this](quint64 id, bool) {
        if (m_dock.fragmentId() == id) m_dock.setBusy(m_jobs.isRunning(id));
    });
    connect(&dock, &widgets::DeveloppeePanel::computeRequested, this, &DeveloppeeLink::compute);
    connect(dock.view(), &widgets::DeveloppeeView::pointPicked, this, &DeveloppeeLink::markInView);
    connect(dock.view(), &widgets::DeveloppeeView::piecePicked, this, &DeveloppeeLink::fragmentPicked);
    if (viewport)
        connect(viewport, &widgets::ViewportWidget::pointPicked, this,
                [this](const Eigen::Vector3d& p, quint64 id) { markInDeveloppee(p, id); });
    connect(&document, &widgets::SceneDocument::fragmentChanged, this, &DeveloppeeLink::refreshFragment);
    connect(&document, &widgets::SceneDocument::dockingDrumChanged, this, &DeveloppeeLink::refreshFragment);
    connect(&document, &widgets::SceneDocument::fragmentRemoved, this, &DeveloppeeLink::refreshFragment);
    connect(&document, &widgets::SceneDocument::sceneReset, this, [this] {
        m_dock.clearResult();
        refreshFragment();
    });
}

void DeveloppeeLink::setFragment(core::scene::FragmentId id)
{
    const bool changed = id != m_fragment;
    m_fragment = id;
    refreshFragment();
    if (!changed) return;
    if (const auto stored = m_document.developpee(id)) m_dock.showResult(*stored);
    else m_dock.clearResult();
    m_dock.setBusy(m_jobs.isRunning(id));
}

void DeveloppeeLink::showAssembly(core::scene::AssemblyId id)
{
    const core::scene::Assembly* assembly = m_document.assembly(id);
    const auto stored = assembly ? m_document.developpee(assembly->drum) : nullptr;
    setFragment(core::scene::NoFragment);
    if (!stored || !stored->pieceAt) return; // the drum's own développée, or none: not the assembly's
    m_dock.showResult(*stored);
    m_dock.setBusy(m_jobs.isRunning(assembly->drum));
}

void DeveloppeeLink::refreshFragment()
{
    const core::scene::Fragment* f = m_document.fragment(m_fragment);
    if (!f) {
        m_dock.setFragment(0, QString());
        m_dock.view()->setGuideLines({});
        if (m_dock.view()->hasDeveloppee()) m_dock.clearResult(); // its fragment is gone
        return;
    }
    m_dock.setFragment(f->id, QString::fromStdString(f->name), axisGuide(m_document, *f));
    m_dock.view()->setGuideLines(fluteLines(m_document, *f));
}

void DeveloppeeLink::setGuidesCache(widgets::DrumGuidesCache* cache)
{
    if (m_cache) disconnect(m_cache, nullptr, this, nullptr);
    m_cache = cache;
    if (!cache) return;
    connect(cache, &widgets::DrumGuidesCache::ready, this, [this](quint64 drum) { guidesArrived(drum, false); });
    connect(cache, &widgets::DrumGuidesCache::failed, this, [this](quint64 drum, const QString&) { guidesArrived(drum, true); });
}

core::scene::FragmentId DeveloppeeLink::guidesOwner(const core::scene::Fragment& fragment) const
{
    return core::scene::unrollAxisOwner(m_document.scene(), fragment.id, m_document.drumFor(fragment.id));
}

bool DeveloppeeLink::leadingRadius(core::scene::FragmentId owner, widgets::DeveloppeeSettings& settings)
{
    settings.radius.reset();
    settings.radiusSlope.reset();
    if (!m_cache || owner == core::scene::NoFragment || owner == m_fitFailed) return true;
    switch (m_cache->request(owner)) {
    case widgets::DrumGuidesCache::State::Ready:
        settings.radius = m_cache->guides(owner)->radius;
        settings.radiusSlope = m_cache->guides(owner)->slope; // a tapering drum unrolls on its cone
        return true;
    case widgets::DrumGuidesCache::State::Fitting: return false;
    case widgets::DrumGuidesCache::State::Unavailable: return true;
    }
    return true;
}

void DeveloppeeLink::guidesArrived(core::scene::FragmentId owner, bool failed)
{
    if (failed) m_fitFailed = owner;
    if (!m_waiting || m_waiting->owner != owner) return;
    const Waiting waiting = *m_waiting;
    m_waiting.reset();
    m_dock.setBusy(m_jobs.isRunning(m_dock.fragmentId()));
    if (waiting.assembly != core::scene::NoAssembly) computeAssembly(waiting.assembly);
    else if (waiting.fragment == m_dock.fragmentId()) compute();
}

void DeveloppeeLink::compute()
{
    const core::scene::Fragment* f = m_document.fragment(m_dock.fragmentId());
    if (!f || m_jobs.isRunning(f->id)) return;
    const core::scene::FragmentId id = f->id;
    widgets::DeveloppeeSettings settings = m_dock.settings();
    if (settings.axis) {
        const core::scene::FragmentId owner = guidesOwner(*f);
        if (!leadingRadius(owner, settings)) { // the guides are being fitted: compute when they are in
            m_waiting = Waiting{owner, id, core::scene::NoAssembly};
            m_dock.setBusy(true);
            return;
        }
    }
    const widgets::DeveloppeeJob job(QString::fromStdString(f->octreePath.string()), id, settings);
    const QString name = QString::fromStdString(f->name);
    // A fragment unrolled about its drum's axis must stand where it belongs on the drum: when fewer than a tenth of
    // its cells (at a coarse level) lie within a sixth of the drum's radius of the drum's surface, it does not (not
    // docked yet). The drum's radius: its guides' leading radius, else half its box's wider horizontal side.
    bool offDrum = false;
    const core::scene::FragmentId owner = guidesOwner(*f);
    if (settings.axis && owner != id && owner != core::scene::NoFragment)
        if (const auto octree = m_document.octree(id), drum = m_document.octree(owner); octree && drum) {
            const Eigen::Vector3d along = settings.axis->direction.normalized();
            const Eigen::Vector3d drumSize = core::view::occupiedBounds(*drum).sizes();
            const double radius = settings.radius.value_or(0.5 * std::max(drumSize.x(), drumSize.y()));
            std::uint64_t cells = 0, near = 0;
            octree->forEachCell(std::min(octree->depth(), 7), [&](const core::octree::CellView& c) {
                const Eigen::Vector3d off = Eigen::Vector3d(c.centre[0], c.centre[1], c.centre[2]) - settings.axis->point;
                ++cells;
                near += std::abs((off - off.dot(along) * along).norm() - radius) <= radius / 6.0 ? 1 : 0;
                return true;
            });
            offDrum = cells > 0 && near * 10 < cells;
        }
    const auto deliver = [this, name, offDrum](core::scene::FragmentId key, const QFuture<widgets::DeveloppeeResult>& future) {
        if (future.resultCount() == 0) { // cancelled from the Tasks dock
            Q_EMIT finished(tr("Développée of %1 cancelled").arg(name), false);
            return;
        }
        const widgets::DeveloppeeResult result = future.result();
        if (result.ok()) m_document.setDeveloppee(key, std::make_shared<const widgets::DeveloppeeResult>(result));
        if (m_dock.fragmentId() == key) m_dock.showResult(result);
        if (result.ok()) Q_EMIT finished(widgets::DeveloppeePanel::fitSummary(result), false);
        else if (offDrum)
            Q_EMIT finished(tr("%1 is unrolled about its drum's axis guide and does not stand on the drum yet: dock it "
                               "first, or untick Use the axis guide to unroll it about a cylinder fitted to itself.")
                                    .arg(name) + QLatin1Char('\n') + result.error,
                            true);
        else Q_EMIT finished(result.error, true);
    };
    if (m_jobs.start<widgets::DeveloppeeResult>(id, job.label(), job, deliver)) m_dock.setBusy(true);
}

bool DeveloppeeLink::computeAssembly(core::scene::AssemblyId id)
{
    const core::scene::Assembly* assembly = m_document.assembly(id);
    if (!assembly) return false;
    const QString name = QString::fromStdString(assembly->name);
    const core::scene::Fragment* drum = m_document.fragment(assembly->drum);
    const auto axis = drum ? core::scene::firstGuide(*drum, core::scene::GuideKind::Axis) : std::nullopt;
    if (!axis) {
        Q_EMIT finished(tr("The développée of %1 needs a drum with an axis guide (Use as the assembly's drum)").arg(name), true);
        return false;
    }
    const core::scene::FragmentId drumId = drum->id;
    const Eigen::Isometry3d drumWorld(core::scene::toEigen(m_document.worldPose(drumId)));
    std::vector<widgets::AssemblyDeveloppeeJob::Piece> pieces;
    for (core::scene::FragmentId member : m_document.scene().membersOf(id)) {
        if (member == drumId) continue;
        const core::scene::Fragment* f = m_document.fragment(member);
        if (!f || !m_document.octree(member) || !m_document.isShown(member)) continue;
        const Eigen::Isometry3d world(core::scene::toEigen(m_document.worldPose(member)));
        pieces.push_back({QString::fromStdString(f->octreePath.string()), drumWorld.inverse() * world, member});
    }
    if (!m_document.octree(drumId) || m_jobs.isRunning(drumId)) {
        Q_EMIT finished(tr("The développée of %1 cannot start: its drum is still opening or busy").arg(name), true);
        return false;
    }
    widgets::DeveloppeeSettings settings = m_dock.settings();
    if (!leadingRadius(drumId, settings)) {
        m_waiting = Waiting{drumId, core::scene::NoFragment, id};
        m_dock.setBusy(true);
        return true;
    }
    const widgets::AssemblyDeveloppeeJob job(QString::fromStdString(drum->octreePath.string()), drumId,
                                             core::unroll::Axis{axis->origin, axis->direction}, std::move(pieces),
                                             settings, name);
    const auto deliver = [this, name](core::scene::FragmentId key, const QFuture<widgets::DeveloppeeResult>& future) {
        if (future.resultCount() == 0) {
            Q_EMIT finished(tr("Développée of %1 cancelled").arg(name), false);
            return;
        }
        const widgets::DeveloppeeResult result = future.result();
        if (result.ok()) m_document.setDeveloppee(key, std::make_shared<const widgets::DeveloppeeResult>(result));
        m_dock.showResult(result);
        if (result.ok()) Q_EMIT finished(tr("Développée of %1: %2").arg(name, widgets::DeveloppeePanel::fitSummary(result)), false);
        else Q_EMIT finished(result.error, true);
    };
    const bool started = m_jobs.start<widgets::DeveloppeeResult>(drumId, job.label(), job, deliver);
    if (started) m_dock.setBusy(true);
    return started;
}

void DeveloppeeLink::markInView(quint64 fragmentId, const Eigen::Vector3d& octreePoint)
{
    const core::scene::Fragment* f = m_document.fragment(fragmentId);
    if (!f || !m_viewport) return;
    m_viewport->setMarker(core::scene::apply(m_document.worldPose(f->id), octreePoint));
}

void DeveloppeeLink::markInDeveloppee(const Eigen::Vector3d& scenePoint, core::scene::FragmentId id)
{
    widgets::DeveloppeeView* view = m_dock.view();
    const core::scene::Fragment* f = m_document.fragment(id);
    if (!f || !view->hasDeveloppee() || view->fragmentId() != id) {
        view->setMarker(std::nullopt);
        return;
    }
    view->setMarker(core::scene::apply(m_document.worldPose(f->id).rigidInverse(), scenePoint));
}

} // namespace stylos::app
