#include "view3d/GapTiles.h"
#include "view3d/ShaderProgram.h"

#include <QOpenGLShaderProgram>

namespace stylos::widgets {

namespace {

const char* const VertexShader = R"(#version 330 core
void main()
{
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

// linearDepth() as in ViewComposite's shader, operation for operation, so that a tile's minimum equals the
// smallest depth the composite pass computes for its pixels.
const char* const FragmentShader = R"(#version 330 core
uniform sampler2D uDepth;
uniform bool uOrthographic;
uniform float uA;
uniform float uB;
out vec4 fragColour;

float linearDepth(float d)
{
    float z = d * 2.0 - 1.0;
    return uOrthographic ? (uB - z) / uA : uB / (z + uA);
}

void main()
{
    ivec2 size = textureSize(uDepth, 0);
    ivec2 origin = ivec2(gl_FragCoord.xy) * 8;
    float nearest = 3.0e38;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            ivec2 q = origin + ivec2(x, y);
            if (q.x >= size.x || q.y >= size.y) continue;
            float d = texelFetch(uDepth, q, 0).r;
            if (d < 1.0) nearest = min(nearest, linearDepth(d));
        }
    fragColour = vec4(nearest, 0.0, 0.0, 1.0);
}
)";

} // namespace

GapTiles::GapTiles() = default;
GapTiles::~GapTiles() = default;

bool GapTiles::initialize()
{
    initializeOpenGLFunctions();
    m_program = linkShaderProgram(VertexShader, FragmentShader);
    if (!m_program) return false;
    glGenVertexArrays(1, &m_vao);
    return true;
}

void GapTiles::release()
{
    if (m_vao) glDeleteVertexArrays(1, &m_vao);
    if (m_fbo) glDeleteFramebuffers(1, &m_fbo);
    if (m_texture) glDeleteTextures(1, &m_texture);
    m_vao = m_fbo = m_texture = 0;
    m_size = {};
    m_program.reset();
}

bool GapTiles::update(GLuint depth, const QSize& size, bool orthographic, float a, float b)
{
    if (!m_program || size.isEmpty()) return false;
    const QSize tiles((size.width() + Tile - 1) / Tile, (size.height() + Tile - 1) / Tile);
    if (tiles != m_size || !m_fbo) {
        if (m_fbo) glDeleteFramebuffers(1, &m_fbo);
        if (m_texture) glDeleteTextures(1, &m_texture);
        glGenTextures(1, &m_texture);
        glBindTexture(GL_TEXTURE_2D, m_texture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, tiles.width(), tiles.height(), 0, GL_RED, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindTexture(GL_TEXTURE_2D, 0);
        glGenFramebuffers(1, &m_fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_texture, 0);
        const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (!complete) {
            glDeleteFramebuffers(1, &m_fbo);
            glDeleteTextures(1, &m_texture);
            m_fbo = m_texture = 0;
            m_size = {};
            return false;
        }
        m_size = tiles;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
    glViewport(0, 0, m_size.width(), m_size.height());
    glDisable(GL_DEPTH_TEST);
    m_program->bind();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, depth);
    m_program->setUniformValue("uDepth", 0);
    m_program->setUniformValue("uOrthographic", orthographic);
    m_program->setUniformValue("uA", a);
    m_program->setUniformValue("uB", b);
    glBindVertexArray(m_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    m_program->release();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return true;
}

} // namespace stylos::widgets
