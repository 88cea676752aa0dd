#include "view3d/OverlayMesh.h"
#include "view3d/ShaderProgram.h"

#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>

#include <cstddef>

namespace stylos::widgets {

namespace {

const char* const VertexShader = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColour;
uniform mat4 uMatrix;
out vec4 vColour;
void main()
{
    gl_Position = uMatrix * vec4(aPosition, 1.0);
    vColour = aColour;
}
)";

const char* const FragmentShader = R"(#version 330 core
in vec4 vColour;
out vec4 fragColour;
void main() { fragColour = vColour; }
)";

} // namespace

OverlayMesh::OverlayMesh() = default;
OverlayMesh::~OverlayMesh() = default;

bool OverlayMesh::initialize()
{
    initializeOpenGLFunctions();
    m_program = linkShaderProgram(VertexShader, FragmentShader);
    if (!m_program) return false;
    m_vao = std::make_unique<QOpenGLVertexArrayObject>();
    m_vao->create();
    QOpenGLVertexArrayObject::Binder bind(m_vao.get());
    m_vbo = std::make_unique<QOpenGLBuffer>(QOpenGLBuffer::VertexBuffer);
    m_vbo->create();
    m_vbo->setUsagePattern(QOpenGLBuffer::StreamDraw);
    m_vbo->bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(OverlayVertex), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(OverlayVertex),
                          reinterpret_cast<const void*>(offsetof(OverlayVertex, r)));
    m_vbo->release();
    return true;
}

void OverlayMesh::release()
{
    m_vao.reset();
    m_vbo.reset();
    m_program.reset();
}

void OverlayMesh::draw(const OverlayFrame& frame, const OverlayGeometry& geometry)
{
    if (!m_program || geometry.empty()) return;
    Eigen::Matrix4d model = Eigen::Matrix4d::Identity();
    model.topRightCorner<3, 1>() = geometry.origin();
    const Eigen::Matrix4f matrix = (frame.projection * frame.view * model).cast<float>();
    const auto& vertices = geometry.triangles();

    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    m_program->bind();
    glUniformMatrix4fv(m_program->uniformLocation("uMatrix"), 1, GL_FALSE, matrix.data());
    {
        QOpenGLVertexArrayObject::Binder bind(m_vao.get());
        m_vbo->bind();
        m_vbo->allocate(vertices.data(), int(vertices.size() * sizeof(OverlayVertex)));
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size()));
        m_vbo->release();
    }
    m_program->release();
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
}

} // namespace stylos::widgets
