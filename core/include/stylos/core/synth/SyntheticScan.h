#pragma once
/** @file
 * @brief Synthetic scans with known truth, for tests, the demo scene and benchmarks: a fluted column
 *        drum, an ovoid omphalos with a raised net, and a fragment of a drum with fracture faces.
 *        Each is sampled as several overlapping "scans" with small registration offsets and sensor noise,
 *        placed in a random pose in a museum frame, written as a binary PLY (streamed, never the whole
 *        cloud in memory) with a JSON sidecar holding the ground truth. Units: metres, radians.
 */
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string_view>

namespace stylos::core::synth {

enum class SyntheticKind { Drum, Omphalos, Fragment };

/** "drum", "omphalos", "fragment" → kind; anything else → nullopt. */
std::optional<SyntheticKind> syntheticKindFromName(std::string_view name);

struct SyntheticOptions {
    /** Metres between neighbouring samples of one scan. The default drum (both bed faces, 3 scans of
     *  ±70°) gives about 16.8 M points at 0.5 mm, 4.2 M at 1 mm; the omphalos 15.4 M, the fragment
     *  2.1 M at 0.5 mm. Points scale as 1/spacing²; over about 2e9 is refused (InvalidArgument). */
    double spacing = 0.002;
    std::uint64_t seed = 1;        ///< same seed, same file, byte for byte
    /** The seed of the drum's design (flute phase, broken region, fracture noise) when it differs from
     *  the scan's: a drum and a fragment with the same design seed come from the same drum, scanned with
     *  different noise, registration and pose (the fragment's sector then comes from @p seed). */
    std::optional<std::uint64_t> designSeed;
    int scans = 3;                 ///< overlapping scans, each with its own small registration offset
    double noise = 0.00033;        ///< sensor noise σ in metres, along the line of sight
    bool writeNormals = false;     ///< also write the true surface normals (real scans have none)
    /** Each scan sees the points whose azimuth about the object's vertical axis lies within ± this of
     *  its viewing azimuth (radians, default 70°); scans are evenly spread, so 3 scans overlap. */
    double scanHalfAngle = 1.2217304763960306;
    // The drum's shape; the fragment is cut from such a drum; the omphalos ignores them.
    double radius = 0.55;          ///< drum radius to the fillets, metres
    double height = 0.5;           ///< drum height between the bed faces, metres
    int grooves = 48;              ///< flutes (grooves); 0: a plain cylinder
    double grooveDepth = 0.008;    ///< from the fillet circle to the bottom of a flute, metres
    /** How much smaller the radius is at the upper bed than at the lower one, metres (a column's taper;
     *  0: a cylinder). The whole cross-section, flutes included, scales with the height. */
    double taper = 0.0;
};

struct SyntheticReport {
    std::uint64_t points = 0;
    std::filesystem::path truthPath; ///< the JSON sidecar: OUT with extension ".truth.json"
};

/** Sidecar path for an output file: "drum.ply" → "drum.truth.json". */
std::filesystem::path truthPathFor(const std::filesystem::path& output);

/**
 * @brief Generates a scan of @p kind into @p output (binary little-endian PLY: x y z as double, nx ny nz
 *        as float with writeNormals, scan_id as uchar) and its truth sidecar (truthPathFor(output)),
 *        both written atomically, streaming in batches of 64 Ki points (memory stays flat). The same
 *        options give the same bytes. @p progress is updated and polled for cancel every row of samples
 *        (a few thousand points). Errors: InvalidArgument (spacing ≤ 0, non-finite or so small the
 *        object would exceed ~2e9 points; noise < 0; scans outside 1..255; scanHalfAngle outside
 *        (0, π]; a drum whose flutes cannot be concave arcs), WriteFailed, Cancelled (no file is left).
 *        Thread-safe: calls share no state.
 */
class SyntheticObject;

/** @brief The object generateScan() samples for @p kind and @p options (same design, same fragment
 *         sector and noise), e.g. to compare a method with the exact solid (AnalyticSkydome.h). Does
 *         not validate the options (generateScan does). */
std::unique_ptr<SyntheticObject> makeSyntheticObject(SyntheticKind kind, const SyntheticOptions& options);
/** @brief The pose (object frame → output frame) generateScan() gives the scan of @p options. */
Eigen::Affine3d syntheticPose(const SyntheticOptions& options);

Result<SyntheticReport> generateScan(SyntheticKind kind, const SyntheticOptions& options,
                                     const std::filesystem::path& output, ProgressSink* progress = nullptr);

} // namespace stylos::core::synth
