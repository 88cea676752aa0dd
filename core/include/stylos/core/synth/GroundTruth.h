#pragma once
/** @file
 * @brief The truth sidecar of a synthetic scan: a JSON object with the kind, the generation options,
 *        the number of points written, the pose (object frame → output frame, 4×4 row-major), the axis
 *        in the output frame (point at the lower bed or base, unit direction), the scan stations and
 *        the object's own parameters (object frame). Written atomically (temporary file + rename).
 *        Units: metres, radians. Stateless; thread-safe.
 */
#include "stylos/core/synth/ScanSimulator.h"
#include "stylos/core/synth/SyntheticObject.h"
#include "stylos/core/synth/SyntheticScan.h"
#include "stylos/core/util/Result.h"

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <cstdint>
#include <filesystem>
#include <string>

namespace stylos::core::synth {

/** @brief Everything the sidecar records. */
struct GroundTruthInput {
    std::string kind;                    ///< "drum", "omphalos" or "fragment"
    const SyntheticOptions* options = nullptr;
    const SyntheticObject* object = nullptr;
    const ScanSimulator* simulator = nullptr;
    Eigen::Affine3d pose = Eigen::Affine3d::Identity(); ///< object frame → output frame
    std::uint64_t points = 0;
};

/** Builds the sidecar's JSON object. */
nlohmann::json buildGroundTruth(const GroundTruthInput& input);

/** A 4×4 transform as 16 numbers, row-major. */
nlohmann::json transformJson(const Eigen::Affine3d& transform);

/** Writes @p truth to @p path through a temporary file renamed into place. Errors: WriteFailed
 *  (nothing is left behind). */
Status writeGroundTruth(const std::filesystem::path& path, const nlohmann::json& truth);

} // namespace stylos::core::synth
