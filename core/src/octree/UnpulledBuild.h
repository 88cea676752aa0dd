#pragma once
// Internal: the construction without its pull, for buildOctree(), which pulls while it writes.
#include "stylos/core/octree/ConstructionOctree.h"
#include "stylos/core/octree/OctreeBuild.h"

#include <memory>

namespace stylos::core::octree {

/** @brief buildConstructionOctree() except the pull: the inner cells' normals are not computed yet. */
Result<std::unique_ptr<ConstructionOctree>> buildUnpulledConstructionOctree(const PointSourceFactory& open,
                                                                            const BuildOptions& options,
                                                                            ProgressSink* progress, BuildReport* report);

} // namespace stylos::core::octree
