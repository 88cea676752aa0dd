#include "stylos/core/view/GapFill.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace stylos::core::view {

namespace {

// E, W, N, S, NE, NW, SE, SW (y grows downward in the frame; the order only breaks ties). The GL pass walks the
// same list.
constexpr std::array<std::array<int, 2>, 8> Directions{{{1, 0}, {-1, 0}, {0, -1}, {0, 1}, {1, -1}, {-1, -1}, {1, 1}, {-1, 1}}};

} // namespace

std::uint8_t gapReach(double radiusPixels)
{
    if (!(radiusPixels >= 1.0)) return 1;
    return std::uint8_t(std::min(127.0, std::floor(radiusPixels + 0.5)));
}

std::int64_t fillGaps(GapFrame& frame, const GapFillOptions& options)
{
    const int w = frame.width, h = frame.height;
    const std::size_t n = std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0));
    assert(frame.depth.size() == n && frame.colour.size() == n && frame.reach.size() == n &&
           "core::view::fillGaps(): arrays of width × height");
    if (n == 0) return 0;
    const std::vector<float> depth = frame.depth; // the rule reads the input only
    const std::vector<std::uint8_t> reach = frame.reach;
    const std::vector<std::uint32_t> colour = frame.colour;
    const float keep = 1.0f - options.depthMargin;
    std::int64_t filled = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float here = depth[std::size_t(y) * w + x];
            const float front = std::isinf(here) ? here : here * keep;
            int enclosing = 0;
            std::size_t best = n;
            for (const auto& d : Directions) {
                for (int s = 1; s <= options.maxSteps; ++s) {
                    const int qx = x + d[0] * s, qy = y + d[1] * s;
                    if (qx < 0 || qy < 0 || qx >= w || qy >= h) break;
                    const std::size_t q = std::size_t(qy) * w + qx;
                    if (!(depth[q] < front)) continue;
                    if (s <= reach[q]) {
                        ++enclosing;
                        if (best == n || depth[q] < depth[best]) best = q;
                    }
                    break;
                }
            }
            if (enclosing < options.minDirections) continue;
            const std::size_t p = std::size_t(y) * w + x;
            frame.depth[p] = depth[best];
            frame.colour[p] = colour[best];
            frame.reach[p] = reach[best];
            ++filled;
        }
    return filled;
}

} // namespace stylos::core::view
