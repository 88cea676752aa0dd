#pragma once
/** @file
 * @brief The gap-filling pass's shortcut (ViewComposite): the nearest linear depth in each 8 × 8 tile of a depth
 *        texture, in a small R32F texture (background: 3e38). A pixel whose walks (maxSteps pixels each way,
 *        core/view/GapFill.h) cover tiles with nothing in front of it cannot be enclosed, so the composite pass
 *        skips its walks — the same result, without walking the wide smooth parts of the picture.
 *
 * GL context current, GUI thread only. Failure modes: initialize() or update() false (no float render target);
 * the composite pass then walks every pixel.
 */
#include <QOpenGLFunctions_3_3_Core>
#include <QSize>

#include <memory>

class QOpenGLShaderProgram;

namespace stylos::widgets {

class GapTiles : protected QOpenGLFunctions_3_3_Core {
public:
    static constexpr int Tile = 8;

    GapTiles();
    ~GapTiles();
    bool initialize();
    void release();

    /** @brief Recomputes the tiles of @p depth (a texture of @p size) for the projection terms @p a, @p b (as the
     *         composite pass takes them); leaves no framebuffer bound. */
    bool update(GLuint depth, const QSize& size, bool orthographic, float a, float b);
    GLuint texture() const { return m_texture; }

private:
    std::unique_ptr<QOpenGLShaderProgram> m_program;
    GLuint m_vao = 0;
    GLuint m_fbo = 0;
    GLuint m_texture = 0;
    QSize m_size;
};

} // namespace stylos::widgets
