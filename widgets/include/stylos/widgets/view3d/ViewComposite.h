#pragma once
/** @file
 * @brief The pass that brings an offscreen frame (OffscreenFrame: colour, with the selection in alpha,
 *        and depth) to the widget's framebuffer: a full-screen triangle that copies the colour, fills the gaps
 *        between splats (core/view/GapFill.h's rule, step for step: background or a far surface enclosed by
 *        nearer splats takes the colour and depth of the nearest of them; each splat's reach comes in alpha,
 *        PointRenderer::Pass::selectionInAlpha), adds
 *        eye-dome lighting (Boucheny's EDL as Potree and CloudCompare draw it: each pixel darkened by how
 *        much nearer it is than its 8 neighbours 1.5 px away, in log₂ of the linear depth) and an outline
 *        around the selected fragments (pixels not selected within 2 px of a selected one), and writes the
 *        depth, so that overlays drawn afterwards are hidden by the surface where they should be.
 *
 * Each combination of the three passes in use is its own program (the others compiled out, built on first use),
 * since llvmpipe pays for shader code that a uniform switches off; a moving frame that only scales the image up
 * runs a plain copy.
 *
 * GL context current, GUI thread only. Failure modes: initialize() returns false (then the caller blits).
 */
#include "stylos/core/view/Camera.h"
#include "stylos/core/view/GapFill.h"
#include "stylos/widgets/view3d/OffscreenFrame.h"

#include <QColor>
#include <QOpenGLFunctions_3_3_Core>

#include <array>
#include <memory>

class QOpenGLShaderProgram;

namespace stylos::widgets {

class GapTiles;

class ViewComposite : protected QOpenGLFunctions_3_3_Core {
public:
    struct Options {
        bool eyeDome = false;
        float eyeDomeStrength = 1.0f;
        bool outline = false;
        QColor outlineColour = QColor(90, 170, 255);
        bool gapFill = false;
        core::view::GapFillOptions gap;
    };

    ViewComposite();
    ~ViewComposite();
    bool initialize();
    void release();
    bool isInitialized() const;

    /** @brief Draws @p source into framebuffer @p target of @p targetSize (scaled) and leaves it bound. */
    void draw(const OffscreenFrame& source, unsigned target, const QSize& targetSize, const core::view::Camera& camera,
              const Options& options);

private:
    enum Pass : unsigned { GapFillPass = 1, EyeDomePass = 2, OutlinePass = 4 };
    /** @brief The program with @p passes (Pass bits) compiled in, linked on first use; null if it does not build. */
    QOpenGLShaderProgram* programFor(unsigned passes);

    std::array<std::unique_ptr<QOpenGLShaderProgram>, 8> m_programs;
    unsigned m_failed = 0; ///< bit p: the program of passes p did not build (not tried again)
    std::unique_ptr<GapTiles> m_tiles; ///< the pass's shortcut; none when it does not build (every pixel walks)
    GLuint m_vao = 0;
};

} // namespace stylos::widgets
