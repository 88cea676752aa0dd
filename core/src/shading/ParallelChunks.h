#pragma once
// Internal to the shadings: a parallel loop over [0, count) in chunks, with cancel.
#include "stylos/core/util/Progress.h"

#include <cstddef>
#include <functional>

namespace stylos::core::shading::detail {

/** @p requested threads, or std::thread::hardware_concurrency() when 0 (at least 1). */
unsigned resolveThreads(unsigned requested);

/**
 * @brief Calls body(begin, end, worker) over consecutive chunks of [0, count) of @p chunk items,
 *        handed out in order to @p threads workers (the caller is worker 0; each worker index is used
 *        by one thread at a time, for per-worker scratch). Checks progress->isCancelRequested()
 *        before every chunk.
 * @return false when cancelled (some chunks may then not have run).
 */
bool parallelChunks(std::size_t count, std::size_t chunk, unsigned threads, ProgressSink* progress,
                    const std::function<void(std::size_t, std::size_t, unsigned)>& body);

} // namespace stylos::core::shading::detail
