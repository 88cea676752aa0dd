#include "stylos/core/ao/ReferenceAo.h"

#include "../shading/ParallelChunks.h"
#include "AoKernel.h"
#include "stylos/core/ao/Directions.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace stylos::core::ao {
namespace {

/** Coordinates (≤ 21 bits each, MaxOctreeDepth) packed into one key. */
std::uint64_t packCoords(std::uint64_t x, std::uint64_t y, std::uint64_t z) { return (x << 42) | (y << 21) | z; }

/**
 * The occupied cells: an open-addressing hash set of packed coordinates (load ≤ 1/2), and in front of
 * it a bitset of bricks of 8³ cells (coarser where the box is huge) over the cells' bounding box, so that rays crossing empty space (most of
 * a ray's steps) rarely touch the hash table. Read-only once built; any number of threads may query it.
 */
class OccupiedCells {
public:
    explicit OccupiedCells(const AoCells& cells)
    {
        m_min = {UINT32_MAX, UINT32_MAX, UINT32_MAX};
        m_max = {0, 0, 0};
        for (const auto& c : cells.coords)
            for (int a = 0; a < 3; ++a) {
                m_min[a] = std::min(m_min[a], c[a]);
                m_max[a] = std::max(m_max[a], c[a]);
            }
        std::size_t slots = 16;
        while (slots < 2 * cells.size()) slots *= 2;
        m_mask = slots - 1;
        m_keys.assign(slots, kEmpty);
        // Bricks of 2^shift cells a side, 8 or more so the bitset stays ≤ 32 MiB at any level.
        for (;; ++m_shift) {
            for (int a = 0; a < 3; ++a) m_bricks[a] = cells.size() ? ((m_max[a] - m_min[a]) >> m_shift) + 1 : 0;
            if (double(m_bricks[0]) * double(m_bricks[1]) * double(m_bricks[2]) <= double(1u << 28)) break;
        }
        m_brickBits.assign((m_bricks[0] * m_bricks[1] * m_bricks[2] + 63) / 64, 0);
        for (const auto& c : cells.coords) {
            const std::uint64_t key = packCoords(c[0], c[1], c[2]);
            std::size_t s = slot(key);
            while (m_keys[s] != kEmpty && m_keys[s] != key) s = (s + 1) & m_mask;
            m_keys[s] = key;
            const std::size_t b = brick(c[0], c[1], c[2]);
            m_brickBits[b >> 6] |= std::uint64_t{1} << (b & 63);
        }
    }

    const std::array<std::uint32_t, 3>& min() const { return m_min; }
    const std::array<std::uint32_t, 3>& max() const { return m_max; }

    /** Whether the cell at @p c (inside the bounding box) is occupied. */
    bool contains(const std::array<std::int64_t, 3>& c) const
    {
        const auto x = std::uint32_t(c[0]), y = std::uint32_t(c[1]), z = std::uint32_t(c[2]);
        const std::size_t b = brick(x, y, z);
        if (!(m_brickBits[b >> 6] >> (b & 63) & 1)) return false;
        const std::uint64_t key = packCoords(x, y, z);
        for (std::size_t s = slot(key);; s = (s + 1) & m_mask) {
            if (m_keys[s] == key) return true;
            if (m_keys[s] == kEmpty) return false;
        }
    }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

    std::size_t slot(std::uint64_t key) const { return std::size_t((key * 0x9E3779B97F4A7C15ull) >> 17) & m_mask; }
    std::size_t brick(std::uint32_t x, std::uint32_t y, std::uint32_t z) const
    {
        return ((std::size_t((z - m_min[2]) >> m_shift) * m_bricks[1]) + ((y - m_min[1]) >> m_shift)) * m_bricks[0] +
               ((x - m_min[0]) >> m_shift);
    }

