#include "WorkerPool.h"

#include <algorithm>

namespace stylos::core::octree {

WorkerPool::WorkerPool(unsigned threads)
{
    for (unsigned i = 1; i < std::max(threads, 1u); ++i) m_workers.emplace_back([this, i] { loop(i); });
}

WorkerPool::~WorkerPool()
{
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_start.notify_all();
    for (std::thread& t : m_workers) t.join();
}

void WorkerPool::run(const std::function<void(unsigned)>& job)
{
    if (m_workers.empty()) {
        job(0);
        return;
    }
    {
        std::lock_guard lock(m_mutex);
        m_job = &job;
        m_running = unsigned(m_workers.size());
        ++m_generation;
    }
    m_start.notify_all();
    job(0);
    std::unique_lock lock(m_mutex);
    m_done.wait(lock, [this] { return m_running == 0; });
    m_job = nullptr;
}

void WorkerPool::loop(unsigned index)
{
    std::uint64_t seen = 0;
    for (;;) {
        const std::function<void(unsigned)>* job;
        {
            std::unique_lock lock(m_mutex);
            m_start.wait(lock, [&] { return m_stop || m_generation != seen; });
            if (m_stop) return;
            seen = m_generation;
            job = m_job;
        }
        (*job)(index);
        {
            std::lock_guard lock(m_mutex);
            if (--m_running == 0) m_done.notify_one();
        }
    }
}

} // namespace stylos::core::octree
