#pragma once
/** @file
 * @brief What a plate is made from, and each panel's picture at print resolution.
 *
 * Sources: a project (`.stylos`: its fragments with their world poses, visibility and legend), a packed octree
 * (`.poct`: one fragment at the identity) or a point file (one fragment; its octree is built at depth 12 into
 * @p scratch on demand, for 3D panels only — a développée reads the points directly).
 *
 * renderPanel: a panel at 1:N and D dpi has pixels of P = N · 25.4 / D mm on the object.
 * - Développée (of the named fragment, or the first): computed as the fragment's `unrolling` says (the axis,
 *   radius and settings the workbench unrolled it with; from a project, its axis guide or its assembly drum's),
 *   in the panel's shading, at its own pixel size (the sampling spacing unless `unrolling` gives one),
 *   then resampled to round(aR / P) × round(height / P) plate pixels, a the développée's arc (2π for a drum,
 *   periodic across the seam; a fragment's own arc, UnrollOptions::cropToPoints); it is placed exactly
 *   aR · 1000 / N mm wide on paper. The classes of the layer, when asked, come from the octree's
 *   layer through the développée's map (majority per pixel, annotation/LabelRaster.h), resampled nearest.
 * - 3D (front, back, …; every visible fragment, or the named one): renderOrtho at exactly P.
 * Then the classes tint the picture in legend colours unless the panel asks for hatches.
 * Failure modes: the readers' and computeDeveloppee's errors (naming the file); InvalidArgument for a fragment
 * name not in the project, a panel whose octree is missing (naming the fragment and its path), labels asked of
 * a point file; OutOfBudget when the picture would be over @p maxPixels (what size and the limit).
 * Thread-safety: reentrant.
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/plate/PanelImage.h"
#include "stylos/core/plate/PlateSpec.h"
#include "stylos/core/scene/Pose.h"
#include "stylos/core/scene/Scene.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stylos::core::plate {

struct PlateFragment {
    std::string name;
    std::filesystem::path path;     ///< the .poct, or the point file
    bool isOctree = true;
    bool missing = false;           ///< a project's octree that was not found
    scene::Pose pose;               ///< fragment → scene
    bool visible = true;
    /** Labels held in memory (the workbench's unsaved edits), per layer (material, toolmark), used instead of
     *  the octree's layers when set; one id per leaf. */
    std::array<std::shared_ptr<const std::vector<std::uint8_t>>, 2> labels;
    /** How its développée is unrolled (axis, radius, taper, pixel size, skydome directions and smoothing, light),
     *  so that a plate shows the développée the workbench shows — the same axis, hence the same cut and angles;
     *  the panel's shading replaces this one's. Unset: an axis fitted to the points, every default. */
    std::optional<developpee::DeveloppeeOptions> unrolling;
    /** The drum whose guides give the radius and taper it unrolls at, as in the Développée dock: its octree and how
     *  its guides are fitted (dock::guideOptionsFor). Fitted when its développée is made, unless `unrolling` gives a
     *  radius already; a fit that fails leaves the radius fitted about the axis, as the dock does (a drum octree that
     *  cannot be read is an error naming it). */
    struct DrumGuidesSource {
        std::filesystem::path octree;
        dock::GuideOptions options;
    };
    std::optional<DrumGuidesSource> drumGuides;
};

struct PlateSources {
    std::string source;                       ///< the file the user named
    std::vector<PlateFragment> fragments;
    annotation::Legend legend = annotation::Legend::defaults();
    bool isProject = false;
};

/** @brief Sets @p out's unrolling (the axis) and drumGuides as the Développée dock unrolls @p fragment of @p scene
 *         against @p drum (its assembly's drum, or the workbench's docking drum): about the axis guide of
 *         scene::unrollAxisOwner, at the radius of that fragment's guides when they can be fitted. Leaves @p out
 *         as it is when neither has an axis guide. */
void unrollAsTheDock(PlateFragment& out, const scene::Scene& scene, scene::FragmentId fragment, scene::FragmentId drum);

/** @brief Reads @p path as a project, an octree or a point file (by content and extension). */
Result<PlateSources> readPlateSources(const std::filesystem::path& path);

struct RenderedPanel {
    PanelImage image;                  ///< at the plate's pixels, tinted unless hatched
    std::array<double, 2> imageMm{};   ///< its size on paper
    double pixelSizeM = 0;             ///< on the object, per plate pixel
    double naturalPixelM = 0;          ///< développée: the pixel size it was computed at
    double arcDegrees = 360;           ///< développée: the turn it spans (less for a fragment's arc)
    std::uint64_t leaves = 0;          ///< 3D: leaves drawn
};

struct PanelRenderOptions {
    int dpi = 600;
    std::filesystem::path scratch;     ///< a folder for octrees built from point files
    std::uint64_t maxPixels = 600'000'000;
    unsigned threads = 0;
};

/** @brief The object's pixel size at 1:@p scale and @p dpi: scale · 0.0254 / dpi metres. */
inline double printPixelSize(double scale, int dpi) { return scale * 0.0254 / double(dpi); }

Result<RenderedPanel> renderPanel(const PlateSources& sources, const PanelSpec& panel, const PanelRenderOptions& options,
                                  ProgressSink* progress = nullptr);

/**
 * @brief A 3D view (of @p panel: its side or camera, shading, layer, fragments) rendered @p widthPx pixels wide
 *        (16..100000), whatever its scale: Export view image. The frame's height follows the scene's extent.
 */
Result<RenderedPanel> renderViewImage(const PlateSources& sources, const PanelSpec& panel, int widthPx,
                                      const PanelRenderOptions& options = {}, ProgressSink* progress = nullptr);

} // namespace stylos::core::plate
