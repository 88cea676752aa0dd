#include "stylos/widgets/view3d/ViewportWidget.h"

#include "view3d/MarkerOverlay.h"
#include "stylos/widgets/view3d/ViewportTool.h"
#include "view3d/ViewportWindow.h"

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPaintEvent>
#include <QResizeEvent>
#include <QSurfaceFormat>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace stylos::widgets {

namespace {

constexpr double PickRadiusPixels = 3.0;

} // namespace

ViewportWidget::ViewportWidget(QWidget* parent) : QWidget(parent), m_marker(std::make_shared<MarkerOverlay>())
{
    qRegisterMetaType<Eigen::Vector3d>();
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    m_window = new ViewportWindow({[this] { initializeGL(); }, [this] { resizeGL(); },
                                   [this](unsigned framebuffer) { paintGL(framebuffer); }});
    m_window->setFormat(format);
    m_container = QWidget::createWindowContainer(m_window, this);
    m_container->setObjectName(QStringLiteral("viewportContainer"));
    // Input goes to this widget (the window is transparent for it), and so does the focus.
    m_container->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_container->setFocusPolicy(Qt::NoFocus);
    m_container->setGeometry(rect());
    setAttribute(Qt::WA_OpaquePaintEvent);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setMinimumSize(160, 120);
    m_camera.setStandardView(core::view::StandardView::Iso);
    m_renderer.addOverlay(m_marker); // the first overlay
    m_stepTimer.setSingleShot(true);
    m_stepTimer.setInterval(0);
    connect(&m_stepTimer, &QTimer::timeout, this, &ViewportWidget::imageStep);
    connect(&m_scheduler, &LodScheduler::cutReady, this, [this](std::shared_ptr<const core::view::SceneCut> batch) {
        m_pending = std::move(batch);
        if (m_renderer.isInitialized() && m_window->isValid()) {
            m_window->makeCurrent();
            uploadPending();
            m_window->doneCurrent();
        }
        invalidateImage(false); // the image on screen stays until the new one is complete
    });
    connect(&m_scheduler, &LodScheduler::motionStopped, this, [this] { invalidateImage(false); });
    connect(m_window, &QOpenGLWindow::frameSwapped, this, [this] { closeFrame(true); });
}

ViewportWidget::~ViewportWidget()
{
    resetTool();
    releaseGl();
    // The window (and its context) goes now, while what its callbacks reach is still alive.
    m_window->disconnect(this);
    if (QOpenGLContext* context = m_window->context()) context->disconnect(this);
    delete m_container;
}

bool ViewportWidget::isSupported()
{
    if (QGuiApplication::platformName() == QLatin1String("offscreen")) return false;
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    QOpenGLContext context;
    context.setFormat(format);
    if (!context.create()) return false;
    const QSurfaceFormat got = context.format();
    return got.majorVersion() > 3 || (got.majorVersion() == 3 && got.minorVersion() >= 3);
}

void ViewportWidget::releaseGl()
{
    if (!m_renderer.isInitialized() || !m_window->context()) return;
    m_window->makeCurrent();
    m_renderer.release();
    m_window->doneCurrent();
}

QSize ViewportWidget::deviceSize() const { return m_window->deviceSize(); }

double ViewportWidget::glPixelRatio() const { return m_window->devicePixelRatio(); }

void ViewportWidget::requestFrame() { m_window->scheduleRender(); }

bool ViewportWidget::renderNow() { return m_window->renderNow(true); }

QImage ViewportWidget::grabFramebuffer() { return m_window->grabFrame(); }

void ViewportWidget::paintEvent(QPaintEvent*) { requestFrame(); }

void ViewportWidget::resizeEvent(QResizeEvent*) { m_container->setGeometry(rect()); }

bool ViewportWidget::isSettled() const
{
    return m_scheduler.isRefined() && !m_scheduler.isComputing() && m_renderer.isImageComplete() && !m_pending;
}

void ViewportWidget::uploadPending()
{
    if (m_fragmentsChanged) {
        m_renderer.points().setFragments(m_scheduler.fragments());
        m_fragmentsChanged = false;
    }
    for (const LabelOp& op : m_pendingLabels) applyLabelOp(op, op.bytes);
    m_pendingLabels.clear();
    if (!m_pending) return;
    for (const core::view::FragmentCut& cut : m_pending->fragments) m_renderer.points().upload(cut.id, cut.splats);
    m_pending.reset();
}

