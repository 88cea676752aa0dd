// The annotation legend: layers, hatches, the default vocabulary and its JSON form.
#include "stylos/core/annotation/Legend.h"

#include "stylos/core/util/JsonText.h"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

namespace stylos::core::annotation {

namespace {

constexpr std::array<const char*, 9> HatchNames{"none",           "diagonal", "back-diagonal", "cross",   "diagonal-cross",
                                                "dots",           "horizontal", "vertical",    "solid"};

LegendClass make(int id, const char* name, const char* colour, Hatch hatch)
{
    return {static_cast<std::uint8_t>(id), name, *scene::Rgb::fromHex(colour), hatch};
}

Error malformed(const std::string& source, const std::string& key, const std::string& problem)
{
    return Error::at(ErrorCode::Malformed, source, key, problem);
}

Result<std::vector<LegendClass>> readClasses(const nlohmann::json& list, const std::string& source, const std::string& key)
{
    if (!list.is_array()) return malformed(source, key, "missing or not a list of classes");
    std::vector<LegendClass> classes;
    std::set<int> ids;
    std::set<std::string> names;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const nlohmann::json& c = list[i];
        const std::string at = key + "[" + std::to_string(i) + "]";
        if (!c.is_object()) return malformed(source, at, "not an object");
        const auto id = c.find("id");
        if (id == c.end() || !id->is_number_integer()) return malformed(source, at + ".id", "missing or not an integer");
        const long long value = id->get<long long>();
        if (value == 0) return malformed(source, at + ".id", "0 is reserved for unlabelled cells");
        if (value < 1 || value > 255) return malformed(source, at + ".id", std::to_string(value) + " is outside 1..255");
        if (!ids.insert(int(value)).second) return malformed(source, at + ".id", "duplicate id " + std::to_string(value));
        const auto name = c.find("name");
        if (name == c.end() || !name->is_string()) return malformed(source, at + ".name", "missing or not a string");
        const std::string text = name->get<std::string>();
        if (text.empty()) return malformed(source, at + ".name", "empty");
        if (!names.insert(text).second) return malformed(source, at + ".name", "duplicate name \"" + text + "\"");
        const auto colour = c.find("colour");
        const auto rgb = colour != c.end() && colour->is_string() ? scene::Rgb::fromHex(colour->get<std::string>())
                                                                   : std::nullopt;
        if (!rgb) return malformed(source, at + ".colour", "missing or not \"#rrggbb\"");
        const auto hatch = c.find("hatch");
        const auto h = hatch != c.end() && hatch->is_string() ? hatchFromName(hatch->get<std::string>()) : std::nullopt;
        if (!h) return malformed(source, at + ".hatch", "missing or not one of none, diagonal, back-diagonal, cross, "
                                                        "diagonal-cross, dots, horizontal, vertical, solid");
        classes.push_back({static_cast<std::uint8_t>(value), text, *rgb, *h});
    }
    return classes;
}

} // namespace

const char* layerName(AnnotationLayer layer) { return layer == AnnotationLayer::Material ? "material" : "toolmark"; }

std::optional<AnnotationLayer> layerFromName(std::string_view name)
{
    for (AnnotationLayer layer : AllAnnotationLayers)
        if (name == layerName(layer)) return layer;
    return std::nullopt;
}

const char* hatchName(Hatch hatch) { return HatchNames[static_cast<std::size_t>(hatch)]; }

std::optional<Hatch> hatchFromName(std::string_view name)
{
    for (std::size_t i = 0; i < HatchNames.size(); ++i)
        if (name == HatchNames[i]) return static_cast<Hatch>(i);
    return std::nullopt;
}

const LegendClass* Legend::find(AnnotationLayer layer, int id) const
{
    for (const LegendClass& c : classes(layer))
        if (c.id == id) return &c;
    return nullptr;
}

Legend Legend::defaults()
{
    Legend legend;
    legend.material = {make(1, "preserved marble", "#e8e0c8", Hatch::None),
                       make(2, "fractured marble", "#c0504d", Hatch::Cross),
                       make(3, "plaster/restoration", "#4f81bd", Hatch::Dots),
                       make(4, "unknown", "#9b9b9b", Hatch::Diagonal)};
    legend.toolmark = {make(1, "point", "#f79646", Hatch::Dots),
                       make(2, "flat chisel", "#4bacc6", Hatch::Horizontal),
                       make(3, "claw chisel", "#8064a2", Hatch::Vertical),
                       make(4, "drill", "#9bbb59", Hatch::DiagonalCross),
                       make(5, "rasp", "#7f6000", Hatch::BackDiagonal)};
    return legend;
}

nlohmann::json Legend::toJson() const
{
    nlohmann::json layers = nlohmann::json::object();
    for (AnnotationLayer layer : AllAnnotationLayers) {
        nlohmann::json list = nlohmann::json::array();
        for (const LegendClass& c : classes(layer))
            list.push_back({{"id", c.id}, {"name", c.name}, {"colour", c.colour.toHex()}, {"hatch", hatchName(c.hatch)}});
        layers[layerName(layer)] = std::move(list);
    }
    return {{"format", kFormat}, {"version", kVersion}, {"layers", std::move(layers)}};
}

Result<Legend> Legend::fromJson(const nlohmann::json& json, const std::string& source)
{
    if (!json.is_object()) return malformed(source, "", "a legend must be a JSON object");
    const auto format = json.find("format");
    if (format == json.end() || *format != kFormat) return malformed(source, "format", "missing or not \"stylos-legend\"");
    const auto version = json.find("version");
    if (version == json.end() || !version->is_number_integer() || version->get<long long>() != kVersion)
        return malformed(source, "version", "missing or not 1");
    const auto layers = json.find("layers");
    if (layers == json.end() || !layers->is_object()) return malformed(source, "layers", "missing or not an object");
    Legend legend;
    for (AnnotationLayer layer : AllAnnotationLayers) {
        const std::string key = std::string("layers.") + layerName(layer);
        const auto list = layers->find(layerName(layer));
        if (list == layers->end()) return malformed(source, key, "missing");
        auto classes = readClasses(*list, source, key);
        if (!classes) return classes.error();
        legend.classes(layer) = std::move(classes).value();
    }
    return legend;
}

Result<Legend> Legend::read(const std::filesystem::path& path)
{
    auto json = readJsonFile(path);
    if (!json) return json.error();
    return fromJson(json.value(), path.string());
}

} // namespace stylos::core::annotation
