#include "DeveloppeeLink.h"

#include "stylos/widgets/DeveloppeeDock.h"
#include "stylos/widgets/DeveloppeeJob.h"
#include "stylos/widgets/DeveloppeeView.h"
#include "stylos/widgets/SceneDocument.h"
#include "stylos/widgets/TaskManager.h"
#include "stylos/widgets/ViewportWidget.h"

#include <QFutureWatcher>

namespace stylos::app {

namespace {

Eigen::Vector3d toEigen(const std::array<double, 3>& p) { return {p[0], p[1], p[2]}; }
std::array<double, 3> toArray(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

/** The fragment's first axis guide, in its own frame. */
std::optional<core::unroll::Axis> axisGuide(const core::scene::Fragment& fragment)
{
    for (const core::scene::Guide& guide : fragment.guides)
        if (guide.kind == core::scene::GuideKind::Axis) return core::unroll::Axis{toEigen(guide.origin), toEigen(guide.direction)};
    return std::nullopt;
}

} // namespace

DeveloppeeLink::DeveloppeeLink(widgets::SceneDocument& document, widgets::TaskManager& tasks,
                               widgets::DeveloppeeDock& dock, widgets::ViewportWidget* viewport, QObject* parent)
    : QObject(parent), m_document(document), m_tasks(tasks), m_dock(dock), m_viewport(viewport)
{
    connect(&dock, &widgets::DeveloppeeDock::computeRequested, this, &DeveloppeeLink::compute);
    connect(dock.view(), &widgets::DeveloppeeView::pointPicked, this, &DeveloppeeLink::markInView);
    if (viewport)
        connect(viewport, &widgets::ViewportWidget::pointPicked, this,
                [this](const Eigen::Vector3d& p, quint64 id) { markInDeveloppee(p, id); });
    connect(&document, &widgets::SceneDocument::fragmentChanged, this, &DeveloppeeLink::refreshFragment);
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
    m_dock.setBusy(m_computing.count(id) != 0);
}

void DeveloppeeLink::refreshFragment()
{
    const core::scene::Fragment* f = m_document.fragment(m_fragment);
    if (!f) {
        m_dock.setFragment(0, QString());
        if (m_dock.view()->hasDeveloppee()) m_dock.clearResult(); // its fragment is gone
        return;
    }
    m_dock.setFragment(f->id, QString::fromStdString(f->name), axisGuide(*f));
}

void DeveloppeeLink::compute()
{
    const core::scene::Fragment* f = m_document.fragment(m_dock.fragmentId());
    if (!f || m_computing.count(f->id) != 0) return;
    const core::scene::FragmentId id = f->id;
    const widgets::DeveloppeeJob job(QString::fromStdString(f->octreePath.string()), id, m_dock.settings());
    m_computing.insert(id);
    m_dock.setBusy(true);
    auto* watcher = m_tasks.start<widgets::DeveloppeeResult>(job.label(), job);
    const QString name = QString::fromStdString(f->name);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, name, id] {
        m_computing.erase(id);
        const bool shown = m_dock.fragmentId() == id;
        if (watcher->future().resultCount() == 0) { // cancelled
            if (shown) m_dock.setBusy(false);
            Q_EMIT finished(tr("Développée of %1 cancelled").arg(name), false);
            return;
        }
        const widgets::DeveloppeeResult result = watcher->future().result();
        if (result.ok()) m_document.setDeveloppee(id, std::make_shared<const widgets::DeveloppeeResult>(result));
        if (shown) m_dock.showResult(result);
        if (result.ok()) Q_EMIT finished(widgets::DeveloppeeDock::fitSummary(result), false);
        else Q_EMIT finished(result.error, true);
    });
}

void DeveloppeeLink::markInView(quint64 fragmentId, const Eigen::Vector3d& octreePoint)
{
    const core::scene::Fragment* f = m_document.fragment(fragmentId);
    if (!f || !m_viewport) return;
    m_viewport->setMarker(toEigen(f->pose.apply(toArray(octreePoint))));
}

void DeveloppeeLink::markInDeveloppee(const Eigen::Vector3d& scenePoint, core::scene::FragmentId id)
{
    widgets::DeveloppeeView* view = m_dock.view();
    const core::scene::Fragment* f = m_document.fragment(id);
    if (!f || !view->hasDeveloppee() || view->fragmentId() != id) {
        view->setMarker(std::nullopt);
        return;
    }
    view->setMarker(toEigen(f->pose.rigidInverse().apply(toArray(scenePoint))));
}

} // namespace stylos::app
