#include "stylos/widgets/tasks/FragmentJobs.h"

namespace stylos::widgets {

FragmentJobs::FragmentJobs(SceneDocument& document, QObject* parent) : QObject(parent), m_document(document)
{
    // Another project: its fragments may reuse the ids, so nothing of the old one may be delivered.
    connect(&m_document, &SceneDocument::sceneAboutToBeReset, this, &FragmentJobs::cancelAll);
    connect(&m_document, &SceneDocument::fragmentAboutToBeRemoved, this, [this](quint64 id) { cancel(id); });
}

std::optional<QString> FragmentJobs::octreePathOf(FragmentId id) const
{
    const core::scene::Fragment* f = m_document.fragment(id);
    if (!f) return std::nullopt;
    return QString::fromStdString(f->octreePath.string());
}

void FragmentJobs::track(FragmentId id, const QString& path, QFutureWatcherBase* watcher,
                         std::function<void(FragmentId)> deliver)
{
    m_running[id] = Entry{watcher, path};
    connect(watcher, &QFutureWatcherBase::finished, this,
            [this, id, watcher, deliver = std::move(deliver)] { finished(id, watcher, deliver); });
}

void FragmentJobs::cancel(FragmentId id)
{
    const auto it = m_running.find(id);
    if (it == m_running.end()) return;
    QFutureWatcherBase* watcher = it->second.watcher;
    m_running.erase(it); // its end is no longer ours to deliver
    if (watcher) watcher->cancel();
}

void FragmentJobs::cancelAll()
{
    while (!m_running.empty()) cancel(m_running.begin()->first);
}

void FragmentJobs::finished(FragmentId id, QFutureWatcherBase* watcher, const std::function<void(FragmentId)>& deliver)
{
    const auto it = m_running.find(id);
    const bool ours = it != m_running.end() && it->second.watcher == watcher;
    const QString path = ours ? it->second.octreePath : QString();
    if (ours) m_running.erase(it);
    // Current only while the same fragment still reads the same file (ids restart in every project).
    const bool current = ours && octreePathOf(id) == path;
    if (current) deliver(id);
    Q_EMIT ended(id, current);
}

} // namespace stylos::widgets
