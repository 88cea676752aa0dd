#pragma once
/** @file
 * @brief Private to core/normals: the estimation kernel behind estimateNormals(), with the extra
 *        controls the tiled file driver needs (queries followed by halo points, a fixed search frame,
 *        a box that every neighbourhood must stay inside).
 */
#include "stylos/core/normals/NormalEstimation.h"

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

namespace stylos::core::normals::detail {

/** @brief One estimation: normals for the first queryCount points, neighbours among all points. */
struct NormalJob {
    std::span<const double> positions; ///< 3n doubles: the queryCount query points, then halo points
    std::size_t queryCount = 0;
    std::span<float> normals;          ///< 3 × queryCount
    std::span<float> quality;          ///< queryCount, or empty
    std::array<double, 3> origin{};    ///< search frame origin (the same for all tiles of a cloud)
    std::array<double, 3> centre{};    ///< orientation centre (AwayFromCentre; fallbacks of Unoriented)
    /** Lower x y z, upper x y z: a neighbourhood reaching past it is counted in NormalReport::truncated. */
    std::optional<std::array<double, 6>> validBox;
    /** With validBox: the points of the whole cloud (or scan) the job's points come from. A neighbourhood of
     *  fewer than k points is counted as truncated only when the cloud has more than it found. */
    std::uint64_t cloudPoints = std::numeric_limits<std::uint64_t>::max();
};

/** Runs @p job; errors as estimateNormals() (the caller has already checked the sizes). */
Result<NormalReport> runNormalJob(const NormalJob& job, const NormalOptions& options, ProgressSink* progress);

/** "neighbours must be in [3, 256]"-style check shared by both entry points; empty when valid. */
std::optional<Error> checkNormalOptions(const NormalOptions& options);

} // namespace stylos::core::normals::detail
