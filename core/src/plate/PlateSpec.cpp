// A plate as stated: page, resolution, caption, panels; names, validation and the layout file.
#include "stylos/core/plate/PlateSpec.h"
#include "stylos/core/util/JsonText.h"
#include "stylos/core/util/TextCase.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <sstream>

namespace stylos::core::plate {

namespace {

constexpr std::array<const char*, 8> ViewNames{"developpee", "front", "back", "left", "right", "top", "bottom", "camera"};
constexpr std::array<const char*, 4> ShadingNames{"skydome", "light", "height", "headlight"};

std::string lower(std::string_view text) { return lowerCase(text); }

Error malformed(const std::string& source, const std::string& key, const std::string& problem)
{
    return Error::at(ErrorCode::Malformed, source, key, problem);
}

Error invalid(const std::string& source, const std::string& key, const std::string& problem)
{
    return Error::at(ErrorCode::InvalidArgument, source, key, problem);
}

std::optional<double> parseNumber(std::string_view text)
{
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

} // namespace

const char* panelViewName(PanelView view) { return ViewNames[std::size_t(view)]; }

std::optional<PanelView> panelViewFromName(std::string_view name)
{
    for (std::size_t i = 0; i < ViewNames.size(); ++i)
        if (lower(name) == ViewNames[i]) return PanelView(i);
    return std::nullopt;
}

const char* panelShadingName(PanelShading shading) { return ShadingNames[std::size_t(shading)]; }

std::optional<PanelShading> panelShadingFromName(std::string_view name)
{
    for (std::size_t i = 0; i < ShadingNames.size(); ++i)
        if (lower(name) == ShadingNames[i]) return PanelShading(i);
    return std::nullopt;
}

std::optional<PageSize> pageFromName(std::string_view name)
{
    const std::string n = lower(name);
    if (n == "a4") return PageSize{210, 297};
    if (n == "a3") return PageSize{297, 420};
    if (n == "letter") return PageSize{215.9, 279.4};
    const auto x = n.find('x');
    if (x == std::string::npos) return std::nullopt;
    const auto w = parseNumber(std::string_view(n).substr(0, x));
    const auto h = parseNumber(std::string_view(n).substr(x + 1));
    if (!w || !h || !(*w >= 10 && *w <= 2000) || !(*h >= 10 && *h <= 2000)) return std::nullopt; // NaN too
    return PageSize{*w, *h};
}

PageSize PlateSpec::orientedPage() const
{
    const double shorter = std::min(page.widthMm, page.heightMm), longer = std::max(page.widthMm, page.heightMm);
    // A named page is portrait unless asked; a "WxH" page keeps its stated orientation, swapped by landscape
    // (the plate dialog's "Turned"; stylos-cli plate --landscape turns such a page only when it is upright).
    if (pageFromName(pageName) && pageName.find_first_of("xX") != std::string::npos)
        return landscape ? PageSize{page.heightMm, page.widthMm} : page;
    return landscape ? PageSize{longer, shorter} : PageSize{shorter, longer};
}

Status PlateSpec::validate(const std::string& source) const
{
    if (!(page.widthMm >= 10 && page.heightMm >= 10 && page.widthMm <= 2000 && page.heightMm <= 2000))
        return invalid(source, "page", "each side must be 10..2000 mm");
    const double shorter = std::min(page.widthMm, page.heightMm);
    if (!(marginMm >= 0 && marginMm <= shorter / 3)) return invalid(source, "margin_mm", "must be 0.." + std::to_string(int(shorter / 3)) + " mm");
    if (dpi < 72 || dpi > 2400) return invalid(source, "dpi", std::to_string(dpi) + " is outside 72..2400");
    if (bits != 8 && bits != 16) return invalid(source, "bits", "must be 8 or 16");
    if (panels.empty()) return invalid(source, "panels", "a plate needs at least one panel");
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const PanelSpec& p = panels[i];
        const std::string at = "panels[" + std::to_string(i) + "]";
        if (!(p.scale >= 1 && p.scale <= 1e6)) return invalid(source, at + ".scale", "must be a number in 1..1000000 (1:N)");
        const bool dev = p.view == PanelView::Developpee;
        if (dev && p.shading == PanelShading::Headlight)
            return invalid(source, at + ".shading", "headlight is for 3D views; a développée takes skydome, light or height");
        if (!dev && (p.shading == PanelShading::Light || p.shading == PanelShading::Height))
            return invalid(source, at + ".shading", "a 3D view takes skydome or headlight");
        if (p.view == PanelView::Camera) {
            if (!p.camera) return invalid(source, at + ".camera", "the camera view needs its orientation [w, x, y, z]");
            const auto& q = *p.camera;
            const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            if (!std::isfinite(norm) || std::abs(norm - 1.0) > 1e-6)
                return invalid(source, at + ".camera", "must be a unit quaternion [w, x, y, z]");
        }
    }
    return {};
}

nlohmann::json PlateSpec::toJson() const
{
    nlohmann::json list = nlohmann::json::array();
    for (const PanelSpec& p : panels) {
        nlohmann::json j{{"view", panelViewName(p.view)},
                         {"scale", p.scale},
                         {"shading", panelShadingName(p.shading)},
                         {"hatches", p.hatches}};
        if (p.layer) j["layer"] = annotation::layerName(*p.layer);
        if (!p.fragment.empty()) j["fragment"] = p.fragment;
        if (p.atMm) j["at_mm"] = {(*p.atMm)[0], (*p.atMm)[1]};
        if (p.camera && p.view == PanelView::Camera) j["camera"] = {(*p.camera)[0], (*p.camera)[1], (*p.camera)[2], (*p.camera)[3]};
        list.push_back(std::move(j));
    }
    return {{"format", kFormat}, {"version", kVersion}, {"page", pageName}, {"landscape", landscape},
            {"margin_mm", marginMm}, {"dpi", dpi}, {"bits", bits}, {"caption", caption}, {"legend", legend},
            {"panels", std::move(list)}};
}

Result<PlateSpec> PlateSpec::fromJson(const nlohmann::json& json, const std::string& source)
{
    if (!json.is_object()) return malformed(source, {}, "not a JSON object");
    // A key this version does not know is refused, named: a misspelt "pagee" or "scael" must not quietly
    // give a plate at the defaults.
    const auto unknownKey = [&](const nlohmann::json& obj, const std::string& at,
                                std::initializer_list<const char*> known) -> std::optional<Error> {
        for (auto it = obj.begin(); it != obj.end(); ++it)
            if (std::none_of(known.begin(), known.end(), [&](const char* k) { return it.key() == k; }))
                return malformed(source, at + it.key(), "is not a key of a plate layout (a misspelling?)");
        return std::nullopt;
    };
    if (auto e = unknownKey(json, "", {"format", "version", "page", "landscape", "margin_mm", "dpi", "bits", "caption",
                                       "legend", "panels"}))
        return *e;
    PlateSpec s;
    if (const auto f = json.find("format"); f != json.end() && (!f->is_string() || f->get<std::string>() != kFormat))
        return malformed(source, "format", std::string("must be \"") + kFormat + "\"");
    if (const auto v = json.find("version"); v != json.end() && (!v->is_number_integer() || v->get<int>() != kVersion))
        return malformed(source, "version", "must be 1");
    if (const auto page = json.find("page"); page != json.end()) {
        if (page->is_string()) {
            const auto size = pageFromName(page->get<std::string>());
            if (!size) return malformed(source, "page", "must be A4, A3, letter, 170x105, 205x135 or WxH in mm");
            s.pageName = page->get<std::string>();
            s.page = *size;
        } else if (page->is_array() && page->size() == 2 && (*page)[0].is_number() && (*page)[1].is_number()) {
            s.page = {(*page)[0].get<double>(), (*page)[1].get<double>()};
            char name[64];
            std::snprintf(name, sizeof name, "%gx%g", s.page.widthMm, s.page.heightMm);
            s.pageName = name;
        } else {
            return malformed(source, "page", "must be a page name or [width, height] in mm");
        }
    }
    auto boolean = [&](const char* key, bool& out) -> Status {
        const auto it = json.find(key);
        if (it == json.end()) return {};
        if (!it->is_boolean()) return malformed(source, key, "must be true or false");
        out = it->get<bool>();
        return {};
    };
    auto number = [&](const nlohmann::json& obj, const std::string& at, const char* key, auto& out) -> Status {
        const auto it = obj.find(key);
        if (it == obj.end()) return {};
        if (!it->is_number()) return malformed(source, at + key, "must be a number");
        using T = std::decay_t<decltype(out)>;
        if constexpr (std::is_integral_v<T>) {
            if (!it->is_number_integer()) return malformed(source, at + key, "must be a whole number");
            out = it->template get<T>();
        } else {
            out = it->template get<T>();
        }
        return {};
    };
    if (auto st = boolean("landscape", s.landscape); !st) return st.error();
    if (auto st = boolean("legend", s.legend); !st) return st.error();
    if (auto st = number(json, "", "margin_mm", s.marginMm); !st) return st.error();
    if (auto st = number(json, "", "dpi", s.dpi); !st) return st.error();
    if (auto st = number(json, "", "bits", s.bits); !st) return st.error();
    if (const auto c = json.find("caption"); c != json.end()) {
        if (!c->is_string()) return malformed(source, "caption", "must be a string");
        s.caption = c->get<std::string>();
    }
    const auto panels = json.find("panels");
    if (panels == json.end() || !panels->is_array()) return malformed(source, "panels", "missing or not a list");
    for (std::size_t i = 0; i < panels->size(); ++i) {
        const nlohmann::json& p = (*panels)[i];
        const std::string at = "panels[" + std::to_string(i) + "].";
        if (!p.is_object()) return malformed(source, at.substr(0, at.size() - 1), "not an object");
        if (auto e = unknownKey(p, at, {"view", "scale", "shading", "layer", "hatches", "fragment", "at_mm", "camera"}))
            return *e;
        PanelSpec panel;
        const auto view = p.find("view");
        const auto v = view != p.end() && view->is_string() ? panelViewFromName(view->get<std::string>()) : std::nullopt;
        if (!v) return malformed(source, at + "view", "missing or not one of developpee, front, back, left, right, top, bottom, camera");
        panel.view = *v;
        if (p.find("scale") == p.end()) return malformed(source, at + "scale", "missing");
        if (auto st = number(p, at, "scale", panel.scale); !st) return st.error();
        if (const auto sh = p.find("shading"); sh != p.end()) {
            const auto k = sh->is_string() ? panelShadingFromName(sh->get<std::string>()) : std::nullopt;
            if (!k) return malformed(source, at + "shading", "must be skydome, light, height or headlight");
            panel.shading = *k;
        } else if (panel.view != PanelView::Developpee) {
            panel.shading = PanelShading::Skydome;
            panel.shadingStated = false;
        }
        if (const auto l = p.find("layer"); l != p.end()) {
            const auto layer = l->is_string() ? annotation::layerFromName(l->get<std::string>()) : std::nullopt;
            if (!layer) return malformed(source, at + "layer", "must be material or toolmark");
            panel.layer = *layer;
        }
        if (const auto h = p.find("hatches"); h != p.end()) {
            if (!h->is_boolean()) return malformed(source, at + "hatches", "must be true or false");
            panel.hatches = h->get<bool>();
        }
        if (const auto f = p.find("fragment"); f != p.end()) {
            if (!f->is_string()) return malformed(source, at + "fragment", "must be a fragment's name");
            panel.fragment = f->get<std::string>();
        }
        if (const auto a = p.find("at_mm"); a != p.end()) {
            if (!a->is_array() || a->size() != 2 || !(*a)[0].is_number() || !(*a)[1].is_number())
                return malformed(source, at + "at_mm", "must be [x, y] in mm from the page's top-left corner");
            panel.atMm = std::array<double, 2>{(*a)[0].get<double>(), (*a)[1].get<double>()};
        }
        if (const auto c = p.find("camera"); c != p.end()) {
            if (!c->is_array() || c->size() != 4 || !(*c)[0].is_number() || !(*c)[1].is_number() || !(*c)[2].is_number() ||
                !(*c)[3].is_number())
                return malformed(source, at + "camera", "must be [w, x, y, z]");
            panel.camera = std::array<double, 4>{(*c)[0].get<double>(), (*c)[1].get<double>(), (*c)[2].get<double>(),
                                                 (*c)[3].get<double>()};
        }
        s.panels.push_back(std::move(panel));
    }
    if (auto st = s.validate(source); !st) return Error{ErrorCode::Malformed, st.error().message};
    return s;
}

Result<PlateSpec> PlateSpec::read(const std::string& path)
{
    auto json = readJsonFile(path);
    if (!json) return json.error();
    return fromJson(json.value(), path);
}

} // namespace stylos::core::plate
