#pragma once
/** @file
 * @brief Exports one point per leaf of a `.poct` as LAS 1.4, point data format 6 (what CloudCompare, PDAL and
 *        GIS tools read): the leaf centre as X, Y, Z (0.1 mm steps, offset at the octree's root corner), return 1
 *        of 1, and the layers asked for:
 *        - "material" → the classification byte: 64 + the class id (ids 1..191; LAS reserves 0–63 for the ASPRS
 *          classes, so user classes start at 64), 0 ("created, never classified") where unlabelled; a
 *          Classification Lookup VLR (LASF_Spec, record 0) names each class of the legend (15 characters);
 *        - "toolmark" → an extra byte (unsigned char, the class id; Extra Bytes VLR, LASF_Spec record 4);
 *        - "ambient" → an extra float (the 3D skydome's fraction of the sky).
 *        The legend also goes whole into a "Stylos" VLR (record 1, the JSON of annotation/Legend.h), so the class
 *        names and colours travel with the points.
 *
 * No time stamp: the creation day and year are 0, so the same octree gives the same bytes. Written to a
 * temporary file beside the target and renamed at the end. Failure modes: exportLeafPly's (unknown or repeated
 * layer, "ambient" absent — naming the octree —, a wrong layer), InvalidArgument for a material id above 191,
 * WriteFailed naming the output, Cancelled. Thread-safety: reentrant.
 */
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace stylos::core::annotation {

/** The classification byte a material class id becomes in LAS (0 stays 0). */
inline constexpr int kLasClassOffset = 64;

Result<std::uint64_t> exportLeafLas(const octree::PackedOctree& octree, const std::vector<std::string>& layers,
                                    const Legend& legend, const std::filesystem::path& output,
                                    ProgressSink* progress = nullptr);

} // namespace stylos::core::annotation
