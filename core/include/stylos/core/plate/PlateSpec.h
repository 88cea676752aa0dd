#pragma once
/** @file
 * @brief What a publication plate holds, in millimetres, as a user or a layout file states it: the page (A4,
 *        A3, US letter, the journal print areas 170 × 105 and 205 × 135 mm, or W×H mm; portrait or landscape;
 *        margins), the print resolution, the caption, whether the legend is drawn, and the panels — each a view
 *        (the développée or an orthographic standard view) at 1:N with its shading and annotation layer.
 *        Plain data: nothing here renders or draws.
 *
 * Layout file (`stylos-cli plate PROJECT --layout PLATE.json`, and the "plate" key of a project):
 *     {"format": "stylos-plate", "version": 1, "page": "A4" | [W, H], "landscape": false, "margin_mm": 15,
 *      "dpi": 600, "bits": 8, "caption": "…", "legend": true,
 *      "panels": [{"view": "developpee", "scale": 10, "shading": "skydome", "layer": "material",
 *                  "hatches": false, "fragment": "Drum 2", "at_mm": [x, y]},
 *                 {"view": "camera", "camera": [w, x, y, z], "scale": 10, "shading": "headlight"}, …]}
 * Every key but "panels" is optional (defaults above; "layer" absent = no annotation; "fragment" absent = the
 * first fragment for a développée, every visible fragment for a 3D view; "at_mm" absent = stacked by
 * layoutPlate). Reading names the first wrong key ("PLATE.json: panels[1].scale: must be a number ≥ 1").
 * Units: millimetres on paper, 1:N scales. Thread-safety: value types.
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/util/Result.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stylos::core::plate {

/** @brief What a panel shows: the développée, the scene seen orthographically from one side, or orthographically
 *         along a stated camera orientation (the workbench's current view). */
enum class PanelView { Developpee, Front, Back, Left, Right, Top, Bottom, Camera };
/** "developpee", "front", "back", "left", "right", "top", "bottom", "camera". */
const char* panelViewName(PanelView view);
std::optional<PanelView> panelViewFromName(std::string_view name);

/** @brief Shading of a panel: skydome (visible sky), light (one directional light, développée only),
 *         height (développée only) or headlight (3D only: lit from the viewer). */
enum class PanelShading { Skydome, Light, Height, Headlight };
const char* panelShadingName(PanelShading shading);
std::optional<PanelShading> panelShadingFromName(std::string_view name);

struct PageSize {
    double widthMm = 210;
    double heightMm = 297;
    bool operator==(const PageSize&) const = default;
};

/**
 * @brief "A4" (210 × 297), "A3" (297 × 420), "letter" (215.9 × 279.4), "170x105" and "205x135" (the journal
 *        print areas, with no margin by default), or "WxH" in millimetres (each 10..2000); case-insensitive.
 */
std::optional<PageSize> pageFromName(std::string_view name);

struct PanelSpec {
    PanelView view = PanelView::Developpee;
    double scale = 10;                                  ///< 1:N, N ≥ 1
    PanelShading shading = PanelShading::Skydome;
    /** False for a 3D panel whose statement left the shading out (a layout file without "shading", stylos-cli plate
     *  without --shading): `shading` is then the skydome, which stylos-cli plate turns into the headlight where a
     *  fragment drawn has no skydome layer. Not written: a written panel states its shading. */
    bool shadingStated = true;
    std::optional<annotation::AnnotationLayer> layer;   ///< annotation drawn over the panel
    bool hatches = false;                               ///< classes as black-and-white hatches, not colours
    std::string fragment;                               ///< a project's fragment by name (see the file comment)
    std::optional<std::array<double, 2>> atMm;          ///< top-left of the image on the page
    /** View "camera": the camera's orientation (unit quaternion w, x, y, z; camera axes → scene axes, as
     *  core/view/Camera.h: the camera looks along its −Z with +Y up). Required for that view, ignored otherwise. */
    std::optional<std::array<double, 4>> camera;
    /** What the panel states; shadingStated, a reading's note that is never written, is left out (a plate read
     *  from a project equals itself read again after a save). */
    bool operator==(const PanelSpec& o) const
    {
        return view == o.view && scale == o.scale && shading == o.shading && layer == o.layer && hatches == o.hatches &&
               fragment == o.fragment && atMm == o.atMm && camera == o.camera;
    }
};

struct PlateSpec {
    static constexpr int kVersion = 1;
    static constexpr const char* kFormat = "stylos-plate";

    std::string pageName = "A4";   ///< as given ("A4", "170x105", "200x150")
    PageSize page;                 ///< portrait size of pageName
    bool landscape = false;
    double marginMm = 15;          ///< 0..(a third of the shorter side)
    int dpi = 600;                 ///< 72..2400: images are rendered at this resolution
    int bits = 8;                  ///< 8 or 16 bits per sample in TIFF / PNG output
    std::string caption;
    bool legend = true;            ///< draw the legend of the annotation layers in use
    std::vector<PanelSpec> panels;

    /** @brief The page as drawn: a named page portrait, or landscape (its longer side across); a W×H page as
     *  stated, or turned (width and height swapped) in landscape. */
    PageSize orientedPage() const;
    /** @brief InvalidArgument naming @p source and the key when a value is out of range (see the fields). */
    Status validate(const std::string& source) const;
    nlohmann::json toJson() const;
    /** @brief Reads toJson()'s object; Malformed "SOURCE: KEY: problem" naming the first wrong key. */
    static Result<PlateSpec> fromJson(const nlohmann::json& json, const std::string& source);
    /** @brief Reads a layout file (NotFound, Unreadable, Malformed naming @p path). */
    static Result<PlateSpec> read(const std::string& path);
    bool operator==(const PlateSpec&) const = default;
};

} // namespace stylos::core::plate
