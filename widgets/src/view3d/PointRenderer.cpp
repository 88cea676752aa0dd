#include "stylos/widgets/view3d/PointRenderer.h"
#include "view3d/ShaderProgram.h"

#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>

#include <algorithm>
#include <cmath>

namespace stylos::widgets {

using core::view::SplatBuffer;
using core::view::SplatVertex;
using core::view::ViewFragment;

namespace {

const char* const VertexShader = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in float aSize;
layout(location = 2) in vec4 aNormal;
layout(location = 3) in vec4 aColour;
layout(location = 4) in uint aLeaf;
uniform mat4 uModelView;
uniform mat4 uProjection;
uniform mat3 uNormalMatrix;
uniform float uPixelsPerMetre;  // perspective: at unit depth; orthographic: everywhere
uniform bool uOrthographic;
uniform float uSizeScale;
uniform float uMaxPointSize;
uniform int uShading;           // 0 headlight, 1 ambient, 2 colour, 3 eye-dome (flat, the relief from the depth pass),
                                // 4 annotation (over headlight or ambient: uAnnotationBase 0 or 1)
uniform int uAnnotationBase;
uniform bool uHasLabels;
uniform usamplerBuffer uLabels;        // one class id per leaf (R8UI)
uniform samplerBuffer uClassColours;   // 256 texels (RGBA8): the class colours, alpha 1 for a class of the legend
uniform vec3 uBaseColour;
uniform bool uCullBackFaces;
out vec3 vColour;
out vec3 vNormal;               // view space, unit, turned toward the eye (two-sided)
out vec3 vCentre;               // view space
out float vRadius;              // metres (view space) covered by half the sprite
flat out float vReach;          // half the sprite in pixels, rounded to 1..127: the gap-filling pass's reach
void main()
{
    vec4 viewPosition = uModelView * vec4(aPosition, 1.0);
    gl_Position = uProjection * viewPosition;
    float depth = uOrthographic ? 1.0 : max(-viewPosition.z, 1e-6);
    gl_PointSize = clamp(aSize * uSizeScale * uPixelsPerMetre / depth, 1.0, uMaxPointSize);
    vRadius = 0.5 * gl_PointSize * depth / uPixelsPerMetre;
    vReach = clamp(floor(0.5 * gl_PointSize + 0.5), 1.0, 127.0);
    vCentre = viewPosition.xyz;
    vec3 n = uNormalMatrix * aNormal.xyz;
    float len = length(n);
    vec3 toEye = uOrthographic ? vec3(0.0, 0.0, 1.0) : normalize(-viewPosition.xyz);
    n = len > 0.0 ? n / len : toEye;
    float facing = dot(n, toEye);
    if (uCullBackFaces && facing < -0.2) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // outside the clip volume: dropped before rasterisation
        return;
    }
    if (facing < 0.0) { n = -n; facing = -facing; } // two-sided: a cell never goes black for facing away
    vNormal = n;
    float lambert = facing;
    int shading = uShading == 4 ? uAnnotationBase : uShading;
    vec3 colour;
    if (shading == 1) // the skydome squared (grooves 0.77 → 0.59, fillets 0.94 → 0.88), a touch of headlight for form
        colour = vec3(0.95) * aColour.a * aColour.a * (0.7 + 0.3 * lambert);
    else if (shading == 2)
        colour = aColour.rgb * (0.3 + 0.7 * lambert);
    else if (shading == 3)
        colour = uBaseColour;
    else
        colour = uBaseColour * (0.12 + 0.88 * lambert);
    if (uShading == 4 && uHasLabels) { // the class colour over the shading; unlabelled cells keep the shading
        uint id = texelFetch(uLabels, int(aLeaf)).r;
        if (id != 0u) {
            vec4 tint = texelFetch(uClassColours, int(id));
            if (tint.a > 0.5) colour = 0.35 * colour + 0.65 * tint.rgb;
        }
    }
    vColour = colour;
}
)";

