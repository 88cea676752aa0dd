#pragma once
/** @file
 * @brief The 3D view: a thin QWidget that forwards to the camera (core::view::Camera), the LodScheduler
 *        (which cells to draw, computed in the background), the tools (what input does) and the ViewRenderer
 *        (the points, then the overlays). It only hands input to its tools, and paints: into a native
 *        OpenGL 3.3 core window (ViewportWindow) shown
 *        in it through QWidget::createWindowContainer, which draws and swaps straight to the screen —
 *        no QOpenGLWidget composition into the top-level window (tens of ms a frame on llvmpipe).
 *        That window is transparent for input: this widget receives the mouse, the wheel and the keys,
 *        and holds the focus (its actions' shortcuts work as for any widget). QWidget::grab() does not
 *        capture the native window: grabFramebuffer() does.
 *
 * Input: each mouse, wheel and key event goes first to the tool set with setTool() (a gizmo, a pick tool,
 * a lasso; see ViewportTool), then, when that tool does not consume it, to navigation (NavigationTool:
 * orbit, pan, dolly, a click picks the surface point under the cursor — core::view::pickScene, a few
 * pixels wide —, marks it and emits pointPicked(); hovering emits cursorMoved(); the view keys).
 * Overlays: addOverlay() puts a ViewOverlay over the points, drawn on every frame after them; the marker
 * (setMarker) is the first.
 * Poses: setFragmentPose() moves one fragment — its model matrix and a redraw, no new cut until the poses
 * stop changing (see LodScheduler); setFragments() replaces everything and recomputes the cut.
 *
 * Frames: while the camera moves, each paint draws an even subsample of the cuts (LodScheduler::drawLimit()
 * points, splats enlarged) without the back faces, so that a frame stays near the target time (the frame
 * time measured includes the swap of the native window). When it stops, the full-detail
 * image is drawn offscreen in slices, each a short step on the GUI thread between events (sized to take
 * about the target frame time), while the last image stays on screen; it is shown when complete, and
 * again after each refinement stage.
 *
 * The scene frame is the fragments' common frame (core::view::ViewFragment::pose maps each octree into it), +Z up.
 * Units: metres; positions in signals are in the scene frame, double precision. GUI thread only.
 */
#include "stylos/core/view/Camera.h"
#include "stylos/core/view/ScenePick.h"
#include "stylos/core/view/ViewFragment.h"
#include "stylos/widgets/view3d/LodScheduler.h"
#include "stylos/widgets/view3d/NavigationTool.h"
#include "stylos/widgets/view3d/PointRenderer.h"
#include "stylos/widgets/view3d/ViewRenderer.h"

#include <QElapsedTimer>
#include <QImage>
#include <QMetaType>
#include <QWidget>
#include <QPoint>
#include <QTimer>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace stylos::widgets {

class MarkerOverlay;
class ViewOverlay;
class ViewportTool;
class ViewportWindow;

class ViewportWidget : public QWidget {
    Q_OBJECT

public:
    using Pick = core::view::ScenePick;
    using Camera = core::view::Camera;
    using Fragments = std::vector<core::view::ViewFragment>;

    explicit ViewportWidget(QWidget* parent = nullptr);
    ~ViewportWidget() override;

    /**
     * @brief Whether this platform can show the view: an OpenGL 3.3 core context can be created (not on
     *        Qt's offscreen platform, which has no native OpenGL windows). Create the view only
     *        when true; otherwise show a message in its place. Needs a QGuiApplication.
     */
    static bool isSupported();

    /** @brief The fragments to show (replaces the previous set; a new cut). The first non-empty set is fitted, and
     *         so is each larger set after it until the camera is set, turned to a standard view or fitted to the
     *         selection (fitToScene() starts framing again). */
    void setFragments(Fragments fragments);
    const Fragments& fragments() const { return m_scheduler.fragments(); }
    /**
     * @brief Moves fragment @p id to @p pose (octree frame → scene frame): its model matrix changes and a
     *        frame is drawn, with no new cut (LodScheduler::setFragmentPose: the cut follows once the poses
     *        stop changing). The camera's scene bounds follow. False (nothing changes) for an unknown id.
     */
    bool setFragmentPose(std::uint64_t id, const Eigen::Matrix4d& pose);

