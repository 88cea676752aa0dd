#include "Frustum.h"

#include <cmath>

namespace stylos::core::octree {

Frustum Frustum::fromViewProjection(const std::array<double, 16>& m, const std::array<double, 3>& origin)
{
    // Row r of the column-major matrix: (m[r], m[4 + r], m[8 + r], m[12 + r]). The clip planes are
    // row3 + row0, row3 − row0, row3 + row1, row3 − row1, row3 + row2, row3 − row2 (Gribb & Hartmann).
    Frustum f;
    for (int i = 0; i < 6; ++i) {
        const int r = i / 2;
        const double sign = (i % 2 == 0) ? 1.0 : -1.0;
        double a[4];
        for (int c = 0; c < 4; ++c) a[c] = m[4 * c + 3] + sign * m[4 * c + r];
        const double len = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        if (!(len > 0) || !std::isfinite(len) || !std::isfinite(a[3])) continue;
        Plane& p = f.m_planes[static_cast<std::size_t>(i)];
        p.n = {a[0] / len, a[1] / len, a[2] / len};
        // Relative coordinates: n · (q + origin) + d = n · q + (d + n · origin).
        p.d = a[3] / len + p.n[0] * origin[0] + p.n[1] * origin[1] + p.n[2] * origin[2];
        f.m_usable |= static_cast<std::uint8_t>(1u << i);
    }
    return f;
}

bool Frustum::keep(const std::array<double, 3>& c, double half, std::uint8_t& planes) const
{
    std::uint8_t active = planes & m_usable;
    planes = active;
    for (int i = 0; active != 0; ++i, active >>= 1) {
        if ((active & 1u) == 0) continue;
        const Plane& p = m_planes[static_cast<std::size_t>(i)];
        const double nc = p.n[0] * c[0] + p.n[1] * c[1] + p.n[2] * c[2];
        const double s = nc + p.d;
        const double r = half * (std::abs(p.n[0]) + std::abs(p.n[1]) + std::abs(p.n[2]));
        // Rounding tolerance, in favour of keeping cells near a plane.
        const double tol = 1e-12 * (std::abs(nc) + std::abs(p.d) + r);
        if (s + r < -tol) return false;
        if (s - r > tol) planes &= static_cast<std::uint8_t>(~(1u << i));
    }
    return true;
}

} // namespace stylos::core::octree
