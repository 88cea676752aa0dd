#include "view3d/ViewportWindow.h"

#include <QCoreApplication>
#include <QEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>

#include <algorithm>
#include <cmath>

namespace stylos::widgets {

namespace {
/** Posted to the window for a scheduled frame (a plain UpdateRequest would be coalesced by Qt with the
 *  platform's own, delayed, update requests). */
const QEvent::Type RenderEvent = QEvent::Type(QEvent::registerEventType());
} // namespace

ViewportWindow::ViewportWindow(Callbacks callbacks)
    : QOpenGLWindow(QOpenGLWindow::NoPartialUpdate), m_callbacks(std::move(callbacks))
{
    setFlag(Qt::WindowTransparentForInput);
    setFlag(Qt::WindowDoesNotAcceptFocus);
}

QSize ViewportWindow::deviceSize() const
{
    const double ratio = devicePixelRatio();
    return QSize(std::max(1, int(std::lround(width() * ratio))), std::max(1, int(std::lround(height() * ratio))));
}

void ViewportWindow::scheduleRender()
{
    if (m_posted) return;
    m_posted = true;
    QCoreApplication::postEvent(this, new QEvent(RenderEvent), Qt::LowEventPriority);
}

bool ViewportWindow::renderNow(bool finish)
{
    if (!isExposed()) return false;
    update(); // marks the window dirty, which the UpdateRequest below paints (paintGL, swap, frameSwapped)
    QEvent request(QEvent::UpdateRequest);
    QCoreApplication::sendEvent(this, &request);
    if (finish && isValid()) {
        makeCurrent();
        context()->functions()->glFinish();
        doneCurrent();
    }
    return true;
}

QImage ViewportWindow::grabFrame()
{
    if (!isValid()) return {};
    makeCurrent();
    const QSize size = deviceSize();
    paintGL();
    QOpenGLFunctions* f = context()->functions();
    f->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
    QImage image(size, QImage::Format_RGBA8888);
    f->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    f->glReadPixels(0, 0, size.width(), size.height(), GL_RGBA, GL_UNSIGNED_BYTE, image.bits());
    doneCurrent();
    for (int y = 0; y < size.height(); ++y) { // opaque, whatever alpha the window's format keeps
        uchar* line = image.scanLine(y);
        for (int x = 0; x < size.width(); ++x) line[4 * x + 3] = 255;
    }
    image = std::move(image).mirrored().convertToFormat(QImage::Format_RGB32);
    image.setDevicePixelRatio(devicePixelRatio());
    return image;
}

void ViewportWindow::initializeGL()
{
    if (m_callbacks.initialize) m_callbacks.initialize();
}

void ViewportWindow::resizeGL(int, int)
{
    if (m_callbacks.resize) m_callbacks.resize();
}

void ViewportWindow::paintGL()
{
    if (m_callbacks.paint) m_callbacks.paint(defaultFramebufferObject());
}

bool ViewportWindow::event(QEvent* event)
{
    if (event->type() == RenderEvent) {
        m_posted = false;
        renderNow();
        return true;
    }
    return QOpenGLWindow::event(event);
}

} // namespace stylos::widgets
