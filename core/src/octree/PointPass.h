#pragma once
// Internal to the octree builders: one pass over a point source, read and prepared on a reader thread.
#include "stylos/core/io/PointReader.h"
#include "stylos/core/octree/PreparedPoint.h"
#include "stylos/core/util/Result.h"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <thread>
#include <vector>

namespace stylos::core::octree {

/**
 * @brief Reads a source batch by batch on its own thread, turns each batch into PreparedPoints there
 *        (the caller's `prepare`), and hands the batches to the calling thread in input order. At most a
 *        few batches are in flight (bounded memory). Destroying the pass stops the reader thread.
 *        One consumer thread.
 */
class PointPass {
public:
    /** Fills @p out (resized by the callee) from @p batch; runs on the reader thread. */
    using Prepare = std::function<void(const io::PointBatch& batch, std::vector<PreparedPoint>& out)>;

    PointPass(std::unique_ptr<io::PointReader> reader, Prepare prepare, std::size_t batchPoints = 16384);
    ~PointPass();
    PointPass(const PointPass&) = delete;
    PointPass& operator=(const PointPass&) = delete;

    /** @brief The next batch in input order (empty once the source is exhausted), valid until the next
     *         call; or the reader's error. */
    Result<std::span<const PreparedPoint>> next();

    /** @brief Fraction of the source read so far (by declared count, else by bytes). */
    double fraction() const { return m_fraction.load(std::memory_order_relaxed); }
    /** @brief Points the reader has delivered so far. */
    std::uint64_t pointsRead() const { return m_pointsRead.load(std::memory_order_relaxed); }
    /** @brief Non-finite points the reader has dropped so far. */
    std::uint64_t pointsSkipped() const { return m_pointsSkipped.load(std::memory_order_relaxed); }

private:
    struct Slot {
        io::PointBatch raw;
        std::vector<PreparedPoint> prepared;
    };
    void produce();

    std::unique_ptr<io::PointReader> m_reader;
    Prepare m_prepare;
    std::size_t m_batchPoints;
    std::vector<Slot> m_slots;
    std::deque<std::size_t> m_free;
    std::deque<std::size_t> m_full;
    std::optional<std::size_t> m_current;   ///< slot the consumer holds
    std::optional<Error> m_error;
    bool m_end = false;
    bool m_stop = false;
    std::mutex m_mutex;
    std::condition_variable m_changed;
    std::atomic<double> m_fraction{0};
    std::atomic<std::uint64_t> m_pointsRead{0};
    std::atomic<std::uint64_t> m_pointsSkipped{0};
    std::thread m_thread;
};

} // namespace stylos::core::octree
