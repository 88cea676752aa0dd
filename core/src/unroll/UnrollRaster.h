#pragma once
// Internal to the unroller: which points are kept, and the per-pixel rule that turns them into heights.
#include "UnrollAzimuth.h"

#include "stylos/core/cloud/PointCloud.h"
#include "stylos/core/shading/HeightField.h"
#include "stylos/core/unroll/UnrollMap.h"
#include "stylos/core/util/Progress.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

namespace stylos::core::unroll::detail {

/** @brief A kept point: its coordinates about the axis (UnrollMap::axialCoords) and on the surface. */
struct KeptPoint {
    double x = 0.0; ///< along e1, metres
    double y = 0.0; ///< along e2, metres
    double v = 0.0; ///< meridian coordinate, metres
    double h = 0.0; ///< height above the surface, metres
};

/**
 * @brief Point @p i of @p cloud on @p map, or nullopt when it is dropped: no meridian coordinates, a
 *        coordinate not finite, or |h| > @p band. Every pass of the unroller decides with this one
 *        function, with the arithmetic of UnrollMap::surfaceCoords() (v and h bit for bit; they do not
 *        depend on the cut), so they all keep the same points.
 */
std::optional<KeptPoint> keptPoint(const UnrollMap& map, const cloud::PointCloud& cloud, std::size_t i, double band);

/**
 * @brief Rasterises the kept points of a cloud into a height field with the "outermost surface seen
 *        from outside" rule, in two parallel passes over the points:
 *   1. every kept point lands in pixel (floor(column), floor(row)) of map.pixelOf(), bit for bit (the
 *      column through UnrollAzimuth; clamped to the image against rounding); the pixel keeps the largest
 *      h (as float) of its points (atomic max);
 *   2. the points of a pixel whose h is within @p tolerance of that largest h are averaged; the sum is
 *      kept in fixed point (nanometres below the largest h, atomic integer adds), so the result does
 *      not depend on the order of the points or the number of threads.
 * A pixel with points becomes Measured with that average; the others stay Empty (height 0). Points
 * deeper than the tolerance behind the outermost one (the bed face seen through the rim, the inside of
 * an overhang) change nothing.
 * Memory: 16 bytes per pixel besides the field (one record per pixel, so that a point touches one
 * cache line per pass; the records in tiles of 16 × 16 pixels, one 4 KiB page, so that consecutive
 * points of a scan line stay within a page), freed on return. Thread-safety: one object per call.
 */
class UnrollRaster {
public:
    UnrollRaster(const cloud::PointCloud& cloud, const UnrollMap& map, double band, double tolerance,
                 unsigned threads);

    /** Fills @p field (map's size, all Empty); false when cancelled (the field is then meaningless). */
    bool run(shading::HeightField& field, ProgressSink* progress);
    /** Points averaged into a pixel (after run()). */
    std::uint64_t pointsAveraged() const { return m_averaged; }
    /** Kept points beyond the map's columns (a fragment's arc, UnrollOptions::cropToPoints): in no pixel. */
    std::uint64_t pointsOutsideArc() const { return m_outsideArc; }

private:
    /** @brief A kept point's pixel (index in the tiled records of run()) and h. */
    struct Hit {
        std::uint32_t pixel;
        float h;
    };
    /** Per-worker scratch of locateBlock(). */
    struct Scratch {
        std::vector<KeptPoint> points;
        std::vector<double> columns;
        std::uint64_t outsideArc = 0; ///< kept points past the last column, counted by locateBlock
    };
    /** The hits of points [begin, end) (at most kBlock), in order; the dropped points are skipped. Three
     *  loops: keptPoint(), the approximate columns (branch-free: vectorised), the exact pixels. */
    void locateBlock(std::size_t begin, std::size_t end, Scratch& scratch, std::vector<Hit>& hits) const;
    /** Calls body(hit) for every kept point of [begin, end), block by block. */
    template <typename Body>
    void forEachHit(std::size_t begin, std::size_t end, Scratch& scratch, std::vector<Hit>& hits, Body&& body) const;

    static constexpr std::size_t kBlock = 1024;

    const cloud::PointCloud& m_cloud;
    const UnrollMap& m_map;
    UnrollAzimuth m_azimuth;
    double m_band;
    double m_tolerance;
    unsigned m_threads;
    std::uint64_t m_averaged = 0;
    std::uint64_t m_outsideArc = 0;
};

} // namespace stylos::core::unroll::detail
