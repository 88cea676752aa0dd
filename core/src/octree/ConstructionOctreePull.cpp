// The pull (every inner cell's normal from its children) on several threads, subtree by subtree, optionally
// handing the pulled cells to a sink level by level on the way (the writer's input, without a walk of its own).
#include "stylos/core/octree/ConstructionOctree.h"

#include "SubtreeCells.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>

namespace stylos::core::octree {

void ConstructionOctree::pullAndVisitLevels(unsigned threads,
                                            const std::function<void(int level, const CellBlock&)>* sink)
{
    // Subtrees below a split level are independent: threads take them one at a time. The levels above
    // are then pulled on this thread with the subtrees' weights. The split is the first level from 4 on
    // with a thousand cells or more: enough subtrees to share out, and small ones to hold when handed out.
    const int depth = m_description.depth;
    PulledSubtrees pulled;
    pulled.level = std::min(depth, 4);
    while (pulled.level < depth && m_description.cellsPerLevel[std::size_t(pulled.level)] < 1024) ++pulled.level;
    const std::vector<std::uint32_t> subtrees = cellIndices(pulled.level);
    pulled.weights.resize(subtrees.size());
    const bool colour = m_arena.cellBytes() == CellArena::ColourCellBytes;
    threads = std::max(threads, 1u);

    // With a sink, each subtree's cells are gathered while it is pulled and handed out in subtree order by
    // one thread at a time (whichever finds the next one ready); a thread may run at most `window`
    // subtrees ahead of the last handed out, which bounds the memory held.
    std::mutex mutex;
    std::condition_variable changed;
    std::size_t nextTake = 0, nextEmit = 0;
    bool emitting = false;
    std::vector<std::unique_ptr<SubtreeCells>> done(sink ? subtrees.size() : 0);
    std::vector<std::unique_ptr<SubtreeCells>> spare;
    const std::size_t window = 8 * std::size_t(threads);
    auto emit = [&](const SubtreeCells& cells) {
        for (int l = cells.top; l <= depth; ++l) {
            const auto& normals = cells.normals[std::size_t(l - cells.top)];
            if (normals.empty()) continue;
            const bool leaf = l == depth;
            (*sink)(l, CellBlock{leaf ? std::span<const std::uint8_t>() : std::span<const std::uint8_t>(cells.masks[std::size_t(l - cells.top)]),
                                 std::span<const std::uint16_t>(normals),
                                 leaf && colour ? std::span<const std::uint8_t>(cells.colours) : std::span<const std::uint8_t>()});
        }
    };
    // Hands out every finished subtree that is next in order; called with the lock held.
    auto emitReady = [&](std::unique_lock<std::mutex>& lock) {
        if (emitting) return;  // the thread handing out will find it
        emitting = true;
        while (nextEmit < done.size() && done[nextEmit]) {
            std::unique_ptr<SubtreeCells> ready = std::move(done[nextEmit]);
            lock.unlock();
            emit(*ready);
            lock.lock();
            spare.push_back(std::move(ready));
            ++nextEmit;
            changed.notify_all();
        }
        emitting = false;
    };
    auto work = [&] {
        std::unique_ptr<SubtreeCells> cells;
        for (;;) {
            std::size_t i;
            {
                std::unique_lock lock(mutex);
                if (sink)
                    changed.wait(lock, [&] { return nextTake >= subtrees.size() || nextTake < nextEmit + window; });
                if (nextTake >= subtrees.size()) return;
                i = nextTake++;
                if (sink && !cells) {
                    if (spare.empty()) {
                        cells = std::make_unique<SubtreeCells>();
                    } else {
                        cells = std::move(spare.back());
                        spare.pop_back();
                    }
                }
            }
            if (cells) cells->reset(pulled.level, depth, colour);
            pullTable(subtrees[i], 1, pulled.level, nullptr, &pulled.weights[i], cells.get());
            if (!sink) continue;
            std::unique_lock lock(mutex);
            done[i] = std::move(cells);
            emitReady(lock);
        }
    };
    std::vector<std::thread> helpers;
    for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(work);
    work();
    for (std::thread& t : helpers) t.join();
    std::uint64_t total = 0;
    pullTable(m_root, 1, 0, &pulled, &total);
    if (!sink) return;
    {
        std::unique_lock lock(mutex);
        emitReady(lock);
    }
    // The levels above the subtrees: a few thousand cells at most.
    for (int l = 0; l < pulled.level; ++l) visitLevel(l, [&](const CellBlock& block) { (*sink)(l, block); });
}

} // namespace stylos::core::octree