// Round splats are discs in the plane of the cell's normal (the sprite's pixels outside the projected disc are
// discarded), their depth that of the disc at each pixel, so that neighbouring discs cut each other along clean
// seams instead of stacking by drawing order; the normal's view z is kept above 0.35 so that grazing discs stay
// wide enough to close the surface. With uEncodeAlpha, alpha carries for the composite pass (ViewComposite) the
// selection (128) plus the splat's reach in pixels (1..127, core/view/GapFill.h), else it is 1.
const char* const FragmentShader = R"(#version 330 core
in vec3 vColour;
in vec3 vNormal;
in vec3 vCentre;
in float vRadius;
flat in float vReach;
uniform bool uRound;
uniform bool uEncodeAlpha;
uniform bool uSelected;
uniform bool uOrthographic;
uniform mat4 uProjection;
out vec4 fragColour;
void main()
{
    if (uRound) {
        vec2 d = vec2(gl_PointCoord.x * 2.0 - 1.0, 1.0 - gl_PointCoord.y * 2.0);
        float nz = max(vNormal.z, 0.35);
        float dz = -(vNormal.x * d.x + vNormal.y * d.y) / nz;
        if (dot(d, d) + dz * dz > 1.0) discard;
        vec3 p = vCentre + vec3(d * vRadius, dz * vRadius);
        vec4 clip = uProjection * vec4(p, 1.0);
        gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
    } else {
        gl_FragDepth = gl_FragCoord.z;
    }
    fragColour = vec4(vColour, uEncodeAlpha ? ((uSelected ? 128.0 : 0.0) + vReach) / 255.0 : 1.0);
}
)";

} // namespace

struct PointRenderer::Slot {
    QOpenGLBuffer vbo{QOpenGLBuffer::VertexBuffer};
    QOpenGLVertexArrayObject vao;
    std::uint64_t count = 0;
    std::array<double, 3> origin{};
    bool hasColour = false;
    bool hasAmbient = false;
};

PointRenderer::PointRenderer() = default;
PointRenderer::~PointRenderer() = default;

bool PointRenderer::initialize()
{
    initializeOpenGLFunctions();
    m_program = linkShaderProgram(VertexShader, FragmentShader, &m_log);
    if (!m_program) return false;
    m_program->bind();
    m_program->setUniformValue("uLabels", 0);        // texture units
    m_program->setUniformValue("uClassColours", 1);
    m_program->release();
    GLint maxTexels = 65536;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    m_maxLabels = std::uint64_t(std::max(maxTexels, 0));
    m_coloursDirty = true;
    GLfloat range[2] = {1, 64};
    glGetFloatv(GL_POINT_SIZE_RANGE, range);
    m_maxPointSize = std::clamp(range[1], 1.0f, 256.0f);
    return true;
}

void PointRenderer::release()
{
    m_slots.clear(); // QOpenGLBuffer / VAO destructors free their objects in the current context
    for (auto& [id, labels] : m_labels) freeTextureBuffer(labels);
    m_labels.clear();
    if (m_colours) freeTextureBuffer(*m_colours);
    m_colours.reset();
    m_program.reset();
}

void PointRenderer::freeTextureBuffer(TextureBuffer& t)
{
    if (t.texture) glDeleteTextures(1, &t.texture);
    if (t.buffer) glDeleteBuffers(1, &t.buffer);
    t = {};
}

void PointRenderer::fillTextureBuffer(TextureBuffer& t, GLenum format, const void* data, std::uint64_t texels,
                                      std::uint64_t bytes)
{
    if (!t.buffer) glGenBuffers(1, &t.buffer);
    if (!t.texture) glGenTextures(1, &t.texture);
    glBindBuffer(GL_TEXTURE_BUFFER, t.buffer);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(bytes), data, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    glBindTexture(GL_TEXTURE_BUFFER, t.texture);
    glTexBuffer(GL_TEXTURE_BUFFER, format, t.buffer);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    t.size = texels;
}

bool PointRenderer::setLabels(std::uint64_t id, std::span<const std::uint8_t> labels)
{
    if (!m_program) return false;
    if (labels.empty() || labels.size() > m_maxLabels) { // more leaves than a buffer texture holds: no tint
        clearLabels(id);
        return false;
    }
    fillTextureBuffer(m_labels[id], GL_R8UI, labels.data(), labels.size(), labels.size());
    return true;
}

bool PointRenderer::updateLabels(std::uint64_t id, std::uint64_t first, std::span<const std::uint8_t> labels)
{
    const auto it = m_labels.find(id);
    if (!m_program || it == m_labels.end() || first > it->second.size || labels.size() > it->second.size - first)
        return false;
    if (labels.empty()) return true;
    glBindBuffer(GL_TEXTURE_BUFFER, it->second.buffer);
    glBufferSubData(GL_TEXTURE_BUFFER, GLintptr(first), GLsizeiptr(labels.size()), labels.data());
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    return true;
}

void PointRenderer::clearLabels(std::uint64_t id)
{
    const auto it = m_labels.find(id);
    if (it == m_labels.end()) return;
    freeTextureBuffer(it->second);
    m_labels.erase(it);
}

