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

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

namespace stylos::core::synth {

enum class SyntheticKind { Drum, Omphalos, Fragment };

/** "drum", "omphalos", "fragment" → kind; anything else → nullopt. */
std::optional<SyntheticKind> syntheticKindFromName(std::string_view name);

struct SyntheticOptions {
    double spacing = 0.002;        ///< metres between neighbouring samples of one scan (0.5 mm ≈ 10 M points)
    std::uint64_t seed = 1;        ///< same seed, same file, byte for byte
    int scans = 3;                 ///< overlapping scans, each with its own small registration offset
    double noise = 0.00033;        ///< sensor noise σ in metres, along the line of sight
    bool writeNormals = false;     ///< also write the true surface normals (real scans have none)
    /** Each scan sees the points whose azimuth about the object's vertical axis lies within ± this of
     *  its viewing azimuth (radians, default 70°); scans are evenly spread, so 3 scans overlap. */
    double scanHalfAngle = 1.2217304763960306;
    double radius = 0.55;          ///< drum (and the fragment's parent drum) radius to the fillets, metres
    double height = 0.5;           ///< drum height between the bed faces, metres
    int grooves = 48;              ///< flutes (grooves); 0: a plain cylinder
    double grooveDepth = 0.008;    ///< from the fillet circle to the bottom of a flute, metres
};

struct SyntheticReport {
    std::uint64_t points = 0;
    std::filesystem::path truthPath; ///< the JSON sidecar: OUT with extension ".truth.json"
};

/** Sidecar path for an output file: "drum.ply" → "drum.truth.json". */
std::filesystem::path truthPathFor(const std::filesystem::path& output);

/**
 * @brief Generates a scan of @p kind into @p output (binary PLY) and its truth sidecar, both written
 *        atomically. Errors: InvalidArgument (spacing ≤ 0 or absurd), WriteFailed, Cancelled.
 */
Result<SyntheticReport> generateScan(SyntheticKind kind, const SyntheticOptions& options,
                                     const std::filesystem::path& output, ProgressSink* progress = nullptr);

} // namespace stylos::core::synth
