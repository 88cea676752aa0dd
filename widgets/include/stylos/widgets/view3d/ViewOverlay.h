#pragma once
/** @file
 * @brief Something the 3D view draws over the points: a marker, guides, a gizmo, annotation tints. The view
 *        keeps a list of overlays (ViewportWidget::addOverlay / removeOverlay) and draws them in that order
 *        after the points, on every frame it shows — a quick frame or the complete full-detail image — so
 *        changing an overlay costs one frame (ViewportWidget::requestFrame()), never a new image or cut.
 *
 * GL: OpenGL 3.3 core, with the view's context current in every call. initialize() runs once the view's
 * GL has started (at once when added later), release() when the overlay is removed, before the context
 * goes, or when the view is destroyed; initialize() may follow a release() again (a new context).
 * draw() finds the target framebuffer bound and its viewport set; the depth buffer holds the points'
 * depth only in quick frames (the full-detail image is copied colour only), so do not depth-test against
 * the points; leave the depth test enabled and blending off as found. GUI thread only.
 * Failure modes: initialize() returns false when it cannot build its GL objects; the view then does not
 * draw that overlay (and says so once with qWarning).
 */
#include "stylos/core/view/Camera.h"

#include <QSize>

#include <Eigen/Core>

namespace stylos::widgets {

/** @brief What an overlay draws for: the camera and its matrices (scene frame, metres), the target's size. */
struct OverlayFrame {
    const core::view::Camera& camera;
    Eigen::Matrix4d view = Eigen::Matrix4d::Identity();        ///< scene → camera (camera.viewMatrix())
    Eigen::Matrix4d projection = Eigen::Matrix4d::Identity();  ///< camera → clip (camera.projectionMatrix())
    QSize size;                                                ///< the target framebuffer, device pixels
    double devicePixelRatio = 1.0;                             ///< device pixels per logical pixel of the camera
};

class ViewOverlay {
public:
    virtual ~ViewOverlay() = default;

    /** @brief Creates the GL objects (context current); false when it cannot. */
    virtual bool initialize() = 0;
    /** @brief Draws into the bound framebuffer (context current). */
    virtual void draw(const OverlayFrame& frame) = 0;
    /** @brief Frees the GL objects (context current); initialize() may be called again. */
    virtual void release() = 0;
};

} // namespace stylos::widgets