void ViewportWidget::invalidateImage(bool repaint)
{
    m_renderer.restartImage();
    if (!m_scheduler.isMoving()) m_stepTimer.start();
    if (repaint) requestFrame();
}

void ViewportWidget::imageStep()
{
    if (m_scheduler.isMoving() || m_renderer.isImageComplete() || !m_renderer.isInitialized() || !m_window->isValid())
        return;
    m_window->makeCurrent();
    uploadPending();
    QElapsedTimer timer;
    timer.start();
    const std::uint64_t drawn = m_renderer.drawImageStep(m_camera, deviceSize(), glPixelRatio(), m_stepPoints);
    m_window->doneCurrent();
    // Slices of about one target frame time, so that input is handled between them (no composition here:
    // its own controller, not the scheduler's).
    const double ms = double(timer.nsecsElapsed()) * 1e-6;
    if (drawn > 0 && ms > 0) {
        const double next = std::min(double(drawn) * 0.85 * m_scheduler.targetFrameMs() / ms, 2.0 * double(m_stepPoints));
        m_stepPoints = std::clamp<std::uint64_t>(std::uint64_t(next), 5'000, std::max<std::uint64_t>(m_scheduler.pointBudget(), 5'000));
    }
    if (!m_renderer.isImageComplete()) {
        m_stepTimer.start();
        return;
    }
    requestFrame();
    if (isSettled()) Q_EMIT refined();
}

void ViewportWidget::setFragments(Fragments fragments)
{
    m_sinceFragments.start();
    m_firstFrameMs = -1;
    m_fragmentsChanged = true;
    invalidateImage(false);
    // The first fragments are framed; while the camera has not been moved since, each that joins them is framed with
    // them (files imported together arrive one by one, in the order they finish: the last was left out of view).
    const bool first = m_scheduler.fragments().empty() && !fragments.empty();
    if (first) m_framing = true;
    const bool fit = first || (m_framing && fragments.size() > m_scheduler.fragments().size());
    m_camera.setSceneBounds(core::view::sceneBounds(fragments));
    if (fit) m_camera.fit(core::view::sceneCorners(fragments));
    m_scheduler.setFragments(std::move(fragments), m_camera);
    requestFrame();
    if (fit) Q_EMIT cameraChanged();
}

bool ViewportWidget::setFragmentPose(std::uint64_t id, const Eigen::Matrix4d& pose)
{
    Fragments moved = m_scheduler.fragments();
    const auto it = std::find_if(moved.begin(), moved.end(), [id](const core::view::ViewFragment& f) { return f.id == id; });
    if (it == moved.end()) return false;
    it->pose = pose;
    m_camera.setSceneBounds(core::view::sceneBounds(moved)); // the clip planes hold the moved fragment
    m_scheduler.setFragmentPose(id, pose, m_camera);
    m_renderer.points().setPose(id, pose); // no GL work: the model matrix of its next draw
    invalidateImage(true);
    return true;
}

void ViewportWidget::setCamera(const Camera& camera, bool moving)
{
    const int w = m_camera.width(), h = m_camera.height();
    m_camera = camera;
    m_camera.setViewport(w, h);
    m_framing = false;
    cameraEdited(moving);
}

void ViewportWidget::cameraEdited(bool moving)
{
    if (moving) m_scheduler.cameraChanged(m_camera);
    else m_scheduler.cameraSettled(m_camera);
    invalidateImage(true);
    Q_EMIT cameraChanged();
}

Eigen::AlignedBox3d ViewportWidget::sceneBounds(bool selectedOnly) const
{
    return core::view::sceneBounds(m_scheduler.fragments(), selectedOnly);
}

void ViewportWidget::fitToScene()
{
    m_camera.fit(core::view::sceneCorners(m_scheduler.fragments()));
    m_framing = true;
    cameraEdited(false);
}

void ViewportWidget::fitToSelection()
{
    const auto selected = core::view::sceneCorners(m_scheduler.fragments(), true);
    m_camera.fit(selected.empty() ? core::view::sceneCorners(m_scheduler.fragments()) : selected);
    m_framing = false;
    cameraEdited(false);
}

void ViewportWidget::setStandardView(core::view::StandardView view)
{
    m_camera.setStandardView(view);
    m_framing = false;
    cameraEdited(false);
}

void ViewportWidget::setOrthographic(bool orthographic)
{
    m_camera.setOrthographic(orthographic);
    cameraEdited(false);
}

void ViewportWidget::setShading(PointRenderer::Shading shading)
{
    m_renderer.points().setShading(shading);
    invalidateImage(true);
}

