#pragma once
// Internal to the octree builders: a fixed set of threads that run one job at a time together.
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace stylos::core::octree {

/**
 * @brief `threads` workers, the calling thread being worker 0: run(fn) calls fn(i) for every
 *        i in [0, threads) at once and returns when all have returned. Not reentrant; one caller.
 */
class WorkerPool {
public:
    explicit WorkerPool(unsigned threads);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    unsigned threads() const { return unsigned(m_workers.size()) + 1; }
    /** @brief Runs @p job on every worker (the caller as worker 0) and waits for all of them. */
    void run(const std::function<void(unsigned)>& job);

private:
    void loop(unsigned index);

    std::vector<std::thread> m_workers;
    std::mutex m_mutex;
    std::condition_variable m_start;
    std::condition_variable m_done;
    const std::function<void(unsigned)>* m_job = nullptr;
    std::uint64_t m_generation = 0;
    unsigned m_running = 0;
    bool m_stop = false;
};

} // namespace stylos::core::octree
