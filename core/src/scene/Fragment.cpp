#include "stylos/core/scene/Fragment.h"

#include <cstdio>

namespace stylos::core::scene {

namespace {

int hexDigit(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

} // namespace

std::string Rgb::toHex() const
{
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", r, g, b);
    return text;
}

std::optional<Rgb> Rgb::fromHex(std::string_view text)
{
    if (text.size() != 7 || text[0] != '#') return std::nullopt;
    std::uint8_t channels[3];
    for (std::size_t i = 0; i < 3; ++i) {
        const int high = hexDigit(text[1 + 2 * i]);
        const int low = hexDigit(text[2 + 2 * i]);
        if (high < 0 || low < 0) return std::nullopt;
        channels[i] = static_cast<std::uint8_t>(16 * high + low);
    }
    return Rgb{channels[0], channels[1], channels[2]};
}

const char* guideKindName(GuideKind kind)
{
    switch (kind) {
    case GuideKind::Axis: return "axis";
    case GuideKind::Groove: return "groove";
    }
    return "axis";
}

std::optional<GuideKind> guideKindFromName(std::string_view name)
{
    if (name == "axis") return GuideKind::Axis;
    if (name == "groove") return GuideKind::Groove;
    return std::nullopt;
}

Rgb defaultFragmentColour(std::size_t index)
{
    // Marble, terracotta, sage, slate blue, ochre, rose, teal, lavender: readable on dark and light.
    static constexpr Rgb palette[] = {{214, 204, 186}, {201, 124, 93}, {143, 170, 122}, {112, 140, 186},
                                      {212, 170, 84},  {196, 128, 150}, {86, 160, 160}, {160, 140, 200}};
    return palette[index % (sizeof palette / sizeof palette[0])];
}

} // namespace stylos::core::scene
