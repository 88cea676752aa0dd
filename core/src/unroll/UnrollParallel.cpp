#include "UnrollParallel.h"

#include "../shading/ParallelChunks.h"

#include <atomic>

namespace stylos::core::unroll::detail {

bool parallelPoints(std::size_t count, unsigned threads, ProgressSink* progress,
                    const std::function<void(std::size_t, std::size_t, unsigned)>& body)
{
    const std::size_t chunks = (count + kPointChunk - 1) / kPointChunk;
    std::atomic<std::size_t> done{0};
    const bool finished = shading::detail::parallelChunks(
        count, kPointChunk, threads, progress, [&](std::size_t begin, std::size_t end, unsigned worker) {
            body(begin, end, worker);
            const std::size_t d = done.fetch_add(1, std::memory_order_relaxed) + 1;
            if (progress && (d % 16 == 0 || d == chunks)) progress->update(double(d) / double(chunks));
        });
    return finished && !(progress && progress->isCancelRequested());
}

} // namespace stylos::core::unroll::detail
