#include "view3d/MarkerOverlay.h"
#include "view3d/ShaderProgram.h"

#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>

namespace stylos::widgets {

namespace {

const char* const VertexShader = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uMatrix;
uniform float uPointSize;
void main()
{
    gl_Position = uMatrix * vec4(aPosition, 1.0);
    gl_PointSize = uPointSize;
}
)";

const char* const FragmentShader = R"(#version 330 core
uniform vec4 uColour;
out vec4 fragColour;
void main() { fragColour = uColour; }
)";

// Three arms of unit half-length, then the centre (drawn as a point).
const float Cross[] = {-1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0};

} // namespace

MarkerOverlay::MarkerOverlay() = default;
MarkerOverlay::~MarkerOverlay() = default;

bool MarkerOverlay::initialize()
{
    initializeOpenGLFunctions();
    m_program = linkShaderProgram(VertexShader, FragmentShader);
    if (!m_program) return false;
    m_vao = std::make_unique<QOpenGLVertexArrayObject>();
    m_vao->create();
    QOpenGLVertexArrayObject::Binder bind(m_vao.get());
    m_vbo = std::make_unique<QOpenGLBuffer>(QOpenGLBuffer::VertexBuffer);
    m_vbo->create();
    m_vbo->bind();
    m_vbo->allocate(Cross, sizeof(Cross));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    m_vbo->release();
    return true;
}

void MarkerOverlay::release()
{
    m_vao.reset();
    m_vbo.reset();
    m_program.reset();
}

void MarkerOverlay::draw(const OverlayFrame& frame)
{
    if (!m_program || !m_point) return;
    const core::view::Camera& camera = frame.camera;
    // Constant size on screen: metres per pixel at the marker's depth.
    const double depth = camera.isOrthographic() ? camera.distance() : (*m_point - camera.eye()).dot(camera.forward());
    if (!camera.isOrthographic() && depth <= 0) return;
    const double metresPerPixel = camera.isOrthographic() ? 1.0 / camera.pixelsPerMetre()
                                                          : depth / (camera.pixelsPerMetre() * camera.distance());
    Eigen::Matrix4d model = Eigen::Matrix4d::Identity();
    model.topLeftCorner<3, 3>() *= m_size * metresPerPixel;
    model.topRightCorner<3, 1>() = *m_point;
    const Eigen::Matrix4f matrix = (frame.projection * frame.view * model).cast<float>();

    glEnable(GL_PROGRAM_POINT_SIZE);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    m_program->bind();
    glUniformMatrix4fv(m_program->uniformLocation("uMatrix"), 1, GL_FALSE, matrix.data());
    m_program->setUniformValue("uPointSize", float(5.0 * frame.devicePixelRatio));
    // Behind the surface: faded (drawn where the depth test fails); in front: at full strength.
    for (const bool behind : {true, false}) {
        glDepthFunc(behind ? GL_GREATER : GL_LEQUAL);
        m_program->setUniformValue("uColour", float(m_colour.redF()), float(m_colour.greenF()), float(m_colour.blueF()),
                                   behind ? BehindOpacity : 1.0f);
        QOpenGLVertexArrayObject::Binder bind(m_vao.get());
        glDrawArrays(GL_LINES, 0, 6);
        glDrawArrays(GL_POINTS, 6, 1);
    }
    m_program->release();
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

} // namespace stylos::widgets
