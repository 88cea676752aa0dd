#include "UnrollRaster.h"

#include "UnrollParallel.h"
#include "stylos/core/util/SubProgress.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace stylos::core::unroll::detail {

namespace {
constexpr double kQuantum = 1e-9; ///< fixed-point unit of the per-pixel sums, metres
constexpr int kTileShift = 4;      ///< the per-pixel records are stored in tiles of 16 × 16 pixels

/** Index of pixel (c, r) in tiles of 16 × 16 (4 KiB of records): a scanner's column sweep, row after
 *  row, stays within one memory page for 16 rows instead of changing page at every point. */
std::uint32_t tiled(int c, int r, std::uint32_t tilesAcross)
{
    const std::uint32_t tile = std::uint32_t(r >> kTileShift) * tilesAcross + std::uint32_t(c >> kTileShift);
    return (tile << (2 * kTileShift)) | (std::uint32_t(r & 15) << kTileShift) | std::uint32_t(c & 15);
}
}

std::optional<KeptPoint> keptPoint(const UnrollMap& map, const cloud::PointCloud& cloud, std::size_t i, double band)
{
    const Eigen::Vector3d world = cloud.world(i);
    if (!world.allFinite()) return std::nullopt;
    const UnrollMap::AxialCoords c = map.axialCoords(world);
    const auto coords = map.surface().meridianCoords(c.t, c.r);
    if (!coords || !std::isfinite(coords->v) || !(std::abs(coords->h) <= band)) return std::nullopt;
    return KeptPoint{c.x, c.y, coords->v, coords->h};
}

UnrollRaster::UnrollRaster(const cloud::PointCloud& cloud, const UnrollMap& map, double band, double tolerance,
                           unsigned threads)
    : m_cloud(cloud), m_map(map), m_azimuth(map), m_band(band), m_tolerance(tolerance), m_threads(threads)
{
}

void UnrollRaster::locateBlock(std::size_t begin, std::size_t end, Scratch& scratch, std::vector<Hit>& hits) const
{
    auto& points = scratch.points;
    auto& columns = scratch.columns;
    points.clear();
    for (std::size_t i = begin; i < end; ++i)
        if (const auto point = keptPoint(m_map, m_cloud, i, m_band)) points.push_back(*point);
    const std::size_t n = points.size();
    columns.resize(n);
    for (std::size_t k = 0; k < n; ++k) columns[k] = m_azimuth.approxColumn(points[k].x, points[k].y);
    hits.clear();
    const double vTop = m_map.vTop(), pixel = m_map.pixelSize();
    const int lastRow = m_map.height() - 1;
    const auto tilesAcross = std::uint32_t((m_map.width() + 15) >> kTileShift);
    const double width = double(m_map.width()); // the whole turn's columns, or a fragment's arc's (UnrollOptions)
    for (std::size_t k = 0; k < n; ++k) {
        const KeptPoint& p = points[k];
        if (!(columns[k] < width)) { // beyond a cropped arc (on the whole turn only at the seam, by rounding)
            ++scratch.outsideArc;
            continue;
        }
        const int c = m_azimuth.column(p.x, p.y, columns[k]);
        // clamp(floor(q), 0, height − 1) without a libm call: int() floors what is ≥ 0.
        const double q = (vTop - p.v) / pixel;
        const int r = q < 0.0 ? 0 : q >= double(lastRow) ? lastRow : int(q);
        hits.push_back(Hit{tiled(c, r, tilesAcross), float(p.h)});
    }
}

template <typename Body>
void UnrollRaster::forEachHit(std::size_t begin, std::size_t end, Scratch& scratch, std::vector<Hit>& hits,
                              Body&& body) const
{
    for (std::size_t b = begin; b < end; b += kBlock) {
        locateBlock(b, std::min(end, b + kBlock), scratch, hits);
        for (const Hit& hit : hits) body(hit);
    }
}

bool UnrollRaster::run(shading::HeightField& field, ProgressSink* progress)
{
    // One 16-byte record per pixel, so that a point touches one cache line in each pass, in tiles.
    struct alignas(16) Pixel {
        float top = -std::numeric_limits<float>::infinity(); ///< largest h of its points
        std::uint32_t count = 0;                             ///< points averaged
        std::uint64_t below = 0;                             ///< Σ (top − h) of those, in kQuantum
    };
    const std::size_t tilesAcross = std::size_t((field.width() + 15) >> kTileShift);
    const std::size_t tilesDown = std::size_t((field.height() + 15) >> kTileShift);
    std::vector<Pixel> pixels(tilesAcross * tilesDown << (2 * kTileShift));

    std::vector<Scratch> scratch(m_threads);
    std::vector<std::vector<Hit>> hits(m_threads);
    SubProgress maxStage(progress, 0.0, 0.45);
    const bool maxDone = parallelPoints(m_cloud.size(), m_threads, &maxStage,
                                        [&](std::size_t begin, std::size_t end, unsigned worker) {
        forEachHit(begin, end, scratch[worker], hits[worker], [&](const Hit& hit) {
            std::atomic_ref<float> top(pixels[hit.pixel].top);
            float current = top.load(std::memory_order_relaxed);
            while (hit.h > current && !top.compare_exchange_weak(current, hit.h, std::memory_order_relaxed)) {
            }
        });
    });
    if (!maxDone) return false;

    std::atomic<std::uint64_t> averaged{0};
    for (Scratch& s : scratch) s.outsideArc = 0; // counted again by the second pass: once
    SubProgress sumStage(progress, 0.45, 0.9);
    const bool sumDone = parallelPoints(m_cloud.size(), m_threads, &sumStage,
                                        [&](std::size_t begin, std::size_t end, unsigned worker) {
        std::uint64_t mine = 0;
        forEachHit(begin, end, scratch[worker], hits[worker], [&](const Hit& hit) {
            Pixel& pixel = pixels[hit.pixel];
            const double depth = double(pixel.top) - double(hit.h); // ≥ 0: top is the largest
            if (!(depth <= m_tolerance)) return;
            std::atomic_ref<std::uint64_t>(pixel.below)
                .fetch_add(std::uint64_t(depth * (1.0 / kQuantum) + 0.5), std::memory_order_relaxed);
            std::atomic_ref<std::uint32_t>(pixel.count).fetch_add(1, std::memory_order_relaxed);
            ++mine;
        });
        averaged.fetch_add(mine, std::memory_order_relaxed);
    });
    if (!sumDone) return false;
    m_averaged = averaged.load();
    m_outsideArc = 0;
    for (const Scratch& s : scratch) m_outsideArc += s.outsideArc;

    std::span<float> heights = field.heights();
    std::span<shading::PixelState> states = field.states();
    for (int r = 0; r < field.height(); ++r)
        for (int c = 0; c < field.width(); ++c) {
            const Pixel& pixel = pixels[tiled(c, r, std::uint32_t(tilesAcross))];
            if (pixel.count == 0) continue; // Empty, height 0
            const std::size_t k = field.index(c, r);
            heights[k] = float(double(pixel.top) - double(pixel.below) * kQuantum / double(pixel.count));
            states[k] = shading::PixelState::Measured;
        }
    if (progress) progress->update(1.0);
    return true;
}

} // namespace stylos::core::unroll::detail
