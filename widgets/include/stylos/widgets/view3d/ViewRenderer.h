#pragma once
/** @file
 * @brief Everything the 3D view draws, behind one GL facade for ViewportWidget: the splats
 *        (PointRenderer), the overlays drawn over them in order (ViewOverlay: the marker, guides, gizmos…),
 *        and the two ways a frame is made —
 *        quick frames (a subsample, enlarged splats; while moving without back faces and optionally at a
 *        reduced resolution) and the full-detail image, drawn offscreen in slices
 *        (drawImageStep) and then copied to the screen (presentImage).
 *
 * Every drawing method needs the widget's GL context current; GUI thread only. Sizes are device
 * pixels; the camera's viewport is in logical pixels (devicePixelRatio converts). Failure modes:
 * initialize() returns false, with log(), without an OpenGL 3.3 core context; without offscreen
 * framebuffers drawImageStep() draws nothing and presentImage() returns false (quick frames remain); an
 * overlay whose initialize() fails is not drawn (one qWarning).
 */
#include "stylos/core/view/Camera.h"
#include "stylos/widgets/view3d/OffscreenFrame.h"
#include "stylos/widgets/view3d/PointRenderer.h"
#include "stylos/widgets/view3d/ViewComposite.h"
#include "stylos/widgets/view3d/ViewOverlay.h"

#include <QColor>
#include <QOpenGLFunctions_3_3_Core>
#include <QSize>
#include <QString>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace stylos::widgets {

class ViewRenderer : protected QOpenGLFunctions_3_3_Core {
public:
    ViewRenderer() = default;
    ViewRenderer(const ViewRenderer&) = delete;
    ViewRenderer& operator=(const ViewRenderer&) = delete;

    bool initialize();
    void release();
    bool isInitialized() const { return m_points.isInitialized(); }
    QString log() const { return m_log; }
    /** @brief The context renders in software (llvmpipe, softpipe, SwiftShader). */
    bool isSoftware() const { return m_software; }

    PointRenderer& points() { return m_points; }
    const PointRenderer& points() const { return m_points; }
    /**
     * @brief Adds @p overlay at the end of the list (drawn last); initialised at once when the renderer is
     *        (context current then), else by initialize(). Adding one already there does nothing.
     */
    void addOverlay(std::shared_ptr<ViewOverlay> overlay);
    /** @brief Releases @p overlay (context current when initialised) and takes it off the list; false when absent. */
    bool removeOverlay(const ViewOverlay* overlay);
    /** @brief The overlays, in drawing order. */
    std::vector<std::shared_ptr<ViewOverlay>> overlays() const;

    /**
     * @brief Resolution of moving frames relative to the view, clamped to [0.1, 1] (default 1). Below 1 the
     *        frame is drawn small and scaled up: fewer fragments, one more full-size copy — on llvmpipe at
     *        1280 × 800 that copy costs more than it saves at the few thousand points a moving frame draws.
     */
    void setMotionResolution(double scale);
    double motionScale() const { return m_motionResolution; }
    void setCullBackFacesWhileMoving(bool cull) { m_cullWhileMoving = cull; }
    /**
     * @brief Whether the composite pass fills the gaps between splats (default true; ViewComposite,
     *        core/view/GapFill.h) when it presents the complete full-detail image; quick frames (moving, or
     *        while the image is drawn) do not.
     */
    void setGapFilling(bool on) { m_gapFill = on; }
    bool gapFilling() const { return m_gapFill; }
    void setGapFillOptions(const core::view::GapFillOptions& options) { m_gapOptions = options; }
    const core::view::GapFillOptions& gapFillOptions() const { return m_gapOptions; }

    /**
     * @brief Clears @p target (of @p size) and draws about @p limit points (0: all) of the visible
     *        fragments, splats enlarged to stand for the rest; @p moving adds the motion shortcuts.
     *        Leaves @p target bound. Returns the points drawn.
     */
    std::uint64_t drawQuick(const core::view::Camera& camera, unsigned target, const QSize& size, double devicePixelRatio,
                            std::uint64_t limit, bool moving);

    /** @brief Starts the full-detail image afresh (nothing drawn yet). */
    void restartImage();
    /** @brief Draws the next slice of about @p points points into the image (@p size); waits for it. */
    std::uint64_t drawImageStep(const core::view::Camera& camera, const QSize& size, double devicePixelRatio, std::uint64_t points);
    bool isImageComplete() const { return m_imageDrawn >= 1.0; }
    std::uint64_t imagePoints() const { return m_imagePoints; }
    /** @brief Copies the complete image into @p target (and binds it); false when there is none. */
    bool presentImage(unsigned target, const QSize& size);

    /** @brief Draws the overlays over the bound framebuffer (of @p size), then waits for the GL to finish. */
    void finishFrame(const core::view::Camera& camera, const QSize& size, double devicePixelRatio);

private:
    struct Overlay {
        std::shared_ptr<ViewOverlay> overlay;
        bool ready = false;   ///< initialised and not released
    };

    void clear(float alpha);
    bool needsComposite() const;
    /** Only the complete image fills gaps (@p fillGaps): quick frames' splats are enlarged, their time steers the
     *  level of detail, and on llvmpipe the pass costs more than such a frame. */
    ViewComposite::Options compositeOptions(bool fillGaps) const;
    void initializeOverlay(Overlay& entry);

    PointRenderer m_points;
    std::vector<Overlay> m_overlays;
    OffscreenFrame m_image;
    OffscreenFrame m_lowRes;            ///< moving frames at a reduced resolution, or for the composite pass
    ViewComposite m_composite;
    std::optional<core::view::Camera> m_imageCamera; ///< the camera m_image is being drawn with
    QString m_log;
    QColor m_background = QColor(33, 36, 41);
    double m_imageDrawn = 0;        ///< fraction of every buffer drawn into m_image
    std::uint64_t m_imagePoints = 0;
    double m_motionResolution = 1;
    bool m_cullWhileMoving = true;
    bool m_gapFill = true;
    core::view::GapFillOptions m_gapOptions;
    bool m_software = false;
};

} // namespace stylos::widgets