void ViewportWidget::applyLabelOp(const LabelOp& op, std::span<const std::uint8_t> labels)
{
    PointRenderer& points = m_renderer.points();
    switch (op.kind) {
    case LabelOp::Set: points.setLabels(op.id, labels); break;
    case LabelOp::Update: points.updateLabels(op.id, op.first, labels); break;
    case LabelOp::Clear: points.clearLabels(op.id); break;
    case LabelOp::ClearAll: points.clearAllLabels(); break;
    }
}

void ViewportWidget::labelOp(LabelOp op, std::span<const std::uint8_t> labels)
{
    if (m_renderer.isInitialized() && m_window->isValid()) {
        m_window->makeCurrent();
        applyLabelOp(op, labels);
        m_window->doneCurrent();
    } else {
        if (op.kind != LabelOp::Update) // a whole set or a clear makes what came before for the fragment moot
            std::erase_if(m_pendingLabels, [&](const LabelOp& o) { return op.kind == LabelOp::ClearAll || o.id == op.id; });
        op.bytes.assign(labels.begin(), labels.end());
        m_pendingLabels.push_back(std::move(op));
    }
    // Only the tint changed: the full-detail image is redrawn from the same buffers, with no new cut.
    if (m_renderer.points().shading() == PointRenderer::Shading::Annotation) invalidateImage(true);
}

void ViewportWidget::setLabels(std::uint64_t id, std::span<const std::uint8_t> labels)
{
    labelOp({LabelOp::Set, id, 0, {}}, labels);
}

void ViewportWidget::updateLabels(std::uint64_t id, std::uint64_t first, std::span<const std::uint8_t> labels)
{
    labelOp({LabelOp::Update, id, first, {}}, labels);
}

void ViewportWidget::clearLabels(std::uint64_t id) { labelOp({LabelOp::Clear, id, 0, {}}, {}); }

void ViewportWidget::clearAllLabels() { labelOp({LabelOp::ClearAll, 0, 0, {}}, {}); }

void ViewportWidget::setClassColours(const PointRenderer::ClassColours& colours)
{
    m_renderer.points().setClassColours(colours);
    if (m_renderer.points().shading() == PointRenderer::Shading::Annotation) invalidateImage(true);
}

void ViewportWidget::setSplatFactor(double factor)
{
    m_renderer.points().setSplatFactor(factor);
    invalidateImage(true);
}

void ViewportWidget::setGapFilling(bool on)
{
    if (on == m_renderer.gapFilling()) return;
    m_renderer.setGapFilling(on); // the image's splats stay; only the composite pass changes
    requestFrame();
}

void ViewportWidget::setGapFillOptions(const core::view::GapFillOptions& options)
{
    m_renderer.setGapFillOptions(options);
    requestFrame();
}

void ViewportWidget::setRoundSplats(bool round)
{
    m_renderer.points().setRoundSplats(round);
    invalidateImage(true);
}

void ViewportWidget::setMotionResolution(double scale)
{
    m_renderer.setMotionResolution(scale);
    requestFrame();
}

void ViewportWidget::setCullBackFacesWhileMoving(bool cull) { m_renderer.setCullBackFacesWhileMoving(cull); }

void ViewportWidget::setMarker(const std::optional<Eigen::Vector3d>& point)
{
    m_marker->setMarker(point);
    requestFrame();
}

std::optional<Eigen::Vector3d> ViewportWidget::marker() const { return m_marker->marker(); }

void ViewportWidget::setTool(std::unique_ptr<ViewportTool> tool)
{
    if (m_tool) m_tool->deactivate(*this);
    m_tool = std::move(tool);
    if (m_tool) m_tool->activate(*this);
    showToolCursor();
}

void ViewportWidget::showToolCursor()
{
    const QCursor wanted = m_tool ? m_tool->cursor() : m_navigation.cursor();
    if (!(cursor() == wanted)) setCursor(wanted);
}

void ViewportWidget::resetTool() { setTool(nullptr); }

void ViewportWidget::addOverlay(std::shared_ptr<ViewOverlay> overlay)
{
    const bool current = m_renderer.isInitialized() && m_window->isValid();
    if (current) m_window->makeCurrent();
    m_renderer.addOverlay(std::move(overlay));
    if (current) m_window->doneCurrent();
    requestFrame();
}

