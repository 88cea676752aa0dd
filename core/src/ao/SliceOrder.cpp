#include "SliceOrder.h"

#include <cassert>
#include <limits>
#include <map>
#include <mutex>

namespace stylos::core::ao::detail {

namespace {

const std::vector<float>& coordinate(const PreparedCells& cells, int axis)
{
    return axis == 0 ? cells.x : axis == 1 ? cells.y : cells.z;
}

/** Stable counting sort of @p in by the integer coordinate on @p axis into @p out; fills @p begin. */
void countingSort(const PreparedCells& cells, int axis, const std::vector<std::uint32_t>& in,
                  std::vector<std::uint32_t>& out, std::vector<std::uint32_t>& begin)
{
    const std::vector<float>& c = coordinate(cells, axis);
    begin.assign(std::size_t(cells.extent[std::size_t(axis)]) + 1, 0);
    for (const std::uint32_t i : in) ++begin[std::size_t(c[i]) + 1];
    for (std::size_t k = 1; k < begin.size(); ++k) begin[k] += begin[k - 1];
    std::vector<std::uint32_t> next(begin.begin(), begin.end() - 1);
    out.resize(in.size());
    for (const std::uint32_t i : in) out[next[std::size_t(c[i])]++] = i;
}

} // namespace

SliceOrder buildSliceOrder(const PreparedCells& cells)
{
    assert(cells.size() <= std::numeric_limits<std::uint32_t>::max() && "buildSliceOrder(): too many cells");
    SliceOrder order;
    std::vector<std::uint32_t> identity(cells.size()), scratch, unused;
    for (std::size_t i = 0; i < identity.size(); ++i) identity[i] = std::uint32_t(i);
    for (int m = 0; m < 3; ++m) {
        const int a = (m + 1) % 3, b = (m + 2) % 3;
        // Least significant key first: a, then b, then the slice coordinate m (each pass stable).
        countingSort(cells, a, identity, scratch, unused);
        std::vector<std::uint32_t> byB;
        countingSort(cells, b, scratch, byB, unused);
        countingSort(cells, m, byB, order.cells[std::size_t(m)], order.sliceBegin[std::size_t(m)]);
    }
    return order;
}

std::shared_ptr<const SliceOrder> sharedSliceOrder(const PreparedCells& cells)
{
    static std::mutex mutex;
    static std::map<const PreparedCells*, std::weak_ptr<const SliceOrder>> cache;
    const std::lock_guard lock(mutex);
    for (auto it = cache.begin(); it != cache.end();)
        it = it->second.expired() ? cache.erase(it) : std::next(it);
    auto& slot = cache[&cells];
    if (auto order = slot.lock()) return order;
    auto order = std::make_shared<const SliceOrder>(buildSliceOrder(cells));
    slot = order;
    return order;
}

} // namespace stylos::core::ao::detail
