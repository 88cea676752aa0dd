#pragma once
/** @file
 * @brief A 3D panel rendered for print on the CPU: the leaves of one or more packed octrees, each placed by its
 *        pose, seen orthographically from a standard side (core/view/Camera.h: Front looks from −Y toward +Y
 *        with Z up), at an exact pixel size on the object (the plate's 1:N at D dpi), at full detail (every
 *        leaf; no point budget, no level of detail).
 *
 * Why the CPU: a print is large (a 200 mm panel at 600 dpi is 4724 pixels wide, over the GL limits of many
 * laptops), must work with no display (stylos-cli on a server) and must be the same file twice; a software
 * z-buffer gives all three. Each leaf is a disc of radius 0.75 · spacing · splatScale (the leaf's share of the
 * surface, octree/LeafSpacing.h) in the plane of its normal, rasterised with its true depth per pixel (the
 * disc's plane, or a screen circle when it is nearly edge-on), so discs interpenetrate as surfaces do and no
 * paper shows through a scanned surface. Shading: headlight (lit from the viewer, two-sided: 0.12 + 0.88 |n·v|)
 * or skydome (the octree's "ambient" layer a, as a · (0.8 + 0.2 |n·v|)); white paper elsewhere. With a layer,
 * the class id of the nearest leaf per pixel is kept (PanelImage::classes).
 *
 * Cost: two passes over the leaves (bounds, then discs) and about π r² pixel tests per leaf (r in pixels);
 * memory 7 bytes per pixel (depth, grey, class) besides the octrees (mapped) and their labels. A frame over
 * @p maxPixels is refused before anything is allocated.
 * Failure modes: InvalidArgument (no source, a pixel size ≤ 0, skydome shading of an octree without an
 * "ambient" layer — naming the octree —, labels of the wrong length); OutOfBudget (the frame's size in pixels,
 * and the limit); Cancelled. Thread-safety: reentrant (octrees are only read).
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/plate/PanelImage.h"
#include "stylos/core/plate/PlateSpec.h"
#include "stylos/core/scene/Pose.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"
#include "stylos/core/view/Camera.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace stylos::core::plate {

struct OrthoSource {
    const octree::PackedOctree* octree = nullptr;
    scene::Pose pose;                       ///< octree frame → the panel's frame
    std::vector<std::uint8_t> labels;       ///< one class id per leaf, or empty
};

struct OrthoOptions {
    view::StandardView view = view::StandardView::Front;
    std::optional<Eigen::Quaterniond> orientation; ///< when set, the camera's orientation instead of @p view
    double pixelSizeM = 0.001;              ///< metres on the object per pixel
    PanelShading shading = PanelShading::Headlight;  ///< Headlight or Skydome
    double splatScale = 1.0;
    bool keepClasses = false;               ///< fill PanelImage::classes from the sources' labels
    std::uint64_t maxPixels = 600'000'000;
};

struct OrthoRender {
    PanelImage image;                       ///< grey
    double extentM[2] = {0, 0};             ///< width and height on the object, metres (= pixels · pixel size)
    std::uint64_t leaves = 0;
};

/** @brief The frame's size in pixels and metres for @p sources, without rendering (one pass over the leaves). */
Result<OrthoRender> measureOrtho(std::span<const OrthoSource> sources, const OrthoOptions& options);

/** @brief Renders @p sources (see the file comment). Progress over the leaves. */
Result<OrthoRender> renderOrtho(std::span<const OrthoSource> sources, const OrthoOptions& options,
                                ProgressSink* progress = nullptr);

/** @brief The camera side of a 3D panel view (Developpee and Camera have none: asserted). */
view::StandardView standardViewOf(PanelView view);

/** @brief The camera orientation (camera → scene) of a 3D panel: its stated camera or its standard side. */
Eigen::Quaterniond panelOrientation(const PanelSpec& panel);

} // namespace stylos::core::plate
