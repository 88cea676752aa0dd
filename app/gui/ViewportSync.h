#pragma once
/** @file
 * @brief Keeps the 3D view showing the scene document: after any change of the fragments (added, removed,
 *        moved, recoloured, hidden, their octree opened or replaced) or of the selection, it hands the view
 *        one core::view::ViewFragment per fragment with an octree. Changes arriving in one turn of the event
 *        loop are pushed once. When only poses changed (a fragment dragged, a pose typed, undone or redone),
 *        only the poses are pushed (ViewportWidget::setFragmentPose: a new model matrix, no new cut); when
 *        nothing the view shows changed, nothing is pushed. The view never reads the document. GUI thread only.
 */
#include "stylos/core/scene/Fragment.h"

#include <QList>
#include <QObject>
#include <QPointer>

namespace stylos::widgets {
class SceneDocument;
class ViewportWidget;
} // namespace stylos::widgets

namespace stylos::app {

class ViewportSync : public QObject {
    Q_OBJECT

public:
    /** Observes @p document (not owned, must outlive this) and feeds @p viewport (may be destroyed first). */
    ViewportSync(widgets::SceneDocument& document, widgets::ViewportWidget& viewport, QObject* parent = nullptr);

    /** @brief The fragments drawn highlighted (the Scene dock's selection). */
    void setSelection(const QList<core::scene::FragmentId>& ids);

    /** @brief Pushes the fragments now (normally done on the next turn of the event loop). */
    void pushNow();

private:
    void schedule();

    widgets::SceneDocument& m_document;
    QPointer<widgets::ViewportWidget> m_viewport;
    QList<core::scene::FragmentId> m_selection;
    bool m_scheduled = false;
};

} // namespace stylos::app