    const Camera& camera() const { return m_camera; }
    /** @brief Sets the camera (its viewport is kept); @p moving: part of a continuous move (the view
     *         refines once it stops) rather than a jump (refined at once). */
    void setCamera(const Camera& camera, bool moving = true);
    void fitToScene();
    void fitToSelection();
    void setStandardView(core::view::StandardView view);
    void setOrthographic(bool orthographic);
    /** @brief Bounds of the visible fragments (selected ones only with @p selectedOnly), scene frame. */
    Eigen::AlignedBox3d sceneBounds(bool selectedOnly = false) const;

    LodScheduler& scheduler() { return m_scheduler; }
    const LodScheduler& scheduler() const { return m_scheduler; }
    /** @brief What draws (read-only: the points' buffers and model matrices, the overlays). */
    const ViewRenderer& renderer() const { return m_renderer; }
    void setShading(PointRenderer::Shading shading);
    PointRenderer::Shading shading() const { return m_renderer.points().shading(); }
    /**
     * @brief Annotation labels of fragment @p id for the Annotation shading (one class id per leaf, leaf order;
     *        see PointRenderer::setLabels): copied to the GL at once (or when the GL starts), then redrawn
     *        without a new cut. The view keeps no reference to @p labels.
     */
    void setLabels(std::uint64_t id, std::span<const std::uint8_t> labels);
    /** @brief Replaces @p id's labels from leaf @p first on with @p labels (PointRenderer::updateLabels). */
    void updateLabels(std::uint64_t id, std::uint64_t first, std::span<const std::uint8_t> labels);
    void clearLabels(std::uint64_t id);
    void clearAllLabels();
    /** @brief The legend's colours per class id (PointRenderer::ClassColours). */
    void setClassColours(const PointRenderer::ClassColours& colours);
    void setSplatFactor(double factor);
    double splatFactor() const { return m_renderer.points().splatFactor(); }
    void setRoundSplats(bool round);
    /** @brief Whether the gaps between splats are filled on screen (ViewRenderer::setGapFilling; default on). */
    void setGapFilling(bool on);
    bool gapFilling() const { return m_renderer.gapFilling(); }
    /** @brief The rule's parameters (core/view/GapFill.h; the defaults unless a benchmark changes them). */
    void setGapFillOptions(const core::view::GapFillOptions& options);
    /** @brief Resolution of moving frames relative to the view (see ViewRenderer::setMotionResolution). */
    void setMotionResolution(double scale);
    /** @brief Whether moving frames skip splats facing away (default true; still frames never do). */
    void setCullBackFacesWhileMoving(bool cull);

    /** @brief Shows a marker at @p point (scene frame); empty hides it. */
    void setMarker(const std::optional<Eigen::Vector3d>& point);
    std::optional<Eigen::Vector3d> marker() const;

    /**
     * @brief Makes @p tool the view's tool (ViewportTool): it gets every input event first, navigation what
     *        it does not consume. The previous tool is deactivated and destroyed; null is resetTool().
     */
    void setTool(std::unique_ptr<ViewportTool> tool);
    /** @brief Back to navigation alone (the previous tool is deactivated and destroyed). */
    void resetTool();
    /** @brief The tool set with setTool(); null when navigation alone. */
    ViewportTool* tool() const { return m_tool.get(); }
    NavigationTool& navigation() { return m_navigation; }

    /** @brief Draws @p overlay over the points from the next frame on, after those added before. */
    void addOverlay(std::shared_ptr<ViewOverlay> overlay);
    /** @brief Stops drawing @p overlay and releases its GL objects; false when it was not there. */
    bool removeOverlay(const ViewOverlay* overlay);
    /** @brief Schedules a frame (e.g. an overlay changed); coalesced, drawn on a later turn of the event loop. */
    void requestFrame();

    /** @brief The surface point under the position @p pixel (logical pixels), if any. */
    std::optional<Pick> pickAt(const QPointF& pixel) const;

