#include "FitParallel.h"

#include "../shading/ParallelChunks.h"

#include <atomic>

namespace stylos::core::unroll::detail {

unsigned fitThreads(unsigned requested) { return shading::detail::resolveThreads(requested); }

bool forEachChunk(std::size_t count, std::size_t chunk, unsigned threads, const FitStage& stage,
                  const std::function<void(std::size_t, std::size_t, std::size_t, unsigned)>& body)
{
    const std::size_t chunks = chunkCount(count, chunk);
    std::atomic<std::size_t> done{0};
    // The shared loop checks cancel before every chunk; the fit adds the chunk index and reports
    // progress from the caller's thread only (worker 0).
    return shading::detail::parallelChunks(
        count, chunk, threads, stage.sink,
        [&](std::size_t begin, std::size_t end, unsigned worker) {
            body(begin / chunk, begin, end, worker);
            const std::size_t finished = done.fetch_add(1, std::memory_order_relaxed) + 1;
            if (worker == 0) stage.update(double(finished) / double(chunks));
        });
}

} // namespace stylos::core::unroll::detail
