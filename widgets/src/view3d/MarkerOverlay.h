#pragma once
/** @file
 * @brief The 3D view's first overlay (ViewOverlay): a marker at a 3D point of the scene (a picked point, or
 *        the 3D point of a click in the développée), a three-axis cross of constant size on screen with a dot
 *        at its centre, never hidden: the parts in front of the surface at full strength, those behind it faded
 *        (BehindOpacity; the depth of the splats is in the framebuffer, ViewRenderer). OpenGL 3.3 core.
 *
 * initialize(), draw() and release() need the GL context current; GUI thread only. Failure modes:
 * initialize() returns false when the shader does not build (no GL 3.3 core context).
 */
#include "stylos/widgets/view3d/ViewOverlay.h"

#include <QColor>
#include <QOpenGLFunctions_3_3_Core>

#include <Eigen/Core>

#include <memory>
#include <optional>

class QOpenGLBuffer;
class QOpenGLShaderProgram;
class QOpenGLVertexArrayObject;

namespace stylos::widgets {

class MarkerOverlay : public ViewOverlay, protected QOpenGLFunctions_3_3_Core {
public:
    /** @brief Opacity of the parts of the marker behind the surface. */
    static constexpr float BehindOpacity = 0.3f;
    MarkerOverlay();
    ~MarkerOverlay() override;
    MarkerOverlay(const MarkerOverlay&) = delete;
    MarkerOverlay& operator=(const MarkerOverlay&) = delete;

    bool initialize() override;
    void release() override;
    /** @brief Draws the marker, if any, into the bound framebuffer. */
    void draw(const OverlayFrame& frame) override;

    /** @brief The marked point, scene frame, metres; empty: no marker. */
    void setMarker(const std::optional<Eigen::Vector3d>& point) { m_point = point; }
    const std::optional<Eigen::Vector3d>& marker() const { return m_point; }
    /** @brief Half the length of an arm, logical pixels (default 14). */
    void setSize(double pixels) { m_size = pixels; }
    void setColour(const QColor& colour) { m_colour = colour; }

private:
    std::unique_ptr<QOpenGLShaderProgram> m_program;
    std::unique_ptr<QOpenGLBuffer> m_vbo;
    std::unique_ptr<QOpenGLVertexArrayObject> m_vao;
    std::optional<Eigen::Vector3d> m_point;
    double m_size = 14;
    QColor m_colour = QColor(255, 70, 40);
};

} // namespace stylos::widgets