    /** @brief Paints and swaps a frame now and waits for the GL to finish it (false: the view is not
     *         exposed); QWidget::repaint() does not reach the native window. */
    bool renderNow();
    /** @brief Draws a frame and returns it (device pixels), as QOpenGLWidget::grabFramebuffer() did;
     *         null before the GL has started. */
    QImage grabFramebuffer();

    /** @brief Time of the last frame, ms — drawing, glFinish and, once the window has swapped, the
     *         swap — and the points it drew. */
    double lastFrameMs() const { return m_lastFrameMs; }
    std::uint64_t lastPointsDrawn() const { return m_lastPoints; }
    /** @brief ms from the last setFragments() to the first frame that drew points; −1 before it. */
    double firstFrameMs() const { return m_firstFrameMs; }
    /** @brief Refined to the end and the full-detail image complete (what refined() announces). */
    bool isSettled() const;
    /** @brief Empty, or why the GL renderers could not start (no OpenGL 3.3 core). */
    QString glError() const { return m_glError; }

Q_SIGNALS:
    void cursorMoved(const Eigen::Vector3d& point);
    void pointPicked(const Eigen::Vector3d& point, quint64 fragmentId);
    void frameTimeChanged(double ms);
    void pointsDrawn(quint64 points);
    /** @brief The view shows full detail for the current camera (the last stage of LodScheduler, drawn). */
    void refined();
    void cameraChanged();

protected:
    void initializeGL();
    void resizeGL();
    void paintGL(unsigned framebuffer);
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    /** Offers an event to the tool, then to navigation; shows the cursor; true when one consumed it. */
    template <typename Handler>
    bool offer(Handler handler);
    void showToolCursor();
    void cameraEdited(bool moving);
    void releaseGl();
    void uploadPending();
    /** Applies @p op at once when the GL is running, else when it starts (uploadPending). */
    struct LabelOp {
        enum Kind { Set, Update, Clear, ClearAll } kind = Set;
        std::uint64_t id = 0;
        std::uint64_t first = 0;
        std::vector<std::uint8_t> bytes;
    };
    void labelOp(LabelOp op, std::span<const std::uint8_t> labels);
    void applyLabelOp(const LabelOp& op, std::span<const std::uint8_t> labels);
    /** The frame painted last is on screen (@p swapped: its time includes the composition), or another
     *  paint came first (its time is the painting's): report it. */
    void closeFrame(bool swapped);
    /** Restarts the full-detail image; @p repaint: the view on screen is no longer right. */
    void invalidateImage(bool repaint);
    void imageStep();
    QSize deviceSize() const;
    double glPixelRatio() const;

    ViewportWindow* m_window = nullptr; ///< owned by m_container
    QWidget* m_container = nullptr;     ///< child; fills this widget
    Camera m_camera;
    bool m_framing = false; ///< fragments that join are framed (setFragments) until the camera is moved
    LodScheduler m_scheduler;
    ViewRenderer m_renderer;
    std::shared_ptr<MarkerOverlay> m_marker;
    NavigationTool m_navigation;
    std::unique_ptr<ViewportTool> m_tool;
    QTimer m_stepTimer;          ///< drives the slices of the full-detail image
    std::uint64_t m_stepPoints = 100'000; ///< points per slice, adapted to about one target frame time
    std::shared_ptr<const core::view::SceneCut> m_pending;
    std::vector<LabelOp> m_pendingLabels; ///< label changes waiting for the GL to start
    bool m_fragmentsChanged = false;
    QString m_glError;
    double m_lastFrameMs = 0;
    QElapsedTimer m_frameTimer;  ///< from the start of the last paintGL
    bool m_frameOpen = false;    ///< painted, not yet reported
    bool m_frameAdapts = false;  ///< that frame was a subsample (feeds the budget controller)
    std::uint64_t m_lastPoints = 0;
    double m_firstFrameMs = -1;
    QElapsedTimer m_sinceFragments;
};

} // namespace stylos::widgets

Q_DECLARE_METATYPE(Eigen::Vector3d)
