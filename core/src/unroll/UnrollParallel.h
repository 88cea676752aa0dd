#pragma once
// Internal to the unroller: a parallel loop over the points of a cloud, with progress and cancel.
#include "stylos/core/util/Progress.h"

#include <cstddef>
#include <functional>

namespace stylos::core::unroll::detail {

/** Points handed to a worker at a time. */
inline constexpr std::size_t kPointChunk = 32 * 1024;

/**
 * @brief Calls body(begin, end, worker) over consecutive chunks of kPointChunk indices of [0, count)
 *        on @p threads workers (worker indices 0 .. threads − 1, each used by one thread at a time,
 *        for per-worker accumulators); reports the fraction of chunks done to @p progress (may be
 *        null) and checks its cancel request before every chunk.
 * @return false when cancelled (some chunks may then not have run).
 */
bool parallelPoints(std::size_t count, unsigned threads, ProgressSink* progress,
                    const std::function<void(std::size_t, std::size_t, unsigned)>& body);

} // namespace stylos::core::unroll::detail
