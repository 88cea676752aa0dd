#include "stylos/widgets/view3d/ViewComposite.h"
#include "view3d/GapTiles.h"
#include "view3d/ShaderProgram.h"

#include <QOpenGLShaderProgram>

#include <Eigen/Core>

#include <string>

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

// The fragment shader's body: compiled once per combination of the passes in use (GAP_FILL, EYE_DOME, OUTLINE
// defined or not, ViewComposite::programFor), because llvmpipe pays for code that a uniform switches off: with the
// gap filling merely compiled in, the orbit's quick frames drew a quarter of the points at the same frame time.
const char* const FragmentBody = R"(
in vec2 vUv;
uniform sampler2D uColour;
uniform sampler2D uDepth;
uniform vec2 uTexel;          // one source pixel in texture coordinates
uniform float uStrength;
uniform vec3 uOutlineColour;
uniform bool uOrthographic;
uniform float uA;             // projection (2,2) and (2,3): NDC depth → linear depth
uniform float uB;
uniform int uGapSteps;
uniform int uGapMinDirections;
uniform float uGapKeep;       // 1 − the depth margin
uniform bool uHasTiles;
uniform sampler2D uTiles;     // GapTiles: the nearest linear depth of each 8 × 8 tile
out vec4 fragColour;

float linearDepth(float d)
{
    float z = d * 2.0 - 1.0;
    return uOrthographic ? (uB - z) / uA : uB / (z + uA);
}

float logDepth(float d) { return log2(max(linearDepth(d), 1e-6)); }

#ifdef OUTLINE
bool selected(float alpha) { return alpha >= 0.5; } // alpha = (128 if selected) + the splat's reach, of 255

#endif

#ifdef GAP_FILL
// core/view/GapFill.h's rule, step for step (the same directions in the same order, in texel coordinates).
const ivec2 Directions[8] = ivec2[8](ivec2(1, 0), ivec2(-1, 0), ivec2(0, -1), ivec2(0, 1),
                                     ivec2(1, -1), ivec2(-1, -1), ivec2(1, 1), ivec2(-1, 1));
const float Background = 3.0e38;

void fillGap(ivec2 p, inout vec4 colour, inout float depth)
{
    ivec2 size = textureSize(uDepth, 0);
    float front = depth < 1.0 ? linearDepth(depth) * uGapKeep : Background;
    if (uHasTiles) { // nothing in front of p in the tiles its walks cover: nothing encloses it (the same result)
        ivec2 lo = max(p - uGapSteps, ivec2(0)) / 8, hi = min(p + uGapSteps, size - 1) / 8;
        float nearest = Background;
        for (int ty = lo.y; ty <= hi.y; ++ty)
            for (int tx = lo.x; tx <= hi.x; ++tx) nearest = min(nearest, texelFetch(uTiles, ivec2(tx, ty), 0).r);
        if (!(nearest < front)) return;
    }
    int enclosing = 0;
    float nearest = Background;
    ivec2 best = p;
    for (int k = 0; k < 8; ++k) {
        for (int s = 1; s <= uGapSteps; ++s) {
            ivec2 q = p + Directions[k] * s;
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) break;
            float d = texelFetch(uDepth, q, 0).r;
            if (d >= 1.0) continue;
            float z = linearDepth(d);
            if (!(z < front)) continue;
            int reach = int(texelFetch(uColour, q, 0).a * 255.0 + 0.5) & 127;
            if (s <= reach) {
                ++enclosing;
                if (z < nearest) { nearest = z; best = q; }
            }
            break;
        }
    }
    if (enclosing < uGapMinDirections) return;
    colour = texelFetch(uColour, best, 0);
    depth = texelFetch(uDepth, best, 0).r;
}
#endif

const vec2 Ring[8] = vec2[8](vec2(1, 0), vec2(-1, 0), vec2(0, 1), vec2(0, -1),
                             vec2(0.7071, 0.7071), vec2(-0.7071, 0.7071), vec2(0.7071, -0.7071), vec2(-0.7071, -0.7071));

