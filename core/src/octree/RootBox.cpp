#include "stylos/core/octree/RootBox.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace stylos::core::octree {

RootBox RootBox::enclosing(const std::array<double, 6>& bounds)
{
    double extent = 0;
    for (int a = 0; a < 3; ++a) {
        assert(bounds[a] <= bounds[a + 3] && "RootBox::enclosing(): inverted bounds");
        extent = std::max(extent, bounds[a + 3] - bounds[a]);
    }
    RootBox box;
    box.size = extent > 0 ? extent : 1.0;
    for (int a = 0; a < 3; ++a) {
        const double centre = bounds[a] + (bounds[a + 3] - bounds[a]) / 2;
        box.origin[a] = centre - box.size / 2;
    }
    return box;
}

double RootBox::cellSize(int level) const
{
    return std::ldexp(size, -level);
}

std::array<std::uint32_t, 3> RootBox::quantise(const double* p, int depth) const
{
    assert(depth >= 0 && depth <= MaxOctreeDepth && "RootBox::quantise(): depth out of range");
    const double cells = double(std::uint64_t(1) << depth);
    const std::uint32_t last = (std::uint32_t(1) << depth) - 1;
    std::array<std::uint32_t, 3> q{};
    for (int a = 0; a < 3; ++a) {
        // floor(t) clamped to [0, last]: for t >= 0, floor(t) < last exactly when t < last, and the
        // truncating conversion is the floor, so no floor() call is needed. NaN fails t >= 0: cell 0.
        const double t = (p[a] - origin[a]) / size * cells;
        q[a] = t >= 0 ? (t < double(last) ? std::uint32_t(t) : last) : 0;
    }
    return q;
}

std::array<double, 3> RootBox::cellCentre(int level, std::uint32_t ix, std::uint32_t iy, std::uint32_t iz) const
{
    const double s = cellSize(level);
    return {origin[0] + (double(ix) + 0.5) * s, origin[1] + (double(iy) + 0.5) * s,
            origin[2] + (double(iz) + 0.5) * s};
}

} // namespace stylos::core::octree