    std::array<std::uint32_t, 3> m_min{}, m_max{};
    std::array<std::size_t, 3> m_bricks{};
    std::vector<std::uint64_t> m_keys;
    std::vector<std::uint64_t> m_brickBits;
    std::size_t m_mask = 0;
    int m_shift = 3;
};

/**
 * Whether the ray from the centre of cell @p start toward @p d leaves the occupied cells' box without
 * entering an occupied cell whose centre lies more than @p bias above the plane through the start's centre
 * with normal @p n. Amanatides–Woo traversal; where the ray crosses an edge or a corner exactly (equal
 * parameters on two or three axes), it steps those axes together: a cell that the ray only grazes at
 * its boundary is not on the ray.
 */
bool rayEscapes(const OccupiedCells& occupied, const std::array<std::uint32_t, 3>& start,
                const std::array<double, 3>& d, const std::array<double, 3>& n, double bias)
{
    constexpr double kInf = std::numeric_limits<double>::infinity();
    std::array<std::int64_t, 3> cell{start[0], start[1], start[2]}, step{};
    std::array<double, 3> tMax{}, tDelta{};
    for (int a = 0; a < 3; ++a) {
        step[a] = d[a] > 0.0 ? 1 : (d[a] < 0.0 ? -1 : 0);
        tDelta[a] = step[a] != 0 ? 1.0 / std::fabs(d[a]) : kInf;
        tMax[a] = 0.5 * tDelta[a];   // from the centre to the next face
    }
    const auto& lo = occupied.min();
    const auto& hi = occupied.max();
    for (;;) {
        const double t = std::min({tMax[0], tMax[1], tMax[2]});
        for (int a = 0; a < 3; ++a)
            if (tMax[a] == t) {
                cell[a] += step[a];
                tMax[a] += tDelta[a];
                if (cell[a] < std::int64_t(lo[a]) || cell[a] > std::int64_t(hi[a])) return true;
            }
        if (occupied.contains(cell)) {
            const double above = double(cell[0] - std::int64_t(start[0])) * n[0] +
                                 double(cell[1] - std::int64_t(start[1])) * n[1] +
                                 double(cell[2] - std::int64_t(start[2])) * n[2];
            if (above > bias) return false;
        }
    }
}

} // namespace

Result<std::vector<float>> referenceAmbientOcclusion(const AoCells& cells, std::span<const std::size_t> samples,
                                                     const AoOptions& options, ProgressSink* progress)
{
    if (options.directions < 1 || options.directions > 65536)
        return Error::at(ErrorCode::InvalidArgument, "skydome reference", "",
                         "the number of directions must be 1..65536, not " + std::to_string(options.directions));
    if (!(options.bias >= 0.0))
        return Error::at(ErrorCode::InvalidArgument, "skydome reference", "", "the bias must be ≥ 0");
    for (const std::size_t s : samples)
        if (s >= cells.size())
            return Error::at(ErrorCode::InvalidArgument, "skydome reference", "",
                             "sample " + std::to_string(s) + " is not one of the " + std::to_string(cells.size()) +
                                 " cells");

    const std::vector<Direction> directions = fibonacciDirections(options.directions, options.upperHemisphere);
    const OccupiedCells occupied(cells);
    std::vector<float> values(samples.size(), 0.0f);
    std::atomic<std::size_t> done{0};
    constexpr std::size_t kChunk = 4;
    const bool finished = shading::detail::parallelChunks(
        samples.size(), kChunk, shading::detail::resolveThreads(options.threads), progress,
        [&](std::size_t begin, std::size_t end, unsigned) {
            for (std::size_t k = begin; k < end; ++k) {
                const std::size_t i = samples[k];
                const std::array<double, 3> n{cells.normals[i][0], cells.normals[i][1], cells.normals[i][2]};
                double seen = 0.0, total = 0.0;
                for (const Direction& d : directions) {
                    // n·d in float, as the methods compute it: the same directions count.
                    const float nd = cells.normals[i][0] * float(d[0]) + cells.normals[i][1] * float(d[1]) +
                                     cells.normals[i][2] * float(d[2]);
                    const float w = detail::directionWeight(nd, options.cosineWeighted);
                    if (w == 0.0f) continue;
                    total += w;
                    if (rayEscapes(occupied, cells.coords[i], d, n, options.bias)) seen += w;
                }
                values[k] = total > 0.0 ? float(std::clamp(seen / total, 0.0, 1.0)) : 0.0f;
            }
            const std::size_t n = done.fetch_add(end - begin) + (end - begin);
            if (progress) progress->update(double(n) / double(samples.size()));
        });
    if (!finished || (progress && progress->isCancelRequested()))
        return Error::at(ErrorCode::Cancelled, "skydome reference", "", "skydome reference cancelled");
    return values;
}

} // namespace stylos::core::ao
