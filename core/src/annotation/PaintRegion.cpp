// The pixel sets of the painting tools: brush segment, polygon, magic wand, enclosed holes.
#include "stylos/core/annotation/PaintRegion.h"

#include "stylos/core/util/HugePages.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <memory>

namespace stylos::core::annotation {

namespace {

/** The pixels a flood reached: columns [c0, c1], rows [r0, r1]; empty when c1 < c0. */
struct Box {
    int c0, c1, r0, r1;
};

/** 4-connected flood from the pixels of @p seeds (those @p inside accepts) over the pixels @p inside accepts,
 *  marking them in @p seen, a span of a row at a time (scanline fill: each pixel is visited a bounded number of
 *  times, in memory order). No list is built: the caller reads the marks inside the returned box, in row-major
 *  order, without sorting. */
template <typename Inside>
Box flood(const std::vector<std::uint32_t>& seeds, int width, int height, std::uint8_t* seen, Inside inside)
{
    Box box{width, -1, height, -1};
    const std::uint32_t w = std::uint32_t(width);
    const auto open = [&](int c, int r) {
        const std::uint32_t q = std::uint32_t(r) * w + std::uint32_t(c);
        return !seen[q] && inside(q);
    };
    std::vector<std::pair<int, int>> stack;
    for (std::uint32_t p : seeds) stack.emplace_back(int(p % w), int(p / w));
    while (!stack.empty()) {
        const auto [x, y] = stack.back();
        stack.pop_back();
        if (!open(x, y)) continue;
        int left = x, right = x;
        while (left > 0 && open(left - 1, y)) --left;
        while (right + 1 < width && open(right + 1, y)) ++right;
        std::uint8_t* row = seen + std::size_t(y) * w;
        std::fill(row + left, row + right + 1, std::uint8_t(1));
        box.c0 = std::min(box.c0, left);
        box.c1 = std::max(box.c1, right);
        box.r0 = std::min(box.r0, y);
        box.r1 = std::max(box.r1, y);
        for (int ny : {y - 1, y + 1}) { // one seed per run of open pixels above and below the span
            if (ny < 0 || ny >= height) continue;
            bool inRun = false;
            for (int c = left; c <= right; ++c) {
                const bool o = open(c, ny);
                if (o && !inRun) stack.emplace_back(c, ny);
                inRun = o;
            }
        }
    }
    return box;
}

/** A byte per pixel of a @p width × @p height grid, not initialised, on huge pages where the system gives them. */
std::unique_ptr<std::uint8_t[]> pixelBytes(int width, int height)
{
    const std::size_t n = std::size_t(std::max(0, width)) * std::size_t(std::max(0, height));
    std::unique_ptr<std::uint8_t[]> bytes(new std::uint8_t[n]);
    adviseHugePages(bytes.get(), n);
    return bytes;
}

/** The pixels of @p box whose mark in @p seen is @p wanted, ascending: counted first (a vectorised pass) so the
 *  list is allocated once, then written a run at a time (the fills mark spans). */
std::vector<std::uint32_t> marked(const std::uint8_t* seen, Box box, int width, std::uint8_t wanted)
{
    std::vector<std::uint32_t> out;
    std::size_t count = 0;
    for (int r = box.r0; r <= box.r1; ++r) {
        const std::uint8_t* row = seen + std::size_t(r) * std::size_t(width);
        for (int c = box.c0; c <= box.c1; ++c) count += row[c] == wanted;
    }
    out.reserve(count);
    adviseHugePages(out.data(), count * sizeof(std::uint32_t));
    out.resize(count);
    std::uint32_t* next = out.data();
    for (int r = box.r0; r <= box.r1; ++r) {
        const std::uint8_t* row = seen + std::size_t(r) * std::size_t(width);
        const std::uint32_t base = std::uint32_t(r) * std::uint32_t(width);
        int c = box.c0;
        while (c <= box.c1) {
            while (c <= box.c1 && row[c] != wanted) ++c;
            const int start = c;
            while (c <= box.c1 && row[c] == wanted) ++c;
            for (int k = start; k < c; ++k) *next++ = base + std::uint32_t(k);
        }
    }
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
    // One byte a pixel, set in a branch-free (vectorised) pass: 0 where the wand may go, 2 where it may not; the
    // fill marks what it takes 1. One array, written once: on large images the time goes to touching memory.
    const auto seen = pixelBytes(width, height);
    std::uint8_t* marks = seen.get();
    for (std::size_t q = 0; q < n; ++q)
        marks[q] = std::uint8_t(2 * !((valid[q] != 0) & (std::abs(values[q] - reference) <= tolerance)));
    const Box box = flood(std::vector<std::uint32_t>{seed}, width, height, marks, [](std::uint32_t) { return true; });
    return marked(marks, box, width, 1);
}

std::vector<std::uint32_t> enclosedHoles(std::span<const std::uint8_t> ids, int width, int height, std::uint32_t seed)
{
    const std::size_t n = std::size_t(std::max(0, width)) * std::size_t(std::max(0, height));
    assert(ids.size() == n && "enclosedHoles(): one id per pixel");
    if (seed >= n || ids[seed] == 0) return {};
    const std::uint8_t id = ids[seed];
    const auto marks = pixelBytes(width, height);
    std::uint8_t* region = marks.get();
    std::fill(region, region + n, std::uint8_t(0));
    const Box box = flood(std::vector<std::uint32_t>{seed}, width, height, region, [&](std::uint32_t q) { return ids[q] == id; });
    const int c0 = box.c0, c1 = box.c1, r0 = box.r0, r1 = box.r1;
    // The region's box, one pixel wider: what is not the region and reaches the frame of that box is outside.
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
    std::uint8_t* seen = region;
    const auto inBox = [&](std::uint32_t q) {
        const int c = int(q % std::uint32_t(width)), r = int(q / std::uint32_t(width));
        return c >= bc0 && c <= bc1 && r >= br0 && r <= br1;
    };
    flood(frame, width, height, seen, inBox);
    return marked(seen, Box{bc0, bc1, br0, br1}, width, 0);
}

} // namespace stylos::core::annotation
