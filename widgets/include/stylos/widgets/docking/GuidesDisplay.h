#pragma once
/** @file
 * @brief Keeps the 3D view showing every visible fragment's guides (its Axis and Groove guides, through its
 *        pose, over its extent) as an overlay, following the document: changes arriving in one turn of the event
 *        loop are pushed once, and a new frame is requested. setVisible() hides them ("Show guides").
 *        GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"

#include <QObject>
#include <QPointer>

#include <memory>

namespace stylos::widgets {

class FragmentBounds;
class GuidesOverlay;
class ViewportWidget;

class GuidesDisplay : public QObject {
    Q_OBJECT

public:
    /** None owned; @p document must outlive this; @p view may go first. The overlay is added at once. */
    GuidesDisplay(SceneDocument& document, ViewportWidget& view, QObject* parent = nullptr);
    ~GuidesDisplay() override;

    void setVisible(bool visible);
    bool isVisible() const;
    /** @brief Guide segments drawn (after the last push). */
    int segmentCount() const;
    /** @brief Pushes the guides now (normally on the next turn of the event loop). */
    void pushNow();

private:
    void schedule();

    SceneDocument& m_document;
    QPointer<ViewportWidget> m_view;
    std::shared_ptr<GuidesOverlay> m_overlay;
    std::unique_ptr<FragmentBounds> m_bounds;
    bool m_scheduled = false;
};

} // namespace stylos::widgets
