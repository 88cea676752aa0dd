// Hatch strokes of a class, traced along parallel lines through its pixels.
#include "stylos/core/plate/HatchLines.h"

#include <cmath>

namespace stylos::core::plate {

namespace {

using annotation::Hatch;

/** One family: lines of direction (dx, dy) (unit), spaced @p spacing along the normal. */
void family(std::span<const std::uint8_t> classes, int width, int height, std::uint8_t id, double dx, double dy,
            double spacing, std::vector<HatchSegment>& out)
{
    auto in = [&](double x, double y) {
        const int ix = int(std::floor(x)), iy = int(std::floor(y));
        return ix >= 0 && iy >= 0 && ix < width && iy < height &&
               classes[std::size_t(iy) * std::size_t(width) + std::size_t(ix)] == id;
    };
    // Normal n = (-dy, dx); a line is {p : p·n = c}; c spans the image's corners.
    const double nx = -dy, ny = dx;
    double cmin = 1e300, cmax = -1e300;
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {double(width), 0.0}, {0.0, double(height)}, {double(width), double(height)}}) {
        const double c = x * nx + y * ny;
        cmin = std::min(cmin, c), cmax = std::max(cmax, c);
    }
    const double first = std::ceil(cmin / spacing) * spacing;
    const double length = std::hypot(double(width), double(height));
    const double step = 0.5;
    for (double c = first; c <= cmax; c += spacing) {
        // Start where the line enters the image's bounding circle around the centre projected on it.
        const double cx = 0.5 * width, cy = 0.5 * height;
        const double offset = c - (cx * nx + cy * ny);
        const double sx = cx + offset * nx - dx * 0.5 * length, sy = cy + offset * ny - dy * 0.5 * length;
        const int steps = int(length / step) + 1;
        bool inside = false;
        double ax = 0, ay = 0, bx = 0, by = 0;
        for (int k = 0; k <= steps; ++k) {
            const double x = sx + dx * step * k, y = sy + dy * step * k;
            if (in(x, y)) {
                if (!inside) ax = x, ay = y, inside = true;
                bx = x, by = y;
            } else if (inside) {
                out.push_back({ax, ay, bx, by});
                inside = false;
            }
        }
        if (inside) out.push_back({ax, ay, bx, by});
    }
}

} // namespace

std::vector<HatchSegment> hatchSegments(std::span<const std::uint8_t> classes, int width, int height, std::uint8_t id,
                                        Hatch hatch, double spacingPx)
{
    std::vector<HatchSegment> out;
    if (width <= 0 || height <= 0 || classes.size() != std::size_t(width) * std::size_t(height) || !(spacingPx > 0.5))
        return out;
    const double r = std::sqrt(0.5);
    switch (hatch) {
    case Hatch::None: break;
    case Hatch::Diagonal: family(classes, width, height, id, r, -r, spacingPx, out); break;
    case Hatch::BackDiagonal: family(classes, width, height, id, r, r, spacingPx, out); break;
    case Hatch::Horizontal: family(classes, width, height, id, 1, 0, spacingPx, out); break;
    case Hatch::Vertical: family(classes, width, height, id, 0, 1, spacingPx, out); break;
    case Hatch::Cross:
        family(classes, width, height, id, 1, 0, spacingPx, out);
        family(classes, width, height, id, 0, 1, spacingPx, out);
        break;
    case Hatch::DiagonalCross:
        family(classes, width, height, id, r, -r, spacingPx, out);
        family(classes, width, height, id, r, r, spacingPx, out);
        break;
    case Hatch::Solid: family(classes, width, height, id, 1, 0, spacingPx / 3.0, out); break;
    case Hatch::Dots:
        for (double y = 0.5 * spacingPx; y < height; y += spacingPx)
            for (double x = 0.5 * spacingPx; x < width; x += spacingPx) {
                const int ix = int(x), iy = int(y);
                if (classes[std::size_t(iy) * std::size_t(width) + std::size_t(ix)] == id) out.push_back({x, y, x, y});
            }
        break;
    }
    return out;
}

} // namespace stylos::core::plate
