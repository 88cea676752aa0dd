#pragma once
// Internal: the Streaming construction (one insertion pass after the bounds scan).
#include "BuildContext.h"

#include "stylos/core/octree/ConstructionOctree.h"

#include <memory>

namespace stylos::core::octree {

/**
 * @brief Root box (bounds pass unless given), then one pass: a reader thread reads, quantises and
 *        prepares the points (unit normal, first-point code); this thread inserts them in input order
 *        (ConstructionOctree::populate); not pulled (the caller pulls). Errors: the reader's, OutOfBudget, Cancelled,
 *        InvalidArgument (no points).
 */
Result<std::unique_ptr<ConstructionOctree>> buildStreaming(BuildContext& context, const BuildOptions& options);

/** @brief Prepares every point of @p batch completely (as preparePoint does; the codes in batch). */
void prepareBatch(const RootBox& box, int depth, const NormalEncoder& encode, const io::PointBatch& batch,
                  std::vector<PreparedPoint>& out);

} // namespace stylos::core::octree
