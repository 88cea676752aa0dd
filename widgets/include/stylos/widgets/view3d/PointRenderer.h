#pragma once
/** @file
 * @brief Draws the fragments' cuts as splats with OpenGL 3.3 core: one vertex buffer per fragment
 *        (SplatBuffer uploaded as is), point sprites whose size follows the cell size and the projection
 *        (a cell of edge s at depth z covers s · f / z pixels, times the splat factor), round or square.
 *
 * Splats: round ones are discs in the plane of the cell's normal, with the depth of the disc at each pixel
 * (neighbours meet along seams, not in drawing order); their diameter is the splat factor times the
 * vertex's footprint (the larger of the cell edge and its leaf's spacing, SplatBuffer), so that the discs
 * close a scanned surface; square ones are screen-aligned squares of that size.
 *
 * Shading: two-sided (a normal facing away is turned toward the eye). Headlight (the fragment's colour
 * lit by a light at the eye, from the cells' normals),
 * Ambient (the "ambient" layer, the 3D skydome, as grey: its square, to read the relief like the paper's
 * figures, times 0.7 + 0.3 of the headlight for the form; falls back to Headlight without the layer),
 * Colour (the scan's colour lit by the headlight; falls back to Headlight without colour), EyeDome (flat
 * colour; ViewComposite adds the eye-dome lighting from the depth), Annotation (the skydome's shading where the
 * fragment has the "ambient" layer, else the headlight's, mixed 0.35 : 0.65 with the colour of the class of
 * the cell's leaf — SplatVertex::leaf — in the labels given with setLabels(); cells of class 0, of an id
 * that is no class (setClassColours) or of a fragment without labels keep the plain shading). The labels are
 * one buffer texture (R8UI, one byte a leaf) per fragment, apart from the splats: an edit re-sends the
 * touched range (updateLabels: glBufferSubData), never the splats. The selection is not tinted: with
 * Pass::selectionInAlpha it goes to alpha, with each splat's radius on screen (its reach), and ViewComposite
 * outlines it and fills the gaps between splats.
 *
 * Parts of the buffers: draw() draws the same slice [from, to) of every buffer (fractions of its
 * length). The buffers are shuffled, so a prefix is an even subsample: a moving frame draws [0, limit /
 * visiblePoints()) with splats enlarged by √(1 / (to − from)) to cover the gaps; the full-detail image
 * is drawn in consecutive slices at the normal size.
 *
 * Every method except the setters of display options needs the GL context current (initialize(),
 * upload(), draw(), release()); GUI thread only. Failure modes: initialize() returns false and
 * log() says why when a shader does not compile or link (no GL 3.3 core context).
 */
#include "stylos/core/view/Camera.h"
#include "stylos/core/view/SplatBuffer.h"
#include "stylos/core/view/ViewFragment.h"

#include <QOpenGLFunctions_3_3_Core>
#include <QString>

#include <Eigen/Core>

#include <cstdint>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <vector>

class QOpenGLBuffer;
class QOpenGLShaderProgram;
class QOpenGLVertexArrayObject;

namespace stylos::widgets {

class PointRenderer : protected QOpenGLFunctions_3_3_Core {
public:
    /**
     * @brief How splats are coloured. Each is one branch of the vertex shader (uShading); a mode that needs a
     *        per-leaf value adds it beside the "ambient" byte of SplatVertex (or a second vertex stream) and a
     *        branch there. EyeDome draws flat colour and leaves the relief to the composite pass.
     */
    enum class Shading { Headlight, Ambient, Colour, EyeDome, Annotation };
    /** @brief Per class id 0..255, its colour (sRGB, 8 bits) and alpha 255 when it is a class of the legend (else 0). */
    using ClassColours = std::array<std::array<std::uint8_t, 4>, 256>;

    /** @brief Which splats one draw() call draws, and how. */
    struct Pass {
        double from = 0;                ///< slice of every buffer, fractions in [0, 1]
        double to = 1;
        bool enlarge = false;           ///< splats × √(1 / (to − from)) (a subsample standing for the whole)
        bool cullBackFaces = false;     ///< skip splats whose normal faces away from the eye
        double pixelScale = 1.0;        ///< device pixels per logical pixel of the camera's viewport
        /// alpha (of 255) = 128 for selected fragments + the splat's reach, its radius in pixels rounded to 1..127
        /// (the gap-filling pass's, core/view/GapFill.h); else alpha 1
        bool selectionInAlpha = false;
    };

    PointRenderer();
    ~PointRenderer();
    PointRenderer(const PointRenderer&) = delete;
    PointRenderer& operator=(const PointRenderer&) = delete;

