#pragma once
// Internal to the surface fit: a deterministic parallel loop over fixed chunks, and progress by stage.
#include "stylos/core/util/Progress.h"

#include <atomic>
#include <cstddef>
#include <functional>

namespace stylos::core::unroll::detail {

/** @p requested worker threads, or std::thread::hardware_concurrency() when 0 (at least 1). */
unsigned fitThreads(unsigned requested);

/** @brief One stage of the fit as the sub-range [from, to] of the caller's progress (the sink may be null). */
struct FitStage {
    ProgressSink* sink = nullptr;
    double from = 0.0;
    double to = 1.0;

    bool cancelled() const { return sink && sink->isCancelRequested(); }
    void update(double fraction) const
    {
        if (sink) sink->update(from + fraction * (to - from));
    }
    /** The sub-stage [a, b] (fractions of this stage). */
    FitStage part(double a, double b) const { return {sink, from + a * (to - from), from + b * (to - from)}; }
};

/** @brief Forwards only increases of the fraction to @p parent (stages re-run passes), thread-safe. */
class FitMonotonicSink final : public ProgressSink {
  public:
    explicit FitMonotonicSink(ProgressSink* parent) : m_parent(parent) {}
    void update(double fraction) override
    {
        double seen = m_high.load(std::memory_order_relaxed);
        while (fraction > seen)
            if (m_high.compare_exchange_weak(seen, fraction)) {
                m_parent->update(fraction);
                return;
            }
    }
    bool isCancelRequested() const override { return m_parent->isCancelRequested(); }

  private:
    ProgressSink* m_parent;
    std::atomic<double> m_high{0.0};
};

/**
 * @brief Calls body(k, begin, end, worker) for every chunk k of [0, count): chunk k is
 *        [k·chunk, min(count, (k+1)·chunk)). The chunks are fixed by @p count and @p chunk alone, so
 *        per-chunk results reduced in chunk order do not depend on the thread count. Chunks are handed
 *        out to @p threads workers (the caller is worker 0 and the only one that reports progress);
 *        cancel is checked before every chunk.
 * @return false when cancelled (some chunks may not have run: discard the results).
 */
bool forEachChunk(std::size_t count, std::size_t chunk, unsigned threads, const FitStage& stage,
                  const std::function<void(std::size_t, std::size_t, std::size_t, unsigned)>& body);

/** Chunks of forEachChunk() for @p count items. */
inline std::size_t chunkCount(std::size_t count, std::size_t chunk)
{
    return (count + chunk - 1) / chunk;
}

} // namespace stylos::core::unroll::detail