bool ViewportWidget::removeOverlay(const ViewOverlay* overlay)
{
    const bool current = m_renderer.isInitialized() && m_window->isValid();
    if (current) m_window->makeCurrent();
    const bool removed = m_renderer.removeOverlay(overlay);
    if (current) m_window->doneCurrent();
    if (removed) requestFrame();
    return removed;
}

std::optional<ViewportWidget::Pick> ViewportWidget::pickAt(const QPointF& pixel) const
{
    return core::view::pickScene(m_scheduler.fragments(), m_camera, pixel.x(), pixel.y(), PickRadiusPixels);
}

void ViewportWidget::initializeGL()
{
    m_glError.clear();
    if (!m_renderer.initialize()) {
        m_glError = tr("The 3D view needs OpenGL 3.3: %1").arg(m_renderer.log());
        qWarning("ViewportWidget: %s", qPrintable(m_glError));
    }
    m_fragmentsChanged = true;
    invalidateImage(false);
    connect(m_window->context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWidget::releaseGl,
            Qt::UniqueConnection);
}

void ViewportWidget::resizeGL()
{
    // The window's size: what the GL draws (the container gives it this widget's size).
    invalidateImage(false);
    const int w = m_window->width(), h = m_window->height();
    if (w == m_camera.width() && h == m_camera.height()) return;
    m_camera.setViewport(w, h);
    m_scheduler.cameraSettled(m_camera);
}

void ViewportWidget::paintGL(unsigned framebuffer)
{
    if (m_frameOpen) closeFrame(false); // the previous frame never reached the screen (a grab, a hidden view)
    m_frameTimer.start();
    uploadPending();
    const QSize size = deviceSize();
    const bool moving = m_scheduler.isMoving();
    // The complete full-detail image when there is one; otherwise a quick frame (moving, or a preview).
    const bool complete = !moving && m_renderer.isImageComplete() && m_renderer.presentImage(framebuffer, size);
    const std::uint64_t drawn = complete ? m_renderer.imagePoints()
                                         : m_renderer.drawQuick(m_camera, framebuffer, size, glPixelRatio(),
                                                                m_scheduler.drawLimit(), moving);
    m_renderer.finishFrame(m_camera, size, glPixelRatio());
    m_lastFrameMs = double(m_frameTimer.nsecsElapsed()) * 1e-6;
    m_lastPoints = drawn;
    m_frameOpen = true;
    m_frameAdapts = !complete;
    if (drawn > 0 && m_firstFrameMs < 0 && m_sinceFragments.isValid())
        m_firstFrameMs = double(m_sinceFragments.nsecsElapsed()) * 1e-6;
}

void ViewportWidget::closeFrame(bool swapped)
{
    if (!m_frameOpen) return;
    m_frameOpen = false;
    if (swapped) m_lastFrameMs = double(m_frameTimer.nsecsElapsed()) * 1e-6;
    if (m_frameAdapts) m_scheduler.reportFrame(m_lastFrameMs, m_lastPoints);
    Q_EMIT frameTimeChanged(m_lastFrameMs);
    Q_EMIT pointsDrawn(m_lastPoints);
}

template <typename Handler>
bool ViewportWidget::offer(Handler handler)
{
    const bool consumed = (m_tool && handler(*m_tool)) || handler(static_cast<ViewportTool&>(m_navigation));
    showToolCursor();
    return consumed;
}

void ViewportWidget::mousePressEvent(QMouseEvent* event)
{
    if (!offer([&](ViewportTool& tool) { return tool.mousePress(*this, *event); })) event->ignore();
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event)
{
    const bool hovering = event->buttons() == Qt::NoButton;
    const bool consumed = offer([&](ViewportTool& tool) {
        return hovering ? tool.hover(*this, *event) : tool.mouseMove(*this, *event);
    });
    if (!consumed) event->ignore();
}

void ViewportWidget::leaveEvent(QEvent* event)
{
    if (m_tool) m_tool->leave(*this);
    m_navigation.leave(*this);
    QWidget::leaveEvent(event);
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event)
{
    if (!offer([&](ViewportTool& tool) { return tool.mouseRelease(*this, *event); })) event->ignore();
}

void ViewportWidget::wheelEvent(QWheelEvent* event)
{
    if (!offer([&](ViewportTool& tool) { return tool.wheel(*this, *event); })) event->ignore();
}

void ViewportWidget::keyPressEvent(QKeyEvent* event)
{
    if (offer([&](ViewportTool& tool) { return tool.keyPress(*this, *event); })) event->accept();
    else QWidget::keyPressEvent(event);
}

} // namespace stylos::widgets