void main()
{
    vec4 colour = texture(uColour, vUv);
    float depth = texture(uDepth, vUv).r;
#ifdef GAP_FILL
    fillGap(ivec2(vUv * vec2(textureSize(uDepth, 0))), colour, depth);
#endif
    vec3 rgb = colour.rgb;
#ifdef EYE_DOME
    if (depth < 1.0) {
        float here = logDepth(depth);
        float sum = 0.0;
        for (int i = 0; i < 8; ++i) {
            float d = texture(uDepth, vUv + Ring[i] * 1.5 * uTexel).r;
            if (d < 1.0) sum += max(0.0, here - logDepth(d));
        }
        rgb *= exp(-sum / 8.0 * 300.0 * uStrength);
    }
#endif
#ifdef OUTLINE
    if (!selected(colour.a)) {
        float near = 0.0;
        for (int i = 0; i < 8; ++i) {
            near = max(near, step(0.5, texture(uColour, vUv + Ring[i] * uTexel).a));
            near = max(near, step(0.5, texture(uColour, vUv + Ring[i] * 2.5 * uTexel).a) * 0.8);
        }
        rgb = mix(rgb, uOutlineColour, near);
        if (near > 0.0) depth = min(depth, 0.99999);
    }
#endif
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
    if (!programFor(0)) return false; // the plain copy builds, or there is no composite pass
    m_tiles = std::make_unique<GapTiles>();
    if (!m_tiles->initialize()) m_tiles.reset();
    glGenVertexArrays(1, &m_vao);
    return true;
}

void ViewComposite::release()
{
    if (m_vao) glDeleteVertexArrays(1, &m_vao);
    m_vao = 0;
    for (auto& program : m_programs) program.reset();
    m_failed = 0;
    if (m_tiles) m_tiles->release();
    m_tiles.reset();
}

QOpenGLShaderProgram* ViewComposite::programFor(unsigned passes)
{
    std::unique_ptr<QOpenGLShaderProgram>& program = m_programs[passes];
    if (program || (m_failed >> passes & 1u)) return program.get();
    std::string source = "#version 330 core\n";
    if (passes & GapFillPass) source += "#define GAP_FILL\n";
    if (passes & EyeDomePass) source += "#define EYE_DOME\n";
    if (passes & OutlinePass) source += "#define OUTLINE\n";
    source += FragmentBody;
    QString log;
    program = linkShaderProgram(VertexShader, source.c_str(), &log);
    if (!program) {
        m_failed |= 1u << passes;
        qWarning("ViewComposite: the composite program (passes %u) did not build: %s", passes, qPrintable(log));
    }
    return program.get();
}

bool ViewComposite::isInitialized() const { return m_programs[0] != nullptr; }

void ViewComposite::draw(const OffscreenFrame& source, unsigned target, const QSize& targetSize,
                         const core::view::Camera& camera, const Options& options)
{
    const Eigen::Matrix4d projection = camera.projectionMatrix();
    const bool tiles = options.gapFill && m_tiles &&
                       m_tiles->update(source.depthTexture(), source.size(), camera.isOrthographic(),
                                       float(projection(2, 2)), float(projection(2, 3)));
    const unsigned passes = (options.gapFill ? GapFillPass : 0u) | (options.eyeDome ? EyeDomePass : 0u) |
                            (options.outline ? OutlinePass : 0u);
    QOpenGLShaderProgram* program = programFor(passes);
    if (!program) program = programFor(0); // a variant that does not build: the plain copy rather than nothing
    if (!program) return;
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, targetSize.width(), targetSize.height());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    program->bind();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, source.colourTexture());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, source.depthTexture());
    program->setUniformValue("uColour", 0);
    program->setUniformValue("uDepth", 1);
    program->setUniformValue("uTexel", 1.0f / float(source.size().width()), 1.0f / float(source.size().height()));
    program->setUniformValue("uStrength", options.eyeDomeStrength);
    program->setUniformValue("uOutlineColour", float(options.outlineColour.redF()),
                               float(options.outlineColour.greenF()), float(options.outlineColour.blueF()));
    program->setUniformValue("uOrthographic", camera.isOrthographic());
    program->setUniformValue("uA", float(projection(2, 2)));
    program->setUniformValue("uB", float(projection(2, 3)));
    program->setUniformValue("uGapSteps", options.gap.maxSteps);
    program->setUniformValue("uGapMinDirections", options.gap.minDirections);
    program->setUniformValue("uGapKeep", 1.0f - options.gap.depthMargin);
    program->setUniformValue("uHasTiles", tiles);
    program->setUniformValue("uTiles", 2);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, tiles ? m_tiles->texture() : 0);
    glBindVertexArray(m_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    program->release();
    glDepthFunc(GL_LESS);
}

} // namespace stylos::widgets
