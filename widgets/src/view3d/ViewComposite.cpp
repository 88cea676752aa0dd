#include "stylos/widgets/view3d/ViewComposite.h"
#include "view3d/ShaderProgram.h"

#include <QOpenGLShaderProgram>

#include <Eigen/Core>

namespace stylos::widgets {

namespace {

const char* const VertexShader = R"(#version 330 core
out vec2 vUv;
void main()
{
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2); // (0,0) (2,0) (0,2): one triangle over the screen
    vUv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

const char* const FragmentShader = R"(#version 330 core
in vec2 vUv;
uniform sampler2D uColour;
uniform sampler2D uDepth;
uniform vec2 uTexel;          // one source pixel in texture coordinates
uniform bool uEyeDome;
uniform float uStrength;
uniform bool uOutline;
uniform vec3 uOutlineColour;
uniform bool uOrthographic;
uniform float uA;             // projection (2,2) and (2,3): NDC depth → linear depth
uniform float uB;
out vec4 fragColour;

float logDepth(float d)
{
    float z = d * 2.0 - 1.0;
    float linear = uOrthographic ? (uB - z) / uA : uB / (z + uA);
    return log2(max(linear, 1e-6));
}

const vec2 Ring[8] = vec2[8](vec2(1, 0), vec2(-1, 0), vec2(0, 1), vec2(0, -1),
                             vec2(0.7071, 0.7071), vec2(-0.7071, 0.7071), vec2(0.7071, -0.7071), vec2(-0.7071, -0.7071));

void main()
{
    vec4 colour = texture(uColour, vUv);
    float depth = texture(uDepth, vUv).r;
    vec3 rgb = colour.rgb;
    if (uEyeDome && depth < 1.0) {
        float here = logDepth(depth);
        float sum = 0.0;
        for (int i = 0; i < 8; ++i) {
            float d = texture(uDepth, vUv + Ring[i] * 1.5 * uTexel).r;
            if (d < 1.0) sum += max(0.0, here - logDepth(d));
        }
        rgb *= exp(-sum / 8.0 * 300.0 * uStrength);
    }
    if (uOutline && colour.a < 0.75) {
        float near = 0.0;
        for (int i = 0; i < 8; ++i) {
            near = max(near, step(0.75, texture(uColour, vUv + Ring[i] * uTexel).a));
            near = max(near, step(0.75, texture(uColour, vUv + Ring[i] * 2.5 * uTexel).a) * 0.8);
        }
        rgb = mix(rgb, uOutlineColour, near);
        if (near > 0.0) depth = min(depth, 0.99999);
    }
    fragColour = vec4(rgb, 1.0);
    gl_FragDepth = depth;
}
)";

} // namespace

ViewComposite::ViewComposite() = default;
ViewComposite::~ViewComposite() = default;

bool ViewComposite::initialize()
{
    initializeOpenGLFunctions();
    m_program = linkShaderProgram(VertexShader, FragmentShader);
    if (!m_program) return false;
    glGenVertexArrays(1, &m_vao);
    return true;
}

void ViewComposite::release()
{
    if (m_vao) glDeleteVertexArrays(1, &m_vao);
    m_vao = 0;
    m_program.reset();
}

void ViewComposite::draw(const OffscreenFrame& source, unsigned target, const QSize& targetSize,
                         const core::view::Camera& camera, const Options& options)
{
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, targetSize.width(), targetSize.height());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    m_program->bind();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, source.colourTexture());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, source.depthTexture());
    m_program->setUniformValue("uColour", 0);
    m_program->setUniformValue("uDepth", 1);
    m_program->setUniformValue("uTexel", 1.0f / float(source.size().width()), 1.0f / float(source.size().height()));
    m_program->setUniformValue("uEyeDome", options.eyeDome);
    m_program->setUniformValue("uStrength", options.eyeDomeStrength);
    m_program->setUniformValue("uOutline", options.outline);
    m_program->setUniformValue("uOutlineColour", float(options.outlineColour.redF()),
                               float(options.outlineColour.greenF()), float(options.outlineColour.blueF()));
    const Eigen::Matrix4d projection = camera.projectionMatrix();
    m_program->setUniformValue("uOrthographic", camera.isOrthographic());
    m_program->setUniformValue("uA", float(projection(2, 2)));
    m_program->setUniformValue("uB", float(projection(2, 3)));
    glBindVertexArray(m_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    m_program->release();
    glDepthFunc(GL_LESS);
}

} // namespace stylos::widgets