    /** @brief Compiles the shaders (context current). False, with log(), on failure. */
    bool initialize();
    /** @brief Frees every GL object (context current); initialize() may be called again. */
    void release();
    bool isInitialized() const { return m_program != nullptr; }
    QString log() const { return m_log; }

    /** @brief The fragments drawn, with their poses and colours; buffers of ids no longer present are freed. */
    void setFragments(const std::vector<core::view::ViewFragment>& fragments);
    /** @brief Moves fragment @p id (octree frame → scene frame); its buffer stays. False if no such fragment. */
    bool setPose(std::uint64_t id, const Eigen::Matrix4d& pose);
    /**
     * @brief The model matrix fragment @p id's splats are drawn with: from its buffer's frame (positions
     *        relative to the root box origin) to the scene frame, pose · translation(origin); empty without a
     *        buffer for it.
     */
    std::optional<Eigen::Matrix4d> modelMatrix(std::uint64_t id) const;
    /** @brief Replaces the splats of fragment @p id (ignored if no such fragment is set). */
    void upload(std::uint64_t id, const core::view::SplatBuffer& splats);
    /** @brief Splats held in buffers, all fragments (hidden ones included). */
    std::uint64_t bufferedPoints() const;
    /** @brief Splats held in the buffers of visible fragments. */
    std::uint64_t visiblePoints() const;
    /** @brief Whether some visible fragment has the "ambient" layer / scan colour in its buffer. */
    bool hasAmbient() const;
    bool hasColour() const;
    /** @brief Whether some visible fragment is selected. */
    bool hasSelection() const;

    /**
     * @brief The annotation labels of fragment @p id (one class id per leaf, leaf order), replacing any (context
     *        current). Kept until clearLabels(), whatever setFragments() does. False (and none kept) when
     *        empty or longer than a buffer texture holds (GL_MAX_TEXTURE_BUFFER_SIZE; the fragment is drawn
     *        untinted).
     */
    bool setLabels(std::uint64_t id, std::span<const std::uint8_t> labels);
    /** @brief Replaces the labels of @p id from leaf @p first on (context current); false without labels of
     *         @p id or when the range does not fit them (nothing changes). */
    bool updateLabels(std::uint64_t id, std::uint64_t first, std::span<const std::uint8_t> labels);
    /** @brief Frees the labels of @p id / of every fragment (context current). */
    void clearLabels(std::uint64_t id);
    void clearAllLabels();
    bool hasLabels(std::uint64_t id) const;
    /** @brief The legend's colours (uploaded by the next draw in Annotation shading; no context needed). */
    void setClassColours(const ClassColours& colours);
    const ClassColours& classColours() const { return m_classColours; }

    void setShading(Shading shading) { m_shading = shading; }
    Shading shading() const { return m_shading; }
    /** @brief Splat diameter / footprint (default 1.5; clamped to [0.1, 10]). */
    void setSplatFactor(double factor);
    double splatFactor() const { return m_splatFactor; }
    /** @brief Round splats (default) or squares. */
    void setRoundSplats(bool round) { m_round = round; }
    bool roundSplats() const { return m_round; }

    /**
     * @brief Draws @p pass of the visible fragments for @p camera into the bound framebuffer (depth test on;
     *        clears nothing; the viewport is the caller's). Returns the points drawn.
     */
    std::uint64_t draw(const core::view::Camera& camera, const Pass& pass);

private:
    struct Slot;
    /** A buffer texture: the buffer and the texture that reads it (R8UI labels or RGBA8 colours). */
    struct TextureBuffer {
        GLuint buffer = 0;
        GLuint texture = 0;
        std::uint64_t size = 0; ///< texels
    };

    void freeTextureBuffer(TextureBuffer& t);
    void fillTextureBuffer(TextureBuffer& t, GLenum format, const void* data, std::uint64_t texels, std::uint64_t bytes);

    core::view::ViewFragment* find(std::uint64_t id);
    const core::view::ViewFragment* find(std::uint64_t id) const;

    std::vector<core::view::ViewFragment> m_fragments;
    std::map<std::uint64_t, std::unique_ptr<Slot>> m_slots;
    std::map<std::uint64_t, TextureBuffer> m_labels;
    std::unique_ptr<TextureBuffer> m_colours;
    ClassColours m_classColours{};
    bool m_coloursDirty = true;
    std::uint64_t m_maxLabels = 65536;
    std::unique_ptr<QOpenGLShaderProgram> m_program;
    QString m_log;
    Shading m_shading = Shading::Headlight;
    double m_splatFactor = 1.5;
    bool m_round = true;
    float m_maxPointSize = 64;
};

} // namespace stylos::widgets
