#include "stylos/core/shading/FieldCoverage.h"

#include <algorithm>
#include <cassert>
#include <vector>

namespace stylos::core::shading {

namespace {

/**
 * One separable pass of a square dilation (any set pixel in the window) or erosion (every pixel of the
 * window set; outside the image counts as set, so the border does not eat the footprint) over rows
 * (horizontal) or columns (vertical), by a running count of the window.
 */
void boxPass(const std::vector<std::uint8_t>& in, std::vector<std::uint8_t>& out, int width, int height, int radius,
             bool erode, bool horizontal)
{
    const int lines = horizontal ? height : width, length = horizontal ? width : height;
    const std::size_t step = horizontal ? 1 : std::size_t(width);
    const int window = 2 * radius + 1;
    for (int line = 0; line < lines; ++line) {
        const std::size_t first = horizontal ? std::size_t(line) * std::size_t(width) : std::size_t(line);
        auto at = [&](int i) -> int {
            if (i < 0 || i >= length) return erode ? 1 : 0;
            return in[first + std::size_t(i) * step];
        };
        int count = 0;
        for (int i = -radius; i <= radius; ++i) count += at(i);
        for (int i = 0; i < length; ++i) {
            out[first + std::size_t(i) * step] = erode ? std::uint8_t(count == window) : std::uint8_t(count > 0);
            count += at(i + radius + 1) - at(i - radius);
        }
    }
}

} // namespace

std::vector<std::uint8_t> footprintMask(const HeightField& field, int radius)
{
    assert(radius >= 0 && "footprintMask(): the radius must be >= 0");
    const int width = field.width(), height = field.height();
    const auto states = field.states();
    std::vector<std::uint8_t> mask(states.size()), scratch(states.size());
    bool any = false;
    for (std::size_t i = 0; i < states.size(); ++i) any |= (mask[i] = states[i] != PixelState::Empty) != 0;
    if (!any || width <= 0 || height <= 0) return mask;
    // Closing = dilation then erosion, each separable into a horizontal and a vertical pass.
    boxPass(mask, scratch, width, height, radius, false, true);
    boxPass(scratch, mask, width, height, radius, false, false);
    boxPass(mask, scratch, width, height, radius, true, true);
    boxPass(scratch, mask, width, height, radius, true, false);
    for (std::size_t i = 0; i < states.size(); ++i) mask[i] |= std::uint8_t(states[i] != PixelState::Empty);
    return mask;
}

FieldCoverage measureCoverage(const HeightField& field, int radius)
{
    assert(radius >= 0 && "measureCoverage(): the radius must be >= 0");
    FieldCoverage coverage;
    for (const PixelState s : field.states()) coverage.withHeight += s != PixelState::Empty ? 1 : 0;
    if (coverage.withHeight == 0) return coverage;
    for (const std::uint8_t in : footprintMask(field, radius)) coverage.footprint += in;
    return coverage;
}

} // namespace stylos::core::shading
