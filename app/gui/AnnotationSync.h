#pragma once
/** @file
 * @brief Keeps the 3D view's annotation tint showing the document's labels: for the chosen layer (material or
 *        tool mark), each fragment's labels array (SceneDocument::labels()) and the legend's colours. Label
 *        changes arriving in one turn of the event loop are pushed once, per fragment only the range between
 *        the lowest and the highest leaf touched (ViewportWidget::updateLabels: a glBufferSubData, the splats
 *        untouched), a whole array when it was loaded or the layer changed. The view never reads the
 *        document. GUI thread only.
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/scene/Fragment.h"
#include "stylos/widgets/view3d/PointRenderer.h"

#include <QObject>
#include <QPointer>

#include <cstdint>
#include <map>
#include <vector>

namespace stylos::widgets {
class SceneDocument;
class ViewportWidget;
} // namespace stylos::widgets

namespace stylos::app {

class AnnotationSync : public QObject {
    Q_OBJECT

public:
    using Layer = core::annotation::AnnotationLayer;

    /** Observes @p document (not owned, must outlive this) and feeds @p viewport (may be destroyed first). */
    AnnotationSync(widgets::SceneDocument& document, widgets::ViewportWidget& viewport, QObject* parent = nullptr);

    /** @brief The layer the view tints by (and the lasso labels); default Material. */
    void setLayer(Layer layer);
    Layer layer() const { return m_layer; }

    /** @brief The legend's colours of @p layer per class id (alpha 255 for a class, 0 otherwise). */
    static widgets::PointRenderer::ClassColours classColours(const core::annotation::Legend& legend, Layer layer);

    /** @brief Pushes what changed now (normally done on the next turn of the event loop). */
    void pushNow();

Q_SIGNALS:
    void layerChanged(int layer);

private:
    /** Leaves [first, last] of a fragment changed; all of them when whole. */
    struct Range {
        bool whole = false;
        std::uint32_t first = 0;
        std::uint32_t last = 0;
    };
    void labelsChanged(quint64 fragment, int layer, const std::vector<std::uint32_t>& leaves);
    void everything();
    void schedule();

    widgets::SceneDocument& m_document;
    QPointer<widgets::ViewportWidget> m_viewport;
    Layer m_layer = Layer::Material;
    std::map<core::scene::FragmentId, Range> m_changes;
    bool m_all = false;      ///< every fragment's labels again (a layer or project change)
    bool m_legend = true;    ///< the colours again
    bool m_scheduled = false;
};

} // namespace stylos::app
