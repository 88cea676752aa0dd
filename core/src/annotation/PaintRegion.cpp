// The pixel sets of the painting tools: brush segment, polygon, magic wand, enclosed holes.
#include "stylos/core/annotation/PaintRegion.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace stylos::core::annotation {

namespace {

/** 4-connected flood from @p seeds over the pixels @p inside accepts; marks them in @p seen; returns them. */
template <typename Inside>
std::vector<std::uint32_t> flood(std::vector<std::uint32_t> stack, int width, int height, std::vector<std::uint8_t>& seen,
                                 Inside inside)
{
    std::vector<std::uint32_t> out;
    for (std::uint32_t p : stack) seen[p] = 1;
    while (!stack.empty()) {
        const std::uint32_t p = stack.back();
        stack.pop_back();
        out.push_back(p);
        const int c = int(p % std::uint32_t(width)), r = int(p / std::uint32_t(width));
        const auto visit = [&](int cc, int rr) {
            if (cc < 0 || rr < 0 || cc >= width || rr >= height) return;
            const std::uint32_t q = std::uint32_t(rr) * std::uint32_t(width) + std::uint32_t(cc);
            if (seen[q] || !inside(q)) return;
            seen[q] = 1;
            stack.push_back(q);
        };
        visit(c - 1, r);
        visit(c + 1, r);
        visit(c, r - 1);
        visit(c, r + 1);
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

std::vector<std::uint32_t> brushPixels(GridPoint a, GridPoint b, double radius, int width, int height)
{
    std::vector<std::uint32_t> out;
    if (radius < 0.0 || width <= 0 || height <= 0) return out;
    const int c0 = std::max(0, int(std::floor(std::min(a.x, b.x) - radius - 0.5)));
    const int c1 = std::min(width - 1, int(std::ceil(std::max(a.x, b.x) + radius)));
    const int r0 = std::max(0, int(std::floor(std::min(a.y, b.y) - radius - 0.5)));
    const int r1 = std::min(height - 1, int(std::ceil(std::max(a.y, b.y) + radius)));
    const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
    const double radius2 = radius * radius;
    for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c) {
            const double px = c + 0.5 - a.x, py = r + 0.5 - a.y;
            const double t = length2 > 0.0 ? std::clamp((px * dx + py * dy) / length2, 0.0, 1.0) : 0.0;
            const double ex = px - t * dx, ey = py - t * dy;
            if (ex * ex + ey * ey <= radius2) out.push_back(std::uint32_t(r) * std::uint32_t(width) + std::uint32_t(c));
        }
    return out;
}

std::vector<std::uint32_t> polygonPixels(std::span<const GridPoint> polygon, int width, int height)
{
    std::vector<std::uint32_t> out;
    if (polygon.size() < 3 || width <= 0 || height <= 0) return out;
    double top = polygon[0].y, bottom = polygon[0].y;
    for (const GridPoint& p : polygon) {
        top = std::min(top, p.y);
        bottom = std::max(bottom, p.y);
    }
    const int r0 = std::max(0, int(std::floor(top))), r1 = std::min(height - 1, int(std::ceil(bottom)));
    std::vector<double> crossings;
    for (int r = r0; r <= r1; ++r) { // scanline through the pixel centres
        const double y = r + 0.5;
        crossings.clear();
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const GridPoint& p = polygon[i];
            const GridPoint& q = polygon[(i + 1) % polygon.size()];
            if ((p.y <= y) != (q.y <= y)) crossings.push_back(p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y));
        }
        std::sort(crossings.begin(), crossings.end());
        for (std::size_t i = 0; i + 1 < crossings.size(); i += 2) {
            // Centres c + 0.5 in [x0, x1): c from ceil(x0 − 0.5) to ceil(x1 − 0.5) − 1.
            const int c0 = std::max(0, int(std::ceil(crossings[i] - 0.5)));
            const int c1 = std::min(width, int(std::ceil(crossings[i + 1] - 0.5)));
            for (int c = c0; c < c1; ++c) out.push_back(std::uint32_t(r) * std::uint32_t(width) + std::uint32_t(c));
        }
    }
    return out; // rows ascending, spans ascending and disjoint within a row
}

std::vector<std::uint32_t> floodFill(std::span<const float> values, std::span<const std::uint8_t> valid, int width,
                                     int height, std::uint32_t seed, float tolerance)
{
    const std::size_t n = std::size_t(std::max(0, width)) * std::size_t(std::max(0, height));
    assert(values.size() == n && valid.size() == n && "floodFill(): one value per pixel");
    if (seed >= n || !valid[seed]) return {};
    const float reference = values[seed];
    std::vector<std::uint8_t> seen(n, 0);
    return flood({seed}, width, height, seen,
                 [&](std::uint32_t q) { return valid[q] && std::abs(values[q] - reference) <= tolerance; });
}

std::vector<std::uint32_t> enclosedHoles(std::span<const std::uint8_t> ids, int width, int height, std::uint32_t seed)
{
    const std::size_t n = std::size_t(std::max(0, width)) * std::size_t(std::max(0, height));
    assert(ids.size() == n && "enclosedHoles(): one id per pixel");
    if (seed >= n || ids[seed] == 0) return {};
    const std::uint8_t id = ids[seed];
    std::vector<std::uint8_t> region(n, 0);
    const std::vector<std::uint32_t> inside = flood({seed}, width, height, region, [&](std::uint32_t q) { return ids[q] == id; });
    // The region's box, one pixel wider: what is not the region and reaches the frame of that box is outside.
    int c0 = width, c1 = -1, r0 = height, r1 = -1;
    for (std::uint32_t p : inside) {
        const int c = int(p % std::uint32_t(width)), r = int(p / std::uint32_t(width));
        c0 = std::min(c0, c);
        c1 = std::max(c1, c);
        r0 = std::min(r0, r);
        r1 = std::max(r1, r);
    }
    // Clamped to the image where the region touches its border: there the frame is the image's border pixels.
    const int bc0 = std::max(0, c0 - 1), bc1 = std::min(width - 1, c1 + 1);
    const int br0 = std::max(0, r0 - 1), br1 = std::min(height - 1, r1 + 1);
    const auto at = [width](int c, int r) { return std::uint32_t(r) * std::uint32_t(width) + std::uint32_t(c); };
    std::vector<std::uint32_t> frame;
    for (int c = bc0; c <= bc1; ++c) {
        frame.push_back(at(c, br0));
        frame.push_back(at(c, br1));
    }
    for (int r = br0; r <= br1; ++r) {
        frame.push_back(at(bc0, r));
        frame.push_back(at(bc1, r));
    }
    std::sort(frame.begin(), frame.end());
    frame.erase(std::unique(frame.begin(), frame.end()), frame.end());
    std::erase_if(frame, [&](std::uint32_t p) { return region[p] != 0; });
    // "seen" = the region, then the outside flooded within the box; the rest of the box is holes.
    std::vector<std::uint8_t>& seen = region;
    const auto inBox = [&](std::uint32_t q) {
        const int c = int(q % std::uint32_t(width)), r = int(q / std::uint32_t(width));
        return c >= bc0 && c <= bc1 && r >= br0 && r <= br1;
    };
    flood(std::move(frame), width, height, seen, inBox);
    std::vector<std::uint32_t> holes;
    for (int r = br0; r <= br1; ++r)
        for (int c = bc0; c <= bc1; ++c)
            if (!seen[at(c, r)]) holes.push_back(at(c, r));
    return holes;
}

} // namespace stylos::core::annotation
