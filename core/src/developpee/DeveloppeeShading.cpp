#include "stylos/core/developpee/DeveloppeeShading.h"

#include <array>
#include <cassert>

namespace stylos::core::developpee {

namespace {

constexpr std::array<ShadingInfo, 3> kShadings{{
    {Shading::Skydome, "skydome", "Skydome"},
    {Shading::Light, "light", "Light"},
    {Shading::Height, "height", "Height"},
}};

} // namespace

std::span<const ShadingInfo> shadings() { return kShadings; }

const ShadingInfo& shadingInfo(Shading kind)
{
    for (const ShadingInfo& info : kShadings)
        if (info.kind == kind) return info;
    assert(false && "developpee::shadingInfo(): a shading missing from the table");
    return kShadings.front();
}

std::optional<Shading> shadingFromKey(std::string_view key)
{
    for (const ShadingInfo& info : kShadings)
        if (key == info.key) return info.kind;
    return std::nullopt;
}

const char* shadingKeyList() { return "skydome, light or height"; }

} // namespace stylos::core::developpee
