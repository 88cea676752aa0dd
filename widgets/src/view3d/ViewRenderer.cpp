#include "stylos/widgets/view3d/ViewRenderer.h"

#include <QtGlobal>

#include <algorithm>

namespace stylos::widgets {

bool ViewRenderer::initialize()
{
    initializeOpenGLFunctions();
    m_log.clear();
    if (!m_points.initialize()) {
        m_log = m_points.log().isEmpty() ? QStringLiteral("OpenGL 3.3 core is not available") : m_points.log();
        return false;
    }
    const QByteArray name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    m_software = name.contains("llvmpipe") || name.contains("softpipe") || name.contains("SwiftShader") ||
                 name.contains("Software");
    if (!m_composite.initialize()) qWarning("ViewRenderer: the composite pass did not build; no eye-dome lighting nor outline");
    restartImage();
    for (Overlay& entry : m_overlays) initializeOverlay(entry);
    return true;
}

void ViewRenderer::initializeOverlay(Overlay& entry)
{
    entry.ready = entry.overlay->initialize();
    if (!entry.ready) qWarning("ViewRenderer: an overlay could not initialise its OpenGL objects; it is not drawn");
}

void ViewRenderer::addOverlay(std::shared_ptr<ViewOverlay> overlay)
{
    if (!overlay) return;
    for (const Overlay& entry : m_overlays)
        if (entry.overlay == overlay) return;
    m_overlays.push_back({std::move(overlay), false});
    if (isInitialized()) initializeOverlay(m_overlays.back());
}

bool ViewRenderer::removeOverlay(const ViewOverlay* overlay)
{
    const auto it = std::find_if(m_overlays.begin(), m_overlays.end(),
                                 [overlay](const Overlay& entry) { return entry.overlay.get() == overlay; });
    if (it == m_overlays.end()) return false;
    if (it->ready) it->overlay->release();
    m_overlays.erase(it);
    return true;
}

std::vector<std::shared_ptr<ViewOverlay>> ViewRenderer::overlays() const
{
    std::vector<std::shared_ptr<ViewOverlay>> out;
    for (const Overlay& entry : m_overlays) out.push_back(entry.overlay);
    return out;
}

void ViewRenderer::release()
{
    m_points.release();
    for (Overlay& entry : m_overlays) {
        if (entry.ready) entry.overlay->release();
        entry.ready = false;
    }
    m_image.release();
    m_lowRes.release();
    m_composite.release();
}

void ViewRenderer::setMotionResolution(double scale) { m_motionResolution = std::clamp(scale, 0.1, 1.0); }

void ViewRenderer::clear(float alpha)
{
    glClearColor(float(m_background.redF()), float(m_background.greenF()), float(m_background.blueF()), alpha);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

std::uint64_t ViewRenderer::drawQuick(const core::view::Camera& camera, unsigned target, const QSize& size, double devicePixelRatio,
                                      std::uint64_t limit, bool moving)
{
    const double scale = moving ? motionScale() : 1.0;
    const std::uint64_t visible = m_points.visiblePoints();
    PointRenderer::Pass pass;
    pass.to = (visible == 0 || limit == 0) ? 1.0 : std::min(1.0, double(limit) / double(visible));
    pass.enlarge = true;
    pass.cullBackFaces = moving && m_cullWhileMoving;
    pass.pixelScale = devicePixelRatio * scale;
    const QSize reduced(std::max(1, int(size.width() * scale)), std::max(1, int(size.height() * scale)));
    const bool composite = m_composite.isInitialized() && (needsComposite() || scale < 1.0);
    if (composite && m_lowRes.bind(reduced)) {
        pass.selectionInAlpha = true;
        clear(0.0f);
        const std::uint64_t drawn = m_points.draw(camera, pass);
        m_composite.draw(m_lowRes, target, size, camera, compositeOptions(false));
        return drawn;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, size.width(), size.height());
    clear(1.0f);
    return m_points.draw(camera, pass);
}

bool ViewRenderer::needsComposite() const
{
    return m_points.shading() == PointRenderer::Shading::EyeDome || m_points.hasSelection();
}

ViewComposite::Options ViewRenderer::compositeOptions(bool fillGaps) const
{
    ViewComposite::Options options;
    options.eyeDome = m_points.shading() == PointRenderer::Shading::EyeDome;
    options.outline = m_points.hasSelection();
    options.gapFill = m_gapFill && fillGaps;
    options.gap = m_gapOptions;
    return options;
}

void ViewRenderer::restartImage()
{
    m_imageDrawn = 0;
    m_imagePoints = 0;
}

std::uint64_t ViewRenderer::drawImageStep(const core::view::Camera& camera, const QSize& size, double devicePixelRatio,
                                          std::uint64_t points)
{
    if (isImageComplete()) return 0;
    if (!m_image.bind(size)) { // no offscreen framebuffer: "complete", presentImage() refuses, quick frames stay
        m_imageDrawn = 1.0;
        return 0;
    }
    if (m_imageDrawn == 0) clear(0.0f);
    m_imageCamera = camera;
    const std::uint64_t visible = m_points.visiblePoints();
    PointRenderer::Pass pass;
    pass.from = m_imageDrawn;
    pass.to = visible == 0 ? 1.0 : std::min(1.0, m_imageDrawn + double(std::max<std::uint64_t>(points, 1)) / double(visible));
    pass.pixelScale = devicePixelRatio;
    pass.selectionInAlpha = true;
    const std::uint64_t drawn = m_points.draw(camera, pass);
    glFinish(); // the step's work is done before the event loop runs again
    m_imageDrawn = pass.to;
    m_imagePoints += drawn;
    return drawn;
}

bool ViewRenderer::presentImage(unsigned target, const QSize& size)
{
    if (!isImageComplete() || m_image.size() != size) return false;
    if (m_composite.isInitialized() && m_imageCamera)
        m_composite.draw(m_image, target, size, *m_imageCamera, compositeOptions(true));
    else
        m_image.blitTo(target, size);
    return true;
}

void ViewRenderer::finishFrame(const core::view::Camera& camera, const QSize& size, double devicePixelRatio)
{
    const OverlayFrame frame{camera, camera.viewMatrix(), camera.projectionMatrix(), size, devicePixelRatio};
    for (Overlay& entry : m_overlays)
        if (entry.ready) entry.overlay->draw(frame);
    glFinish(); // the frame time is the rendering's, not the submission's
}

} // namespace stylos::widgets
