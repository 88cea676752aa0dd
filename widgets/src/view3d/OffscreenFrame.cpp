#include "stylos/widgets/view3d/OffscreenFrame.h"

namespace stylos::widgets {

bool OffscreenFrame::bind(const QSize& size)
{
    if (!m_initialized) m_initialized = initializeOpenGLFunctions();
    if (!m_initialized || size.isEmpty()) return false;
    if (size != m_size || m_fbo == 0) {
        release();
        glGenFramebuffers(1, &m_fbo);
        glGenRenderbuffers(1, &m_colour);
        glGenRenderbuffers(1, &m_depth);
        glBindRenderbuffer(GL_RENDERBUFFER, m_colour);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size.width(), size.height());
        glBindRenderbuffer(GL_RENDERBUFFER, m_depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size.width(), size.height());
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_colour);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m_depth);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            release();
            return false;
        }
        m_size = size;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
    glViewport(0, 0, m_size.width(), m_size.height());
    return true;
}

void OffscreenFrame::clear(float red, float green, float blue)
{
    glClearColor(red, green, blue, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void OffscreenFrame::blitTo(GLuint target, const QSize& targetSize)
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    const GLenum filter = targetSize == m_size ? GL_NEAREST : GL_LINEAR;
    glBlitFramebuffer(0, 0, m_size.width(), m_size.height(), 0, 0, targetSize.width(), targetSize.height(),
                      GL_COLOR_BUFFER_BIT, filter);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, targetSize.width(), targetSize.height());
}

void OffscreenFrame::release()
{
    if (!m_initialized) return;
    if (m_fbo) glDeleteFramebuffers(1, &m_fbo);
    if (m_colour) glDeleteRenderbuffers(1, &m_colour);
    if (m_depth) glDeleteRenderbuffers(1, &m_depth);
    m_fbo = m_colour = m_depth = 0;
    m_size = {};
}

} // namespace stylos::widgets
