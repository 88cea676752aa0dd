#pragma once
/** @file
 * @brief The annotation lasso of the 3D view (a ViewportTool): a left-button drag draws a closed polygon (shown
 *        as an overlay, the closing edge fainter); the release hands its owner the visible leaves inside it
 *        of the target fragment (core::view::lassoVisibleLeaves: not the back of a drum, not what another
 *        fragment hides), and whether to erase (Ctrl held at the release, or eraser mode). The target is the
 *        selected visible fragment (the first in the view's order), else the fragment under the press.
 *        Escape during the drag cancels it (nothing is handed over); an Alt drag, other buttons and the wheel
 *        are left to navigation. The owner gives the leaves their class in one undo step
 *        (SceneDocument::setLabels); the tool never reads the document. GUI thread only.
 */
#include "stylos/core/view/LassoVisibility.h"
#include "stylos/widgets/view3d/ViewportTool.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

namespace stylos::widgets {

class LassoOverlay;

class LassoTool : public ViewportTool {
public:
    /** Receives the lasso's leaves (one entry per target; may hold no leaves) and whether to erase. */
    using Handler = std::function<void(const std::vector<core::view::LassoLeaves>& hits, bool erase)>;

    explicit LassoTool(Handler onLasso);
    ~LassoTool() override;

    /** @brief Eraser mode: every lasso erases (as with Ctrl). */
    void setErase(bool erase) { m_erase = erase; }
    bool erase() const { return m_erase; }
    /** @brief The polygon being drawn (pixels of the view), empty when none. */
    const std::vector<Eigen::Vector2d>& polygon() const { return m_polygon; }
    /** @brief The fragments a lasso released now on @p view would label (see the file comment). */
    static std::vector<std::uint64_t> targets(const ViewportWidget& view, const Eigen::Vector2d& press);

    void activate(ViewportWidget& view) override;
    void deactivate(ViewportWidget& view) override;
    bool mousePress(ViewportWidget& view, QMouseEvent& event) override;
    bool mouseMove(ViewportWidget& view, QMouseEvent& event) override;
    bool mouseRelease(ViewportWidget& view, QMouseEvent& event) override;
    bool keyPress(ViewportWidget& view, QKeyEvent& event) override;
    QCursor cursor() const override;

private:
    void showPolygon(ViewportWidget& view);

    Handler m_onLasso;
    std::shared_ptr<LassoOverlay> m_overlay;
    std::vector<Eigen::Vector2d> m_polygon;
    bool m_drawing = false;
    bool m_erase = false;
};

} // namespace stylos::widgets
