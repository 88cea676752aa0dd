#pragma once
/** @file
 * @brief The annotation legend: two layers per object (material / condition, tool mark), each a list of
 *        classes {id 1..255, name, colour, black-and-white hatch}. Id 0 is "unlabelled" and never a class.
 *        Plain data: painting, tinting and plates read it; nothing here draws.
 *
 * JSON (docs/annotation.md):
 *     {"format": "stylos-legend", "version": 1,
 *      "layers": {"material": [{"id": 1, "name": "preserved marble", "colour": "#e8e0c8", "hatch": "none"}, …],
 *                 "toolmark": […]}}
 * Reading checks every key and names the first wrong one ("SOURCE: layers.material[2].id: duplicate id 3"):
 * format and version, both layers present as arrays, ids integers in 1..255 and unique within a layer, names
 * non-empty strings (unique within a layer), colours "#rrggbb", hatches one of hatchName()'s names.
 * Thread-safety: a value type. Failure modes: Malformed (a wrong key), NotFound / Unreadable (readLegend).
 */
#include "stylos/core/scene/Fragment.h"
#include "stylos/core/util/Result.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stylos::core::annotation {

/** @brief The two annotation layers of an object; stored in a `.poct` under layerName(). */
enum class AnnotationLayer { Material, Toolmark };
inline constexpr std::array<AnnotationLayer, 2> AllAnnotationLayers{AnnotationLayer::Material, AnnotationLayer::Toolmark};

/** "material" or "toolmark". */
const char* layerName(AnnotationLayer layer);
std::optional<AnnotationLayer> layerFromName(std::string_view name);

/** @brief A black-and-white fill pattern for print, so that classes stay distinct without colour. */
enum class Hatch { None, Diagonal, BackDiagonal, Cross, DiagonalCross, Dots, Horizontal, Vertical, Solid };

/** "none", "diagonal", "back-diagonal", "cross", "diagonal-cross", "dots", "horizontal", "vertical", "solid". */
const char* hatchName(Hatch hatch);
std::optional<Hatch> hatchFromName(std::string_view name);

/** @brief One class of a layer. */
struct LegendClass {
    std::uint8_t id = 1;  ///< 1..255 (0 = unlabelled)
    std::string name;     ///< non-empty, UTF-8
    scene::Rgb colour;
    Hatch hatch = Hatch::None;
    bool operator==(const LegendClass&) const = default;
};

struct Legend {
    static constexpr int kVersion = 1;
    static constexpr const char* kFormat = "stylos-legend";

    std::vector<LegendClass> material;
    std::vector<LegendClass> toolmark;

    std::vector<LegendClass>& classes(AnnotationLayer layer) { return layer == AnnotationLayer::Material ? material : toolmark; }
    const std::vector<LegendClass>& classes(AnnotationLayer layer) const
    {
        return layer == AnnotationLayer::Material ? material : toolmark;
    }
    /** The class @p id of @p layer, or nullptr. */
    const LegendClass* find(AnnotationLayer layer, int id) const;

    /** @brief The default vocabulary: material 1 preserved marble, 2 fractured marble, 3 plaster/restoration,
     *         4 unknown; toolmark 1 point, 2 flat chisel, 3 claw chisel, 4 drill, 5 rasp; distinct colours
     *         and hatches within each layer. */
    static Legend defaults();

    nlohmann::json toJson() const;
    /** @brief Reads toJson()'s object; Malformed "SOURCE: KEY: problem" naming the first wrong key. */
    static Result<Legend> fromJson(const nlohmann::json& json, const std::string& source);
    /** @brief Reads a legend file: NotFound, Unreadable, Malformed (not JSON, or as fromJson), naming @p path. */
    static Result<Legend> read(const std::filesystem::path& path);
    bool operator==(const Legend&) const = default;
};

} // namespace stylos::core::annotation
