#pragma once
/** @file
 * @brief Simulates a terrestrial scanning campaign of a synthetic object: several scans from evenly
 *        spread azimuths, each sampling the surface it sees (azimuth within ± the half angle of its
 *        viewing direction) on its own jittered grid at the requested spacing, with Gaussian noise
 *        along the line of sight (clamped at 5 σ) and its own small registration error (rotation about
 *        the scan centre ≤ 0.05°, translation ≤ 0.3 mm); every point is then carried by the pose into
 *        the output frame and streamed to a PLY writer in batches, so memory stays flat.
 *        Deterministic for a seed. Units: metres, radians. Not thread-safe.
 */
#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/synth/SyntheticObject.h"
#include "stylos/core/synth/SyntheticScan.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <nlohmann/json_fwd.hpp>

#include <Eigen/Geometry>

#include <cstdint>
#include <numbers>
#include <vector>

namespace stylos::core::synth {

/** @brief One scan's station and registration error. */
struct ScanStation {
    double viewAzimuth = 0.0;           ///< radians, about the object's vertical scan axis
    Eigen::Vector3d scanner;            ///< scanner position, object frame, metres
    Eigen::Vector3d registrationAxis;   ///< unit axis of the registration rotation
    double registrationAngle = 0.0;     ///< radians
    Eigen::Vector3d registrationShift;  ///< metres
    Eigen::Affine3d toOutput;           ///< object frame → output frame, registration error included
};

class ScanSimulator {
public:
    static constexpr double kMaxRegistrationAngle = 0.05 * std::numbers::pi / 180.0; ///< radians
    static constexpr double kMaxRegistrationShift = 0.0003;   ///< metres
    static constexpr double kNoiseClamp = 5.0;                ///< noise clamped at this many σ
    static constexpr std::size_t kBatchPoints = 64 * 1024;

    /** @p pose maps the object frame to the output frame; @p seed drives every random choice. */
    ScanSimulator(const SyntheticObject& object, const SyntheticOptions& options, const Eigen::Affine3d& pose,
                  std::uint64_t seed);

    /** Expected number of points (from the patches' areas), for validation and progress. */
    double estimatePoints() const;
    /** Largest displacement a registration error causes anywhere on the object, metres. */
    double registrationBound() const;
    const std::vector<ScanStation>& stations() const { return m_stations; }

    /** Writes every scan's points to @p writer; returns the number written. Errors: WriteFailed
     *  (from the writer), Cancelled (checked every row of samples and every batch). */
    Result<std::uint64_t> run(io::PlyWriter& writer, ProgressSink* progress);

    /** The stations as JSON (output frame), for the truth sidecar. */
    nlohmann::json stationsTruth() const;

private:
    struct Sampler;
    Status samplePatch(const SurfacePatch& patch, int scan, Sampler& sampler) const;

    const SyntheticObject& m_object;
    SyntheticOptions m_options;
    Eigen::Affine3d m_pose;
    std::uint64_t m_seed;
    std::vector<ScanStation> m_stations;
};

} // namespace stylos::core::synth
