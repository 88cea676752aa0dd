#pragma once
// Internal to the surface fit: the points a stage works on (a stratified random sample of the cloud).
#include "stylos/core/cloud/PointCloud.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace stylos::core::unroll::detail {

/** @brief Points (and optionally normals) copied out of a cloud, float, in the cloud's local frame. */
struct FitPoints {
    std::vector<float> xyz;     ///< x y z interleaved, cloud-local (relative to PointCloud::origin)
    std::vector<float> normals; ///< nx ny nz interleaved, or empty

    std::size_t size() const { return xyz.size() / 3; }
};

/**
 * @brief A stratified random sample of about @p target of the @p count indices 0..count−1, ascending:
 *        the range is cut into @p target equal strata and one index is drawn uniformly in each
 *        (SplitMix64 of @p seed and @p stream). All indices when count ≤ target. Depends only on the
 *        arguments.
 */
std::vector<std::size_t> stratifiedSample(std::size_t count, std::size_t target, std::uint64_t seed,
                                          std::uint64_t stream);

/** @brief The points at @p indices, skipping non-finite ones; their normals too when @p withNormals
 *         and the cloud has them. */
FitPoints gatherPoints(const cloud::PointCloud& cloud, const std::vector<std::size_t>& indices, bool withNormals);

/** SplitMix64's output n for seed s (a counter-based generator: the same (s, n) always gives the same). */
std::uint64_t splitMix64(std::uint64_t s, std::uint64_t n);

} // namespace stylos::core::unroll::detail
