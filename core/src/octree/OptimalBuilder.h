#pragma once
// Internal: the Optimal construction (one marking pass per level, exact-size tables, a leaf pass).
#include "BuildContext.h"

#include "stylos/core/octree/ConstructionOctree.h"

#include <memory>

namespace stylos::core::octree {

/**
 * @brief Root box (bounds pass unless given); then for each level l < depth a marking pass (a reader
 *        thread quantises, options.threads threads set the child bits of the level-l cells) followed by
 *        the exact-size child tables of level l + 1 (refused before allocating if they would pass the
 *        memory limit); then a leaf pass (the reader thread prepares each point and finds its leaf, this
 *        thread averages in input order); not pulled (the caller pulls). Errors: the reader's, OutOfBudget, Cancelled,
 *        InvalidArgument (no points), Malformed (the source changed between passes).
 */
Result<std::unique_ptr<ConstructionOctree>> buildOptimal(BuildContext& context, const BuildOptions& options);

} // namespace stylos::core::octree
