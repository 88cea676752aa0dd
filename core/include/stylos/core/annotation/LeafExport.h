#pragma once
/** @file
 * @brief Exports one point per leaf of a `.poct` with per-leaf layers as properties: a binary PLY of the
 *        leaf centres (`x y z` double, metres, the octree's frame) followed by one property per requested
 *        layer, named after it — "material" and "toolmark" as uchar class ids (0 where the file has no such
 *        layer yet), "ambient" as float (the 3D skydome's layer, which must be present).
 *
 * Written atomically (PlyWriter: temporary file beside the target, renamed by finish()): on any error or
 * cancel nothing is left and an existing file is untouched. LAS 1.4: annotation/LeafLas.h.
 * Thread-safety: reentrant. Failure modes: InvalidArgument (an unknown or repeated layer name, or "ambient"
 * absent from the file — naming the octree's file), Malformed (a layer of the wrong type or size),
 * WriteFailed naming the output, Cancelled.
 */
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace stylos::core::annotation {

/** @brief The layer names exportLeafPly() knows: "material", "toolmark", "ambient". */
bool isExportableLayer(const std::string& name);

/** @brief One exported layer's values per leaf: class ids (material, toolmark) or floats (ambient). */
struct LeafColumn {
    std::string name;
    std::vector<std::uint8_t> labels;
    std::vector<float> floats;
    bool isFloat() const { return name == "ambient"; }
    double at(std::uint64_t leaf) const { return labels.empty() ? double(floats[leaf]) : double(labels[leaf]); }
};

/**
 * @brief Reads @p layers of @p octree for an export to @p output (the PLY and LAS writers alike): InvalidArgument
 *        for an unknown or repeated name (naming @p output) or "ambient" absent (naming the octree), Malformed
 *        for a layer of the wrong type or size.
 */
Result<std::vector<LeafColumn>> readLeafColumns(const octree::PackedOctree& octree, const std::vector<std::string>& layers,
                                                const std::filesystem::path& output);

/** @brief Writes the leaves of @p octree with @p layers (in that order) to @p output; returns the point count. */
Result<std::uint64_t> exportLeafPly(const octree::PackedOctree& octree, const std::vector<std::string>& layers,
                                    const std::filesystem::path& output, ProgressSink* progress = nullptr);

} // namespace stylos::core::annotation
