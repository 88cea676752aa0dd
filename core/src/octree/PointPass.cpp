#include "PointPass.h"

#include <algorithm>

namespace stylos::core::octree {

namespace {
constexpr std::size_t slotCount = 4;
}

PointPass::PointPass(std::unique_ptr<io::PointReader> reader, Prepare prepare, std::size_t batchPoints)
    : m_reader(std::move(reader)), m_prepare(std::move(prepare)), m_batchPoints(batchPoints), m_slots(slotCount)
{
    for (std::size_t i = 0; i < slotCount; ++i) m_free.push_back(i);
    m_thread = std::thread([this] { produce(); });
}

PointPass::~PointPass()
{
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_changed.notify_all();
    m_thread.join();
}

void PointPass::produce()
{
    const io::PointReader& r = *m_reader;
    const std::optional<std::uint64_t> declared = r.header().declaredPoints;
    for (;;) {
        std::size_t slot;
        {
            std::unique_lock lock(m_mutex);
            m_changed.wait(lock, [this] { return m_stop || !m_free.empty(); });
            if (m_stop) return;
            slot = m_free.front();
            m_free.pop_front();
        }
        Slot& s = m_slots[slot];
        Result<std::size_t> n = m_reader->read(s.raw, m_batchPoints);
        if (n.ok() && *n > 0) m_prepare(s.raw, s.prepared);
        m_pointsRead.store(r.pointsRead(), std::memory_order_relaxed);
        m_pointsSkipped.store(r.pointsSkipped(), std::memory_order_relaxed);
        double f = declared && *declared > 0 ? double(r.pointsRead()) / double(*declared)
                   : r.fileBytes() > 0      ? double(r.bytesConsumed()) / double(r.fileBytes())
                                            : 0.0;
        m_fraction.store(std::clamp(f, 0.0, 1.0), std::memory_order_relaxed);
        {
            std::lock_guard lock(m_mutex);
            if (!n.ok()) {
                m_error = n.error();
                m_end = true;
            } else if (*n == 0) {
                m_end = true;
            } else {
                m_full.push_back(slot);
            }
        }
        m_changed.notify_all();
        if (!n.ok() || *n == 0) return;
    }
}

Result<std::span<const PreparedPoint>> PointPass::next()
{
    std::unique_lock lock(m_mutex);
    if (m_current) {
        m_free.push_back(*m_current);
        m_current.reset();
        m_changed.notify_all();
    }
    m_changed.wait(lock, [this] { return !m_full.empty() || m_end; });
    if (!m_full.empty()) {
        m_current = m_full.front();
        m_full.pop_front();
        return std::span<const PreparedPoint>(m_slots[*m_current].prepared);
    }
    if (m_error) return *m_error;
    return std::span<const PreparedPoint>();
}

} // namespace stylos::core::octree
