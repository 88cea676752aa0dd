#include "stylos/widgets/view3d/OffscreenFrame.h"

namespace stylos::widgets {

bool OffscreenFrame::bind(const QSize& size)
{
    if (!m_initialized) m_initialized = initializeOpenGLFunctions();
    if (!m_initialized || size.isEmpty()) return false;
    if (size != m_size || m_fbo == 0) {
        release();
        glGenFramebuffers(1, &m_fbo);
        glGenTextures(1, &m_colour);
        glGenTextures(1, &m_depth);
        glBindTexture(GL_TEXTURE_2D, m_colour);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.width(), size.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        setNearest();
        glBindTexture(GL_TEXTURE_2D, m_depth);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size.width(), size.height(), 0, GL_DEPTH_COMPONENT,
                     GL_UNSIGNED_INT, nullptr);
        setNearest();
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_colour, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depth, 0);
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

void OffscreenFrame::setNearest()
{
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
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
    if (m_colour) glDeleteTextures(1, &m_colour);
    if (m_depth) glDeleteTextures(1, &m_depth);
    m_fbo = m_colour = m_depth = 0;
    m_size = {};
}

} // namespace stylos::widgets
