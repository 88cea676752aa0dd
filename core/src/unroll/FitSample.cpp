#include "FitSample.h"

#include <cmath>

namespace stylos::core::unroll::detail {

namespace {
__extension__ typedef unsigned __int128 Wide; // 64 × 64 → 128-bit products
} // namespace

std::uint64_t splitMix64(std::uint64_t s, std::uint64_t n)
{
    std::uint64_t z = s + (n + 1) * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

std::vector<std::size_t> stratifiedSample(std::size_t count, std::size_t target, std::uint64_t seed,
                                          std::uint64_t stream)
{
    std::vector<std::size_t> indices;
    if (count <= target) {
        indices.resize(count);
        for (std::size_t i = 0; i < count; ++i)
            indices[i] = i;
        return indices;
    }
    indices.resize(target);
    const std::uint64_t key = splitMix64(seed, stream);
    for (std::size_t k = 0; k < target; ++k) {
        // Stratum k is [⌊k·count/target⌋, ⌊(k+1)·count/target⌋), never empty as count > target.
        const std::size_t begin = std::size_t((Wide)k * count / target);
        const std::size_t end = std::size_t((Wide)(k + 1) * count / target);
        const std::uint64_t u = splitMix64(key, k);
        indices[k] = begin + std::size_t((Wide)u * (end - begin) >> 64);
    }
    return indices;
}

FitPoints gatherPoints(const cloud::PointCloud& cloud, const std::vector<std::size_t>& indices, bool withNormals)
{
    FitPoints points;
    withNormals = withNormals && cloud.hasNormals();
    points.xyz.reserve(3 * indices.size());
    if (withNormals) points.normals.reserve(3 * indices.size());
    for (std::size_t i : indices) {
        const float* p = &cloud.positions[3 * i];
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
        if (withNormals) {
            const float* n = &cloud.normals[3 * i];
            if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) continue;
            points.normals.insert(points.normals.end(), n, n + 3);
        }
        points.xyz.insert(points.xyz.end(), p, p + 3);
    }
    return points;
}

} // namespace stylos::core::unroll::detail
