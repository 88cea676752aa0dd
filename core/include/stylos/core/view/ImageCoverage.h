#pragma once
/** @file
 * @brief How much of a rendered picture of a scanned surface is background where there should be surface: the
 *        measure behind the 3D view's "no background through a scanned surface" target (docs/benchmarks.md,
 *        "Splats that close the surface"). Pure image arithmetic on a coverage mask (1 = something drawn,
 *        0 = background), row-major, @p width × @p height.
 *
 * - *Silhouette*: the closing of the covered pixels by a (2 r + 1)² square: background gaps narrower than 2 r + 1
 *   pixels count as inside.
 * - *Holes*: background pixels inside the silhouette. They are of two kinds, told apart by the background region
 *   (4-connected) they belong to:
 *   - *through*: the region lies wholly inside the silhouette and off the picture's border — background enclosed
 *     by drawn surface, seen through a gap between splats;
 *   - *edge*: the region reaches background outside the silhouette (a region at least 2 r + 1 wide: the outside,
 *     or an opening of the scan) or the border — the notches the closing fills between the round splats along an
 *     outline, whether the outline is the object's or that of an opening of the scan.
 *
 * Thread-safety: pure functions. Units: pixels. Failure modes: none (a mask whose size is not width × height is a
 * programmer error, asserted).
 */
#include <cstdint>
#include <vector>

namespace stylos::core::view {

using CoverageMask = std::vector<std::uint8_t>;

/** @brief Closing (dilation then erosion) of @p mask by a (2 @p radius + 1)² square; outside the picture counts
 *         as empty for the dilation and as full for the erosion (a shape cut by the border stays closed). */
CoverageMask closeMask(const CoverageMask& mask, int width, int height, int radius);

/** @brief Background pixels of @p covered whose 4-connected background region lies wholly inside @p silhouette
 *         and touches no border pixel (1), others 0. */
CoverageMask enclosedBackground(const CoverageMask& covered, const CoverageMask& silhouette, int width, int height);

/** @brief Pixel counts of the measure (see the file comment). */
struct CoverageCounts {
    std::int64_t covered = 0;      ///< drawn pixels
    std::int64_t silhouette = 0;   ///< pixels of the closing
    std::int64_t holes = 0;        ///< background inside the silhouette = through + edge
    std::int64_t through = 0;      ///< of which enclosed by drawn pixels
    std::int64_t edge = 0;         ///< of which open to the outside or to an opening

    double holeFraction() const { return silhouette ? double(holes) / double(silhouette) : 0.0; }
    double throughFraction() const { return silhouette ? double(through) / double(silhouette) : 0.0; }
    double edgeFraction() const { return silhouette ? double(edge) / double(silhouette) : 0.0; }
};

/** @brief What a hole pixel is, for a picture of the holes. */
enum class HoleKind : std::uint8_t { None = 0, Through = 1, Edge = 2 };

/**
 * @brief Measures @p covered with a closing of @p radius (12: a 25 × 25 square). @p kinds, when not null,
 *        receives one HoleKind per pixel.
 */
CoverageCounts measureCoverage(const CoverageMask& covered, int width, int height, int radius,
                               std::vector<HoleKind>* kinds = nullptr);

} // namespace stylos::core::view