void PointRenderer::clearAllLabels()
{
    for (auto& [id, labels] : m_labels) freeTextureBuffer(labels);
    m_labels.clear();
}

bool PointRenderer::hasLabels(std::uint64_t id) const { return m_labels.count(id) != 0; }

void PointRenderer::setClassColours(const ClassColours& colours)
{
    m_classColours = colours;
    m_coloursDirty = true;
}

void PointRenderer::setSplatFactor(double factor) { m_splatFactor = std::clamp(factor, 0.1, 10.0); }

ViewFragment* PointRenderer::find(std::uint64_t id)
{
    auto it = std::find_if(m_fragments.begin(), m_fragments.end(), [id](const ViewFragment& f) { return f.id == id; });
    return it == m_fragments.end() ? nullptr : &*it;
}

const ViewFragment* PointRenderer::find(std::uint64_t id) const { return const_cast<PointRenderer*>(this)->find(id); }

void PointRenderer::setFragments(const std::vector<ViewFragment>& fragments)
{
    m_fragments = fragments;
    for (auto it = m_slots.begin(); it != m_slots.end();) {
        const ViewFragment* f = find(it->first);
        it = (f && f->octree) ? std::next(it) : m_slots.erase(it);
    }
}

bool PointRenderer::setPose(std::uint64_t id, const Eigen::Matrix4d& pose)
{
    ViewFragment* f = find(id);
    if (!f) return false;
    f->pose = pose;
    return true;
}

std::optional<Eigen::Matrix4d> PointRenderer::modelMatrix(std::uint64_t id) const
{
    const ViewFragment* f = find(id);
    const auto it = m_slots.find(id);
    if (!f || it == m_slots.end()) return std::nullopt;
    const auto& origin = it->second->origin;
    Eigen::Matrix4d toOctree = Eigen::Matrix4d::Identity();
    toOctree.topRightCorner<3, 1>() = Eigen::Vector3d(origin[0], origin[1], origin[2]);
    return Eigen::Matrix4d(f->pose * toOctree);
}

void PointRenderer::upload(std::uint64_t id, const SplatBuffer& splats)
{
    if (!find(id)) return;
    auto& slot = m_slots[id];
    if (!slot) {
        slot = std::make_unique<Slot>();
        slot->vao.create();
        slot->vbo.create();
        slot->vbo.setUsagePattern(QOpenGLBuffer::StaticDraw);
        QOpenGLVertexArrayObject::Binder bind(&slot->vao);
        slot->vbo.bind();
        const GLsizei stride = sizeof(SplatVertex);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(0));
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(12));
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(2, 4, GL_BYTE, GL_TRUE, stride, reinterpret_cast<void*>(16));
        glEnableVertexAttribArray(3);
        glVertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride, reinterpret_cast<void*>(20));
        glEnableVertexAttribArray(4);
        glVertexAttribIPointer(4, 1, GL_UNSIGNED_INT, stride, reinterpret_cast<void*>(24));
        slot->vbo.release();
    }
    slot->vbo.bind();
    slot->vbo.allocate(splats.vertices.data(), int(splats.vertices.size() * sizeof(SplatVertex)));
    slot->vbo.release();
    slot->count = splats.vertices.size();
    slot->origin = splats.origin;
    slot->hasColour = splats.hasColour;
    slot->hasAmbient = splats.hasAmbient;
}

std::uint64_t PointRenderer::bufferedPoints() const
{
    std::uint64_t n = 0;
    for (const auto& [id, slot] : m_slots) n += slot->count;
    return n;
}

bool PointRenderer::hasAmbient() const
{
    return std::any_of(m_slots.begin(), m_slots.end(), [](const auto& s) { return s.second->hasAmbient; });
}

bool PointRenderer::hasColour() const
{
    return std::any_of(m_slots.begin(), m_slots.end(), [](const auto& s) { return s.second->hasColour; });
}

bool PointRenderer::hasSelection() const
{
    return std::any_of(m_fragments.begin(), m_fragments.end(), [this](const ViewFragment& f) {
        return f.visible && f.selected && m_slots.count(f.id) != 0;
    });
}

std::uint64_t PointRenderer::visiblePoints() const
{
    std::uint64_t total = 0;
    for (const ViewFragment& f : m_fragments)
        if (auto it = m_slots.find(f.id); f.visible && it != m_slots.end()) total += it->second->count;
    return total;
}

