#include "DepthMapFrame.h"

#include <algorithm>
#include <cmath>

namespace stylos::core::ao::detail {

DepthMapFrame makeDepthMapFrame(const std::array<float, 3>& dir, const std::array<float, 3>& lo,
                                const std::array<float, 3>& hi)
{
    const double d[3] = {dir[0], dir[1], dir[2]};
    double e1[3] = {1.0, 0.0, 0.0};
    const double r = std::hypot(d[0], d[1]);
    if (r > 1e-9) {
        e1[0] = -d[1] / r;
        e1[1] = d[0] / r;
    }
    const double e2[3] = {d[1] * e1[2] - d[2] * e1[1], d[2] * e1[0] - d[0] * e1[2], d[0] * e1[1] - d[1] * e1[0]};
    DepthMapFrame f;
    // Bounds of the projections and keys of the box's corners.
    double uLo = 0, uHi = 0, vLo = 0, vHi = 0, kLo = 0, kHi = 0;
    for (int k = 0; k < 3; ++k) {
        f.e1[k] = float(e1[k]);
        f.e2[k] = float(e2[k]);
        f.d[k] = float(d[k]);
        const double a = lo[std::size_t(k)], b = hi[std::size_t(k)];
        uLo += std::min(e1[k] * a, e1[k] * b);
        uHi += std::max(e1[k] * a, e1[k] * b);
        vLo += std::min(e2[k] * a, e2[k] * b);
        vHi += std::max(e2[k] * a, e2[k] * b);
        kLo += std::min(d[k] * a, d[k] * b);
        kHi += std::max(d[k] * a, d[k] * b);
    }
    // A pixel of margin on each side (the 2 × 2 splat below and right, float rounding) and one more.
    f.u0 = float(1.0 - std::floor(uLo));
    f.v0 = float(1.0 - std::floor(vLo));
    f.width = int(std::ceil(uHi) - std::floor(uLo)) + 3;
    f.height = int(std::ceil(vHi) - std::floor(vLo)) + 3;
    f.keyMin = float(kLo - 1.0);
    const double range = kHi - kLo + 2.0;
    f.keyScale = float(double((1 << 23) - 4) / range);
    f.keyInverse = 1.0f / f.keyScale;

    // Projected axes A_k = (e1_k, e2_k); slab normal N_k ⊥ A_k (unit), half-width h_k = ½ Σ_m |N_k·A_m|.
    // An axis along d projects to a point: its slab is void (N = 0, h = 1 always holds).
    for (int k = 0; k < 3; ++k) {
        const double len = std::hypot(e1[k], e2[k]);
        double nu = 0, nv = 0, h = 1.0;
        if (len > 1e-6) {
            nu = -e2[k] / len;
            nv = e1[k] / len;
            h = 1e-4;
            for (int m = 0; m < 3; ++m)
                h += 0.5 * std::abs(nu * e1[m] + nv * e2[m]);
        }
        f.nu[k] = float(nu);
        f.nv[k] = float(nv);
        f.h[k] = float(h);
    }
    return f;
}

} // namespace stylos::core::ao::detail
