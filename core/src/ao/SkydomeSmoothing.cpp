#include "stylos/core/ao/SkydomeSmoothing.h"

#include "../shading/ParallelChunks.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace stylos::core::ao {

namespace {

/** Bins of edge `radius`, keyed by their three coordinates (21 bits each, offset so that none is negative). */
struct Bins {
    double edge = 1.0;
    std::array<double, 3> lower{};
    std::vector<std::pair<std::uint64_t, std::uint32_t>> sorted; ///< (key, receiver), by key
    std::vector<std::uint64_t> keys;                              ///< the distinct keys, ascending
    std::vector<std::uint32_t> begin;                             ///< keys + 1 entries: each bin's range in sorted

    static constexpr std::uint64_t kCoordMask = (1u << 21) - 1;

    std::array<std::int64_t, 3> coordsOf(const std::array<float, 3>& p) const
    {
        return {std::int64_t(std::floor((double(p[0]) - lower[0]) / edge)),
                std::int64_t(std::floor((double(p[1]) - lower[1]) / edge)),
                std::int64_t(std::floor((double(p[2]) - lower[2]) / edge))};
    }
    static std::uint64_t keyOf(std::int64_t x, std::int64_t y, std::int64_t z)
    {
        return (std::uint64_t(z) << 42) | (std::uint64_t(y) << 21) | std::uint64_t(x);
    }
};

} // namespace

Status smoothSkydome(const AoReceivers& receivers, std::span<float> values, const SkydomeSmoothing& options,
                     ProgressSink* progress)
{
    assert(values.size() == receivers.size() && "smoothSkydome(): one value per receiver");
    const std::size_t n = receivers.size();
    if (!(options.radius > 0.0) || n < 2) return {};

    Bins bins;
    bins.edge = options.radius;
    bins.lower = {double(receivers.positions[0][0]), double(receivers.positions[0][1]), double(receivers.positions[0][2])};
    std::array<double, 3> upper = bins.lower;
    for (const auto& p : receivers.positions)
        for (int a = 0; a < 3; ++a) bins.lower[a] = std::min(bins.lower[a], double(p[a])), upper[a] = std::max(upper[a], double(p[a]));
    // At most 2^21 bins along an axis: a radius too small for the extent is widened (a finer grid than that
    // would hold one receiver per million bins).
    for (int a = 0; a < 3; ++a) bins.edge = std::max(bins.edge, (upper[a] - bins.lower[a]) / double(Bins::kCoordMask - 2));
    for (int a = 0; a < 3; ++a) bins.lower[a] -= bins.edge; // a margin: every neighbour bin's coordinate ≥ 0

    bins.sorted.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = bins.coordsOf(receivers.positions[i]);
        bins.sorted[i] = {Bins::keyOf(c[0], c[1], c[2]), std::uint32_t(i)};
    }
    std::sort(bins.sorted.begin(), bins.sorted.end());
    for (std::size_t i = 0; i < n; ++i)
        if (i == 0 || bins.sorted[i].first != bins.sorted[i - 1].first) {
            bins.keys.push_back(bins.sorted[i].first);
            bins.begin.push_back(std::uint32_t(i));
        }
    bins.begin.push_back(std::uint32_t(n));
    // The receivers in bin order, so that a bin's neighbours are read as contiguous runs.
    struct Leaf {
        float x, y, z, nx, ny, nz, value;
    };
    std::vector<Leaf> leaves(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t i = bins.sorted[k].second;
        const auto& p = receivers.positions[i];
        const auto& m = receivers.normals[i];
        leaves[k] = {p[0], p[1], p[2], m[0], m[1], m[2], values[i]};
    }

    const float r2 = float(options.radius * options.radius), inverse = 1.0f / r2;
    std::vector<float> smoothed(n);
    const bool finished = shading::detail::parallelChunks(
        bins.keys.size(), 256, shading::detail::resolveThreads(options.threads), progress,
        [&](std::size_t first, std::size_t last, unsigned) {
            // The neighbours of bin (x, y, z) in row (y + dy, z + dz) are bins x − 1..x + 1 of that row: keys
            // key − 1 + offset .. key + 1 + offset, consecutive in the sorted keys, so one run of leaves. As the
            // bins go up, each of the nine rows' first key goes up too: a cursor per row that only moves on.
            std::array<std::uint64_t, 9> offset{};
            for (int r = 0; r < 9; ++r)
                offset[std::size_t(r)] = (std::uint64_t(std::int64_t(r % 3 - 1)) << 21) + (std::uint64_t(std::int64_t(r / 3 - 1)) << 42);
            std::array<std::size_t, 9> cursor{};
            const std::size_t keyCount = bins.keys.size();
            for (std::size_t r = 0; r < 9; ++r)
                cursor[r] = std::size_t(std::lower_bound(bins.keys.begin(), bins.keys.end(), bins.keys[first] + offset[r] - 1) -
                                        bins.keys.begin());
            std::array<std::pair<std::uint32_t, std::uint32_t>, 9> ranges;
            for (std::size_t b = first; b < last; ++b) {
                std::size_t count = 0;
                for (std::size_t r = 0; r < 9; ++r) {
                    const std::uint64_t low = bins.keys[b] + offset[r] - 1, high = low + 2;
                    std::size_t c = cursor[r];
                    while (c < keyCount && bins.keys[c] < low) ++c;
                    cursor[r] = c;
                    std::size_t e = c;
                    while (e < keyCount && bins.keys[e] <= high) ++e;
                    if (e > c) ranges[count++] = {bins.begin[c], bins.begin[e]};
                }
                for (std::uint32_t k = bins.begin[b]; k < bins.begin[b + 1]; ++k) {
                    const Leaf& a = leaves[k];
                    float sum = 0.0f, weights = 0.0f;
                    for (std::size_t r = 0; r < count; ++r)
                        for (std::uint32_t l = ranges[r].first; l < ranges[r].second; ++l) {
                            const Leaf& o = leaves[l];
                            const float dx = o.x - a.x, dy = o.y - a.y, dz = o.z - a.z;
                            const float d2 = dx * dx + dy * dy + dz * dz;
                            const float facing = std::abs(a.nx * o.nx + a.ny * o.ny + a.nz * o.nz);
                            if (d2 >= r2 || facing < options.minCos) continue;
                            const float t = 1.0f - d2 * inverse; // (1 − d²/r²)²: 1 at the centre, 0 at the radius
                            sum += t * t * o.value;
                            weights += t * t;
                        }
                    smoothed[bins.sorted[k].second] = weights > 0.0f ? sum / weights : a.value;
                }
            }
        });
    if (!finished) return Error{ErrorCode::Cancelled, "the skydome's smoothing was cancelled"};
    std::copy(smoothed.begin(), smoothed.end(), values.begin());
    return {};
}

} // namespace stylos::core::ao
