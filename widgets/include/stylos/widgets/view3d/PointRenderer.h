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
 * colour; ViewComposite adds the eye-dome lighting from the depth). The selection is not tinted: with
 * Pass::selectionInAlpha it goes to alpha and ViewComposite outlines it.
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
#include <map>
#include <memory>
#include <optional>
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
    enum class Shading { Headlight, Ambient, Colour, EyeDome };

    /** @brief Which splats one draw() call draws, and how. */
    struct Pass {
        double from = 0;                ///< slice of every buffer, fractions in [0, 1]
        double to = 1;
        bool enlarge = false;           ///< splats × √(1 / (to − from)) (a subsample standing for the whole)
        bool cullBackFaces = false;     ///< skip splats whose normal faces away from the eye
        double pixelScale = 1.0;        ///< device pixels per logical pixel of the camera's viewport
        bool selectionInAlpha = false;  ///< alpha 1 for selected fragments, 0.5 for the others (else 1)
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

    core::view::ViewFragment* find(std::uint64_t id);
    const core::view::ViewFragment* find(std::uint64_t id) const;

    std::vector<core::view::ViewFragment> m_fragments;
    std::map<std::uint64_t, std::unique_ptr<Slot>> m_slots;
    std::unique_ptr<QOpenGLShaderProgram> m_program;
    QString m_log;
    Shading m_shading = Shading::Headlight;
    double m_splatFactor = 1.5;
    bool m_round = true;
    float m_maxPointSize = 64;
};

} // namespace stylos::widgets