std::uint64_t PointRenderer::draw(const core::view::Camera& camera, const Pass& pass)
{
    const double from = std::clamp(pass.from, 0.0, 1.0), to = std::clamp(pass.to, from, 1.0);
    if (!m_program || to <= from || visiblePoints() == 0) return 0;
    const double enlarge = pass.enlarge ? std::sqrt(1.0 / (to - from)) : 1.0;

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_PROGRAM_POINT_SIZE);
    m_program->bind();
    const Eigen::Matrix4d view = camera.viewMatrix();
    const Eigen::Matrix4f projection = camera.projectionMatrix().cast<float>();
    const double pixelsPerMetre = camera.isOrthographic() ? camera.pixelsPerMetre()
                                                          : camera.pixelsPerMetre() * camera.distance();
    glUniformMatrix4fv(m_program->uniformLocation("uProjection"), 1, GL_FALSE, projection.data());
    m_program->setUniformValue("uPixelsPerMetre", float(pixelsPerMetre * pass.pixelScale));
    m_program->setUniformValue("uCullBackFaces", pass.cullBackFaces);
    m_program->setUniformValue("uSizeScale", float(m_splatFactor * enlarge));
    m_program->setUniformValue("uOrthographic", camera.isOrthographic());
    m_program->setUniformValue("uMaxPointSize", m_maxPointSize);
    m_program->setUniformValue("uRound", m_round);
    const bool annotation = m_shading == Shading::Annotation;
    if (annotation) {
        if (m_coloursDirty || !m_colours) {
            if (!m_colours) m_colours = std::make_unique<TextureBuffer>();
            fillTextureBuffer(*m_colours, GL_RGBA8, m_classColours.data(), m_classColours.size(), sizeof(m_classColours));
            m_coloursDirty = false;
        }
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_BUFFER, m_colours->texture);
        glActiveTexture(GL_TEXTURE0);
    }

    std::uint64_t drawn = 0;
    for (const ViewFragment& f : m_fragments) {
        auto it = m_slots.find(f.id);
        if (!f.visible || it == m_slots.end() || it->second->count == 0) continue;
        Slot& slot = *it->second;
        const auto first = std::uint64_t(std::floor(double(slot.count) * from));
        const std::uint64_t last = to >= 1.0 ? slot.count : std::uint64_t(std::floor(double(slot.count) * to));
        if (last <= first) continue;
        const Eigen::Matrix4d modelView = view * *modelMatrix(f.id); // double until here: site coordinates are large
        const Eigen::Matrix4f mv = modelView.cast<float>();
        const Eigen::Matrix3f normalMatrix = mv.topLeftCorner<3, 3>(); // rigid: the rotation is its own inverse transpose
        glUniformMatrix4fv(m_program->uniformLocation("uModelView"), 1, GL_FALSE, mv.data());
        glUniformMatrix3fv(m_program->uniformLocation("uNormalMatrix"), 1, GL_FALSE, normalMatrix.data());
        int shading = 0;
        if (m_shading == Shading::Ambient && slot.hasAmbient) shading = 1;
        if (m_shading == Shading::Colour && slot.hasColour) shading = 2;
        if (m_shading == Shading::EyeDome) shading = 3;
        const auto labels = annotation ? m_labels.find(f.id) : m_labels.end();
        if (annotation) {
            shading = 4;
            m_program->setUniformValue("uAnnotationBase", slot.hasAmbient ? 1 : 0);
            m_program->setUniformValue("uHasLabels", labels != m_labels.end());
            glBindTexture(GL_TEXTURE_BUFFER, labels != m_labels.end() ? labels->second.texture : 0);
        }
        m_program->setUniformValue("uShading", shading);
        m_program->setUniformValue("uBaseColour", float(f.colour[0]) / 255.0f, float(f.colour[1]) / 255.0f,
                                   float(f.colour[2]) / 255.0f);
        m_program->setUniformValue("uEncodeAlpha", pass.selectionInAlpha);
        m_program->setUniformValue("uSelected", f.selected);
        QOpenGLVertexArrayObject::Binder bind(&slot.vao);
        glDrawArrays(GL_POINTS, GLint(first), GLsizei(last - first));
        drawn += last - first;
    }
    if (annotation) { // leave no buffer texture bound
        glBindTexture(GL_TEXTURE_BUFFER, 0);
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_BUFFER, 0);
        glActiveTexture(GL_TEXTURE0);
    }
    m_program->release();
    return drawn;
}

} // namespace stylos::widgets
