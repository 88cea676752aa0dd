#include "FitParallel.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace stylos::core::unroll::detail {

unsigned fitThreads(unsigned requested)
{
    if (requested > 0) return requested;
    return std::max(1u, std::thread::hardware_concurrency());
}

bool forEachChunk(std::size_t count, std::size_t chunk, unsigned threads, const FitStage& stage,
                  const std::function<void(std::size_t, std::size_t, std::size_t, unsigned)>& body)
{
    const std::size_t chunks = chunkCount(count, chunk);
    threads = unsigned(std::min<std::size_t>(std::max(1u, threads), std::max<std::size_t>(1, chunks)));
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> done{0};
    std::atomic<bool> cancelled{false};
    auto work = [&](unsigned worker) {
        for (;;) {
            if (cancelled.load(std::memory_order_relaxed)) return;
            if (stage.cancelled()) {
                cancelled.store(true);
                return;
            }
            const std::size_t k = next.fetch_add(1, std::memory_order_relaxed);
            if (k >= chunks) return;
            body(k, k * chunk, std::min(count, (k + 1) * chunk), worker);
            const std::size_t finished = done.fetch_add(1, std::memory_order_relaxed) + 1;
            if (worker == 0) stage.update(double(finished) / double(chunks));
        }
    };
    std::vector<std::thread> helpers;
    helpers.reserve(threads - 1);
    for (unsigned t = 1; t < threads; ++t)
        helpers.emplace_back(work, t);
    work(0);
    for (auto& helper : helpers)
        helper.join();
    return !cancelled.load();
}

} // namespace stylos::core::unroll::detail
