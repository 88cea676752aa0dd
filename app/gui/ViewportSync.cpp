#include "ViewportSync.h"

#include "stylos/core/scene/SceneEigen.h"

#include "stylos/core/view/ViewFragment.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QTimer>

namespace stylos::app {

ViewportSync::ViewportSync(widgets::SceneDocument& document, widgets::ViewportWidget& viewport, QObject* parent)
    : QObject(parent), m_document(document), m_viewport(&viewport)
{
    using widgets::SceneDocument;
    connect(&document, &SceneDocument::fragmentAdded, this, &ViewportSync::schedule);
    connect(&document, &SceneDocument::fragmentRemoved, this, &ViewportSync::schedule);
    connect(&document, &SceneDocument::fragmentChanged, this, &ViewportSync::schedule);
    connect(&document, &SceneDocument::octreeChanged, this, &ViewportSync::schedule);
    connect(&document, &SceneDocument::sceneReset, this, &ViewportSync::schedule);
    schedule();
}

void ViewportSync::setSelection(const QList<core::scene::FragmentId>& ids)
{
    if (ids == m_selection) return;
    m_selection = ids;
    schedule();
}

void ViewportSync::schedule()
{
    if (m_scheduled) return;
    m_scheduled = true;
    QTimer::singleShot(0, this, &ViewportSync::pushNow);
}

void ViewportSync::pushNow()
{
    m_scheduled = false;
    if (!m_viewport) return;
    std::vector<core::view::ViewFragment> fragments;
    for (const core::scene::Fragment& f : m_document.scene().fragments()) {
        auto octree = m_document.octree(f.id);
        if (!octree) continue;
        core::view::ViewFragment r;
        r.id = f.id;
        r.octree = std::move(octree);
        r.pose = core::scene::toEigen(m_document.worldPose(f.id));
        r.colour = {f.colour.r, f.colour.g, f.colour.b};
        r.visible = m_document.isShown(f.id);
        r.selected = m_selection.contains(f.id);
        fragments.push_back(std::move(r));
    }
    // A pose alone moves its fragment in the view (no new cut); anything else replaces the fragments.
    if (const auto poses = core::view::poseChanges(m_viewport->fragments(), fragments)) {
        for (const core::view::PoseChange& change : *poses) m_viewport->setFragmentPose(change.id, change.pose);
        return;
    }
    m_viewport->setFragments(std::move(fragments));
}

} // namespace stylos::app
