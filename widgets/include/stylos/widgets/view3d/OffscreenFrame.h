#pragma once
/** @file
 * @brief An offscreen colour + depth framebuffer (two textures, so that ViewComposite can read them) that the 3D view draws into and then copies (scaled,
 *        linear filtering) into the widget's framebuffer. Used to build the full-detail image in steps
 *        while the last complete image stays on screen, and (optionally) to draw moving frames at a
 *        lower resolution. OpenGL 3.3 core.
 *
 * Every method needs the GL context current; GUI thread only. Failure modes: bind() returns false when
 * the framebuffer cannot be created (then draw directly).
 */
#include <QOpenGLFunctions_3_3_Core>
#include <QSize>

namespace stylos::widgets {

class OffscreenFrame : protected QOpenGLFunctions_3_3_Core {
public:
    OffscreenFrame() = default;
    ~OffscreenFrame() = default; ///< call release() with the context current first
    OffscreenFrame(const OffscreenFrame&) = delete;
    OffscreenFrame& operator=(const OffscreenFrame&) = delete;

    /** @brief Binds it as the draw framebuffer, (re)allocated at @p size (device pixels), and sets the viewport. */
    bool bind(const QSize& size);
    /** @brief Clears colour and depth (bound). */
    void clear(float red, float green, float blue);
    /** @brief Copies the colour into framebuffer @p target of @p targetSize (scaled), and binds @p target. */
    void blitTo(GLuint target, const QSize& targetSize);
    QSize size() const { return m_size; }
    /** @brief The colour (RGBA8) and depth (24-bit) textures; 0 before the first successful bind(). */
    GLuint framebuffer() const { return m_fbo; }
    GLuint colourTexture() const { return m_colour; }
    GLuint depthTexture() const { return m_depth; }
    void release();

private:
    void setNearest();

    bool m_initialized = false;
    GLuint m_fbo = 0;
    GLuint m_colour = 0;
    GLuint m_depth = 0;
    QSize m_size;
};

} // namespace stylos::widgets
