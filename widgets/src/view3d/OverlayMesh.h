#pragma once
/** @file
 * @brief The GL side of the overlays drawn as coloured triangles (OverlayGeometry): one small shader, one
 *        vertex array, and a buffer refilled on every draw (a gizmo or a set of guides is a few thousand
 *        vertices). Drawn over the points without the depth test, with alpha blending; the GL state is left
 *        as found (depth test on, blending off). OpenGL 3.3 core.
 *
 * initialize(), draw() and release() need the GL context current; GUI thread only. Failure modes:
 * initialize() returns false when the shader does not build.
 */
#include "stylos/widgets/view3d/ViewOverlay.h"
#include "view3d/OverlayGeometry.h"

#include <QOpenGLFunctions_3_3_Core>

#include <memory>

class QOpenGLBuffer;
class QOpenGLShaderProgram;
class QOpenGLVertexArrayObject;

namespace stylos::widgets {

class OverlayMesh : protected QOpenGLFunctions_3_3_Core {
public:
    OverlayMesh();
    ~OverlayMesh();
    OverlayMesh(const OverlayMesh&) = delete;
    OverlayMesh& operator=(const OverlayMesh&) = delete;

    bool initialize();
    void release();
    bool isInitialized() const { return m_program != nullptr; }
    /** @brief Draws @p geometry's triangles with @p frame's matrices into the bound framebuffer. */
    void draw(const OverlayFrame& frame, const OverlayGeometry& geometry);

private:
    std::unique_ptr<QOpenGLShaderProgram> m_program;
    std::unique_ptr<QOpenGLBuffer> m_vbo;
    std::unique_ptr<QOpenGLVertexArrayObject> m_vao;
};

} // namespace stylos::widgets
