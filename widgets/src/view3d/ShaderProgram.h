#pragma once
/** @file
 * @brief The one way the 3D view's passes build their GLSL program: a vertex and a fragment shader, linked.
 *        Needs a current OpenGL context. GUI thread only.
 */
#include <QOpenGLShaderProgram>
#include <QString>

#include <memory>

namespace stylos::widgets {

/** @brief The linked program of @p vertex and @p fragment; null on failure, with the compiler's log in @p log. */
inline std::unique_ptr<QOpenGLShaderProgram> linkShaderProgram(const char* vertex, const char* fragment,
                                                              QString* log = nullptr)
{
    auto program = std::make_unique<QOpenGLShaderProgram>();
    if (!program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex) ||
        !program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragment) || !program->link()) {
        if (log) *log = program->log();
        return nullptr;
    }
    return program;
}

} // namespace stylos::widgets
