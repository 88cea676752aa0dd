#pragma once
/** @file
 * @brief Internal to the view cut: the priority queue of candidate cells, a flat 4-ary heap of 32-byte
 *        entries laid out so that the four children of a node share two cache lines (one sift-down
 *        touches about half the cache lines of a binary heap of the same size).
 *
 * Order (a total order, so the cut is deterministic): larger `priority` first, then smaller
 * `distance2`, then smaller `tag` (level, then index). Not thread-safe (one per cut).
 */
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

namespace stylos::core::octree {

/** A cell waiting to be refined. */
struct alignas(32) CutCandidate {
    double priority;        ///< projected size, pixels (infinity when the eye is inside)
    double distance2;       ///< squared distance eye–centre, m²
    std::uint64_t coords;   ///< x | y << 21 | z << 42
    std::uint64_t tag;      ///< level << 58 | index << 6 | frustum planes still to test

    static std::uint64_t packCoords(std::uint32_t x, std::uint32_t y, std::uint32_t z)
    {
        return std::uint64_t(x) | (std::uint64_t(y) << 21) | (std::uint64_t(z) << 42);
    }
    static std::uint64_t packTag(int level, std::uint64_t index, std::uint8_t planes)
    {
        assert(index < (std::uint64_t(1) << 52) && "CutCandidate::packTag(): index too large");
        return (std::uint64_t(level) << 58) | (index << 6) | planes;
    }
    std::uint32_t x() const { return std::uint32_t(coords & 0x1FFFFF); }
    std::uint32_t y() const { return std::uint32_t((coords >> 21) & 0x1FFFFF); }
    std::uint32_t z() const { return std::uint32_t(coords >> 42); }
    int level() const { return int(tag >> 58); }
    std::uint64_t index() const { return (tag >> 6) & ((std::uint64_t(1) << 52) - 1); }
    std::uint8_t planes() const { return std::uint8_t(tag & 0x3F); }

    /** True when this comes out of the queue before @p o. */
    bool before(const CutCandidate& o) const
    {
        if (priority != o.priority) return priority > o.priority;
        if (distance2 != o.distance2) return distance2 < o.distance2;
        return tag < o.tag;
    }
};

class CutQueue {
public:
    explicit CutQueue(std::size_t capacity)
        : m_capacity(capacity < 1 ? 1 : capacity),
          m_store(static_cast<CutCandidate*>(::operator new((m_capacity + Offset) * sizeof(CutCandidate),
                                                            std::align_val_t(64)))),
          m_items(m_store + Offset)
    {
    }
    ~CutQueue() { ::operator delete(m_store, std::align_val_t(64)); }
    CutQueue(const CutQueue&) = delete;
    CutQueue& operator=(const CutQueue&) = delete;

    bool empty() const { return m_size == 0; }
    std::size_t size() const { return m_size; }
    const CutCandidate& top() const { return m_items[0]; }

    void push(const CutCandidate& c)
    {
        if (m_size == m_capacity) grow();
        std::size_t i = m_size++;
        while (i > 0) {
            const std::size_t parent = (i - 1) / 4;
            if (!c.before(m_items[parent])) break;
            m_items[i] = m_items[parent];
            i = parent;
        }
        m_items[i] = c;
    }

    /** Replaces the top by @p c (one sift-down instead of a pop and a push). */
    void replaceTop(const CutCandidate& c) { siftDown(c); }

    /** The entries, in heap order (for a pass that takes them all). */
    const CutCandidate* data() const { return m_items; }

    void clear() { m_size = 0; }

    /** Replaces the contents by @p count entries from @p items, in any order (heapified in O(count)). */
    void assign(const CutCandidate* items, std::size_t count)
    {
        while (m_capacity < count) grow();
        for (std::size_t k = 0; k < count; ++k) m_items[k] = items[k];
        m_size = count;
        if (count < 2) return;
        for (std::size_t i = (count - 2) / 4 + 1; i-- > 0;) siftDownFrom(i, m_items[i]);
    }

    void pop()
    {
        assert(m_size > 0 && "CutQueue::pop(): empty");
        --m_size;
        if (m_size > 0) siftDown(m_items[m_size]);
    }

private:
    // Element k lives at m_store[k + 3]: the children 4i+1..4i+4 then start on a 128-byte boundary.
    static constexpr std::size_t Offset = 3;

    void siftDown(const CutCandidate& c) { siftDownFrom(0, c); }

    /** Places @p item (copied first: it may live in the heap) at @p i or below. */
    void siftDownFrom(std::size_t i, const CutCandidate& item)
    {
        const CutCandidate c = item;
        for (;;) {
            const std::size_t first = 4 * i + 1;
            if (first >= m_size) break;
            const std::size_t last = first + 4 < m_size ? first + 4 : m_size;
            std::size_t best = first;
            for (std::size_t k = first + 1; k < last; ++k)
                if (m_items[k].before(m_items[best])) best = k;
            if (!m_items[best].before(c)) break;
            m_items[i] = m_items[best];
            i = best;
        }
        m_items[i] = c;
    }

    void grow()
    {
        const std::size_t capacity = 2 * m_capacity;
        auto* store = static_cast<CutCandidate*>(
            ::operator new((capacity + Offset) * sizeof(CutCandidate), std::align_val_t(64)));
        for (std::size_t k = 0; k < m_size; ++k) store[Offset + k] = m_items[k];
        ::operator delete(m_store, std::align_val_t(64));
        m_store = store;
        m_items = store + Offset;
        m_capacity = capacity;
    }

    std::size_t m_size = 0;
    std::size_t m_capacity;
    CutCandidate* m_store;
    CutCandidate* m_items;
};

} // namespace stylos::core::octree
