#pragma once
/** @file
 * @brief Normal estimation for clouds held in memory: for every point, the plane through its k
 *        nearest neighbours (principal component analysis), oriented away from a centre or toward a
 *        scanner. For files larger than memory, see NormalFileEstimation.h.
 *
 * Method. Neighbours: the k nearest points, the point itself included, found exactly with nanoflann
 * KD-trees (leaf size 20) searched one leaf of queries at a time, in float relative to the bounding-box
 * centre (a 300 m cloud still resolves 15 µm); ties at equal distance are broken by a fixed spatial
 * (Morton) rank, so the neighbourhood of a point is a well-defined set in a well-defined order.
 * Normal: the eigenvector of the smallest eigenvalue of the neighbours' covariance (computed in double;
 * NeighbourhoodPca.h). Orientation: flipped so that n·(p − c) ≥ 0 (AwayFromCentre; right for
 * star-shaped objects such as a drum or a statue seen from outside) or n·(s − p) ≥ 0 (TowardViewpoint;
 * right for a single scan whose scanner position s is known). Quality: the surface variation
 * λ0/(λ0+λ1+λ2), 0 on a plane, 1/3 for isotropic noise.
 *
 * Degenerate neighbourhoods get a defined fallback and are counted in NormalReport::degenerate:
 * fewer than 3 points or all points identical → the orientation direction itself ((p − c) or (s − p),
 * normalised; +Z if that is zero); points on a line → the orientation direction made perpendicular
 * to the line (any perpendicular if it is parallel). Their quality is 1.
 *
 * Determinism: the output is bitwise identical whatever the number of threads, trees or leaf size
 * (each point's result depends only on the input array, in its order). Speed, k = 16, 1 M points of a
 * generated drum on the 2-core 2.5 GHz Xeon dev box (NormalEstimationBenchmark): 0.65 M points/s on 1
 * thread, 1.1–1.2 M points/s on 2; about 5 % of the time (Morton sort, copies) is serial. Memory:
 * normalEstimationBytesPerPoint() (88 bytes) per point at peak beyond the caller's arrays.
 * Cancel is checked every ~1,000 points once the index is built (~0.25 s per million points).
 *
 * Units: metres (positions in any consistent unit work; nothing depends on scale).
 * Thread-safety: the function is reentrant; it starts its own std::threads and joins them before it
 * returns. The ProgressSink is called from the calling thread (update) and from workers (cancel checks).
 */
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace stylos::core::normals {

/** @brief Which way the normals are turned (the PCA gives only an axis). */
enum class NormalOrientation {
    AwayFromCentre,  ///< n·(p − c) ≥ 0, c = NormalOptions::centre or the centroid of the points
    TowardViewpoint, ///< n·(s − p) ≥ 0, s = NormalOptions::viewpoint (the scanner position)
    Unoriented,      ///< the eigenvector's sign as computed (deterministic but meaningless)
};

/** @brief Parameters of normal estimation. */
struct NormalOptions {
    /** Neighbours per point, the point itself included; 3 ≤ k ≤ 256. 16 fits 0.5 mm scans with noise. */
    std::size_t neighbours = 16;
    /** Worker threads, the caller's included; 0 means std::thread::hardware_concurrency(). */
    unsigned threads = 0;
    NormalOrientation orientation = NormalOrientation::AwayFromCentre;
    /** AwayFromCentre: the centre c, metres; absent means the centroid of the points given. */
    std::optional<std::array<double, 3>> centre;
    /** TowardViewpoint: the scanner position s, metres. */
    std::array<double, 3> viewpoint{0, 0, 0};
    /** KD-tree leaf size (points per leaf). 20 measured best for k = 16 (12: +13 % instructions,
     *  24–32: within 2 %). Changes speed, never results. */
    std::size_t leafSize = 20;
};

/** @brief What an estimation did. */
struct NormalReport {
    std::uint64_t points = 0;     ///< normals written
    std::uint64_t degenerate = 0; ///< normals from the fallback (see the file comment)
    /** Tiled file estimation only: points whose k-neighbourhood may reach past their tile's halo,
     *  so their normal may differ from the in-memory result (isolated outliers, very uneven density). */
    std::uint64_t truncated = 0;
    std::array<double, 3> centre{0, 0, 0}; ///< the c used by AwayFromCentre (else the centroid)
};

/**
 * @brief Estimates one unit normal per point.
 * @param positions x y z interleaved (3n doubles), finite, n < 2^32 − 1.
 * @param normals   output, 3n floats (nx ny nz), same order as the positions.
 * @param quality   optional output: n floats, the surface variation (empty: not computed).
 * @return the report, or InvalidArgument (sizes that disagree, k or leaf size out of range, a
 *         non-finite coordinate: the message gives its index), OutOfBudget (allocation failed) or
 *         Cancelled (the outputs are then partly written and must be discarded).
 */
Result<NormalReport> estimateNormals(std::span<const double> positions, std::span<float> normals,
                                     const NormalOptions& options = {}, ProgressSink* progress = nullptr,
                                     std::span<float> quality = {});

/** @brief Peak working memory of estimateNormals() per point, in bytes, not counting its arguments. */
std::size_t normalEstimationBytesPerPoint();

} // namespace stylos::core::normals
