#include "stylos/core/octree/NormalCode.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace stylos::core::octree {

namespace {

constexpr int paperLevels = 6;
constexpr int octGridHalf = 126; // map coordinate = k / 126 − 1, k in [0, 252]
constexpr int octGridMax = 2 * octGridHalf;

using Vec3d = std::array<double, 3>;

/** Rescaled input: false (and untouched v) for zero or non-finite vectors. */
bool normalisedInput(float x, float y, float z, Vec3d& v)
{
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return false;
    const double m = std::max({std::abs(double(x)), std::abs(double(y)), std::abs(double(z))});
    if (m == 0) return false;
    v = {x / m, y / m, z / m};
    return true;
}

std::array<float, 3> unitFloat(double x, double y, double z)
{
    const double n = std::sqrt(x * x + y * y + z * z);
    return {float(x / n), float(y / n), float(z / n)};
}

// ---- Paper15 ----

std::uint16_t encodePaper(const Vec3d& v)
{
    const unsigned octant = (v[0] < 0 ? 1u : 0u) | (v[1] < 0 ? 2u : 0u) | (v[2] < 0 ? 4u : 0u);
    const double s = std::abs(v[0]) + std::abs(v[1]) + std::abs(v[2]);
    // Barycentric coordinates in the current triangle (initially the face: corners x, y, z).
    double a = std::abs(v[0]) / s, b = std::abs(v[1]) / s, c = std::abs(v[2]) / s;
    unsigned code = octant;
    for (int level = 0; level < paperLevels; ++level) {
        unsigned child;
        if (a >= 0.5) {
            child = 0, a = 2 * a - 1, b = 2 * b, c = 2 * c;
        } else if (b >= 0.5) {
            child = 1, a = 2 * a, b = 2 * b - 1, c = 2 * c;
        } else if (c >= 0.5) {
            child = 2, a = 2 * a, b = 2 * b, c = 2 * c - 1;
        } else { // central, inverted triangle (mid-yz, mid-zx, mid-xy)
            child = 3, a = 1 - 2 * a, b = 1 - 2 * b, c = 1 - 2 * c;
        }
        code = (code << 2) | child;
    }
    return static_cast<std::uint16_t>(code);
}

std::array<float, 3> decodePaper(std::uint16_t code)
{
    code &= 0x7FFF;
    Vec3d p0{1, 0, 0}, p1{0, 1, 0}, p2{0, 0, 1};
    auto mid = [](const Vec3d& u, const Vec3d& w) {
        return Vec3d{(u[0] + w[0]) / 2, (u[1] + w[1]) / 2, (u[2] + w[2]) / 2};
    };
    for (int level = 0; level < paperLevels; ++level) {
        const unsigned child = (code >> (2 * (paperLevels - 1 - level))) & 3u;
        const Vec3d m01 = mid(p0, p1), m12 = mid(p1, p2), m20 = mid(p2, p0);
        switch (child) {
        case 0: p1 = m01, p2 = m20; break;
        case 1: p0 = m01, p2 = m12; break;
        case 2: p0 = m20, p1 = m12; break;
        default: p0 = m12, p1 = m20, p2 = m01; break;
        }
    }
    const unsigned octant = code >> (2 * paperLevels);
    const double x = (p0[0] + p1[0] + p2[0]) * ((octant & 1u) ? -1 : 1);
    const double y = (p0[1] + p1[1] + p2[1]) * ((octant & 2u) ? -1 : 1);
    const double z = (p0[2] + p1[2] + p2[2]) * ((octant & 4u) ? -1 : 1);
    return unitFloat(x, y, z);
}

// ---- Octahedral16 ----

/** Folded octahedral map coordinates of v (any length, not zero), in [−1, 1]². */
std::array<double, 2> octahedralMap(const Vec3d& v)
{
    const double s = std::abs(v[0]) + std::abs(v[1]) + std::abs(v[2]);
    double u = v[0] / s, w = v[1] / s;
    if (v[2] < 0) {
        const double fu = (1 - std::abs(w)) * (u < 0 ? -1 : 1);
        const double fw = (1 - std::abs(u)) * (w < 0 ? -1 : 1);
        u = fu, w = fw;
    }
    return {u, w};
}

std::uint16_t octCode(int ku, int kv)
{
    return static_cast<std::uint16_t>((std::clamp(ku, 0, octGridMax) << 8) | std::clamp(kv, 0, octGridMax));
}

Vec3d decodeOctDouble(std::uint16_t code)
{
    const int ku = std::min<int>(code >> 8, octGridMax), kv = std::min<int>(code & 0xFF, octGridMax);
    double u = double(ku - octGridHalf) / octGridHalf, w = double(kv - octGridHalf) / octGridHalf;
    const double z = 1 - std::abs(u) - std::abs(w);
    if (z < 0) {
        const double fu = (1 - std::abs(w)) * (u < 0 ? -1 : 1);
        const double fw = (1 - std::abs(u)) * (w < 0 ? -1 : 1);
        u = fu, w = fw;
    }
    return {u, w, z};
}

std::array<float, 3> decodeOct(std::uint16_t code)
{
    const Vec3d d = decodeOctDouble(code);
    return unitFloat(d[0], d[1], d[2]);
}

std::uint16_t encodeOctRounded(const Vec3d& v)
{
    const auto m = octahedralMap(v);
    return octCode(int(std::lround((m[0] + 1) * octGridHalf)), int(std::lround((m[1] + 1) * octGridHalf)));
}

std::uint16_t encodeOctPrecise(const Vec3d& v)
{
    const auto m = octahedralMap(v);
    const int fu = int(std::floor((m[0] + 1) * octGridHalf)), fv = int(std::floor((m[1] + 1) * octGridHalf));
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    std::uint16_t best = octCode(fu, fv);
    double bestCos = -2;
    for (int du = 0; du < 2; ++du) {
        for (int dv = 0; dv < 2; ++dv) {
            const std::uint16_t candidate = octCode(fu + du, fv + dv);
            const Vec3d d = decodeOctDouble(candidate);
            const double cosine = (d[0] * v[0] + d[1] * v[1] + d[2] * v[2]) /
                                  (n * std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
            if (cosine > bestCos) bestCos = cosine, best = candidate;
        }
    }
    return best;
}

std::vector<std::array<float, 3>> buildTable(NormalCodeKind kind)
{
    std::vector<std::array<float, 3>> table(normalCodeCount(kind));
    for (std::size_t code = 0; code < table.size(); ++code)
        table[code] = decodeNormal(kind, static_cast<std::uint16_t>(code));
    return table;
}

/** Standard normal deviates by Box–Muller on a 64-bit Mersenne twister (platform-independent). */
class Gaussian {
public:
    explicit Gaussian(std::uint64_t seed) : m_random(seed) {}
    double operator()()
    {
        if (m_hasSpare) {
            m_hasSpare = false;
            return m_spare;
        }
        constexpr double twoPi = 6.283185307179586476925;
        const double u1 = (double(m_random() >> 11) + 0.5) * 0x1p-53; // in (0, 1)
        const double u2 = double(m_random() >> 11) * 0x1p-53;
        const double r = std::sqrt(-2 * std::log(u1));
        m_spare = r * std::sin(twoPi * u2);
        m_hasSpare = true;
        return r * std::cos(twoPi * u2);
    }

private:
    std::mt19937_64 m_random;
    double m_spare = 0;
    bool m_hasSpare = false;
};

} // namespace

std::size_t normalCodeCount(NormalCodeKind kind)
{
    return kind == NormalCodeKind::Paper15 ? std::size_t(1) << 15 : std::size_t(1) << 16;
}

std::uint16_t encodeNormal(NormalCodeKind kind, float x, float y, float z)
{
    Vec3d v{0, 0, 1};
    normalisedInput(x, y, z, v); // zero or non-finite: keeps +Z
    return kind == NormalCodeKind::Paper15 ? encodePaper(v) : encodeOctPrecise(v);
}

std::uint16_t encodeOctahedral16Rounded(float x, float y, float z)
{
    Vec3d v{0, 0, 1};
    normalisedInput(x, y, z, v);
    return encodeOctRounded(v);
}

std::array<float, 3> decodeNormal(NormalCodeKind kind, std::uint16_t code)
{
    return kind == NormalCodeKind::Paper15 ? decodePaper(code) : decodeOct(code);
}

const std::array<float, 3>* normalDecodeTable(NormalCodeKind kind)
{
    static const std::vector<std::array<float, 3>> paper = buildTable(NormalCodeKind::Paper15);
    static const std::vector<std::array<float, 3>> octahedral = buildTable(NormalCodeKind::Octahedral16);
    return kind == NormalCodeKind::Paper15 ? paper.data() : octahedral.data();
}

NormalCodeError measureNormalCodeError(NormalCodeKind kind, std::size_t samples, std::uint64_t seed)
{
    NormalCodeError error;
    if (samples == 0) return error;
    Gaussian gaussian(seed);
    double sum = 0;
    for (std::size_t i = 0; i < samples; ++i) {
        double x, y, z, n;
        do {
            x = gaussian(), y = gaussian(), z = gaussian();
            n = std::sqrt(x * x + y * y + z * z);
        } while (n == 0);
        x /= n, y /= n, z /= n;
        const auto d = decodeNormal(kind, encodeNormal(kind, float(x), float(y), float(z)));
        const double cx = y * d[2] - z * d[1], cy = z * d[0] - x * d[2], cz = x * d[1] - y * d[0];
        const double angle =
            std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), x * d[0] + y * d[1] + z * d[2]);
        sum += angle;
        error.maxRadians = std::max(error.maxRadians, angle);
    }
    error.meanRadians = sum / double(samples);
    return error;
}

} // namespace stylos::core::octree
