#include "NeighbourIndex.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <system_error>
#include <thread>

namespace stylos::core::normals::detail {
namespace {

constexpr std::uint64_t kNoKey = std::numeric_limits<std::uint64_t>::max();

/** nanoflann dataset adaptor: a rank range of the float copy of the points. */
struct FloatAdaptor {
    const float* points = nullptr;
    std::size_t count = 0;

    std::size_t kdtree_get_point_count() const { return count; }
    float kdtree_get_pt(std::size_t i, std::size_t d) const { return points[3 * i + d]; }
    template <class Box> bool kdtree_get_bbox(Box&) const { return false; }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<
    nanoflann::L2_Simple_Adaptor<float, FloatAdaptor, float, std::uint32_t>, FloatAdaptor, 3, std::uint32_t>;
using KdNode = KdTree::Node;

std::uint32_t bitsOf(float value) { return std::bit_cast<std::uint32_t>(value); }

/**
 * Runs fn(0) … fn(tasks − 1), each on its own thread, fn(0) on the calling one. A thread that cannot be
 * started (std::system_error) is replaced by running its task on the calling thread. @p fn must not throw.
 */
template <class Fn> void runTasks(std::size_t tasks, const Fn& fn)
{
    std::vector<std::thread> workers;
    workers.reserve(tasks); // no allocation once threads run
    std::size_t started = 1;
    for (; started < tasks; ++started) {
        try {
            workers.emplace_back(fn, started);
        } catch (const std::system_error&) {
            break;
        }
    }
    for (std::size_t task = started; task < tasks; ++task) fn(task);
    fn(std::size_t(0));
    for (auto& worker : workers) worker.join();
}

/** Runs fn(begin, end) over [0, count) cut into up to @p threads slices. */
template <class Fn> void parallelFor(std::size_t count, unsigned threads, const Fn& fn)
{
    const std::size_t slices = std::clamp<std::size_t>(count / 32768, 1, threads);
    runTasks(slices, [&](std::size_t t) { fn(count * t / slices, count * (t + 1) / slices); });
}

/** Spreads the low 10 bits of @p v two bits apart (for a 30-bit Morton code). */
std::uint64_t spreadBits(std::uint64_t v)
{
    v &= 0x3ff;
    v = (v | (v << 16)) & 0x30000ff;
    v = (v | (v << 8)) & 0x300f00f;
    v = (v | (v << 4)) & 0x30c30c3;
    v = (v | (v << 2)) & 0x9249249;
    return v;
}

/**
 * Morton order of the points (1024 cells per axis), stable: equal cells keep their input order.
 * Returns (code << 32 | index) sorted: three LSD radix passes of 10 bits.
 */
std::vector<std::uint64_t> mortonOrder(std::span<const double> positions, unsigned threads)
{
    const std::size_t n = positions.size() / 3;
    std::array<double, 3> lo{}, hi{};
    lo.fill(std::numeric_limits<double>::max());
    hi.fill(std::numeric_limits<double>::lowest());
    for (std::size_t i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d) {
            lo[d] = std::min(lo[d], positions[3 * i + d]);
            hi[d] = std::max(hi[d], positions[3 * i + d]);
        }
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    const double scale = extent > 0 ? 1023.999 / extent : 0.0;
    std::vector<std::uint64_t> keys(n), sorted(n);
    parallelFor(n, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            std::uint64_t code = 0;
            for (int d = 0; d < 3; ++d) {
                const double cell = std::clamp((positions[3 * i + d] - lo[d]) * scale, 0.0, 1023.0);
                code |= spreadBits(static_cast<std::uint64_t>(cell)) << d;
            }
            keys[i] = (code << 32) | i;
        }
    });
    for (int shift : {32, 42, 52}) {
        std::array<std::size_t, 1024> start{};
        for (std::uint64_t key : keys) ++start[(key >> shift) & 0x3ff];
        std::size_t sum = 0;
        for (std::size_t& slot : start) {
            const std::size_t bucket = slot;
            slot = sum;
            sum += bucket;
        }
        for (std::uint64_t key : keys) sorted[start[(key >> shift) & 0x3ff]++] = key;
        keys.swap(sorted);
    }
    return keys;
}

} // namespace

float KnnScratch::squaredDistance(std::size_t q, std::size_t j) const
{
    return std::bit_cast<float>(static_cast<std::uint32_t>(keys[q * (k + 1) + 1 + j] >> 32));
}

NeighbourIndex::NeighbourIndex(std::span<const double> positions, const std::array<double, 3>& origin,
                               std::size_t leafSize, unsigned trees)
{
    const std::size_t n = positions.size() / 3;
    assert(n < std::numeric_limits<std::uint32_t>::max() && "NeighbourIndex: too many points");
    assert(leafSize >= 1 && trees >= 1 && "NeighbourIndex: leafSize and trees must be positive");
    if (n == 0) return;
    // Rank order, the double copy for the PCA and a float copy for building the trees.
    std::vector<float> search(3 * n);
    {
        const std::vector<std::uint64_t> order = mortonOrder(positions, trees);
        m_source.resize(n);
        m_local.resize(3 * n);
        parallelFor(n, trees, [&](std::size_t begin, std::size_t end) {
            for (std::size_t r = begin; r < end; ++r) {
                const auto source = static_cast<std::uint32_t>(order[r]);
                m_source[r] = source;
                for (int d = 0; d < 3; ++d) {
                    m_local[3 * r + d] = positions[3 * std::size_t(source) + d] - origin[d];
                    search[3 * r + d] = static_cast<float>(m_local[3 * r + d]);
                }
            }
        });
    }

    // One nanoflann tree per contiguous rank range (spatially compact thanks to the Morton order),
    // built in parallel, then flattened one after the other.
    const std::size_t treeCount = std::clamp<std::size_t>(std::min<std::size_t>(trees, n / 4096), 1, 64);
    std::vector<FloatAdaptor> adaptors(treeCount);
    std::vector<std::unique_ptr<KdTree>> kdTrees(treeCount);
    std::vector<std::exception_ptr> failures(treeCount);
    for (std::size_t t = 0; t < treeCount; ++t) {
        const std::size_t begin = n * t / treeCount, end = n * (t + 1) / treeCount;
        adaptors[t] = FloatAdaptor{search.data() + 3 * begin, end - begin};
    }
    auto build = [&](std::size_t t) {
        try {
            kdTrees[t] = std::make_unique<KdTree>(3, adaptors[t], nanoflann::KDTreeSingleIndexAdaptorParams(leafSize));
        } catch (...) {
            failures[t] = std::current_exception();
        }
    };
    runTasks(treeCount, build);
    for (auto& failure : failures)
        if (failure) std::rethrow_exception(failure);

    // Structure-of-arrays copy in tree order (a leaf is a contiguous range), one tree per thread.
    m_x.resize(n);
    m_y.resize(n);
    m_z.resize(n);
    m_rankAt.resize(n);
    auto copyTree = [&](std::size_t t) {
        const auto base = static_cast<std::uint32_t>(n * t / treeCount);
        for (std::size_t i = 0; i < adaptors[t].count; ++i) {
            const std::uint32_t rank = base + kdTrees[t]->vAcc[i];
            const std::size_t position = base + i;
            m_rankAt[position] = rank;
            m_x[position] = search[3 * std::size_t(rank)];
            m_y[position] = search[3 * std::size_t(rank) + 1];
            m_z[position] = search[3 * std::size_t(rank) + 2];
        }
    };
    runTasks(treeCount, copyTree);
    for (std::size_t t = 0; t < treeCount; ++t) {
        flatten(kdTrees[t].get(), static_cast<std::uint32_t>(n * t / treeCount), static_cast<std::uint32_t>(t));
        kdTrees[t].reset();
    }
}

NeighbourIndex::~NeighbourIndex() = default;

void NeighbourIndex::flatten(const void* nanoflannTree, std::uint32_t base, std::uint32_t tree)
{
    const auto& kd = *static_cast<const KdTree*>(nanoflannTree);
    TreeRoot root{static_cast<std::uint32_t>(m_nodes.size()), base, {}};
    for (int d = 0; d < 3; ++d) {
        root.box.lo[d] = kd.root_bbox[d].low;
        root.box.hi[d] = kd.root_bbox[d].high;
    }
    m_roots.push_back(root);
    // Depth-first, child1 right after its parent; child2's index patched in when it is reached.
    std::vector<std::pair<const KdNode*, std::uint32_t>> stack{{kd.root_node, ~0u}};
    while (!stack.empty()) {
        const auto [node, parent] = stack.back();
        stack.pop_back();
        const auto index = static_cast<std::uint32_t>(m_nodes.size());
        if (parent != ~0u) m_nodes[parent].payload = index;
        if (!node->child1 && !node->child2) {
            Leaf leaf{base + static_cast<std::uint32_t>(node->node_type.lr.left),
                      base + static_cast<std::uint32_t>(node->node_type.lr.right), tree};
            LeafBox box{};
            box.lo = box.hi = {m_x[leaf.begin], m_y[leaf.begin], m_z[leaf.begin]};
            for (std::uint32_t p = leaf.begin; p < leaf.end; ++p) {
                const float c[3] = {m_x[p], m_y[p], m_z[p]};
                for (int d = 0; d < 3; ++d) {
                    box.lo[d] = std::min(box.lo[d], c[d]);
                    box.hi[d] = std::max(box.hi[d], c[d]);
                }
            }
            m_nodes.push_back(Node{0, 0, 3, static_cast<std::uint32_t>(m_leaves.size())});
            m_leaves.push_back(leaf);
            m_leafBoxes.push_back(box);
        } else {
            m_nodes.push_back(Node{node->node_type.sub.divlow, node->node_type.sub.divhigh,
                                   static_cast<std::uint32_t>(node->node_type.sub.divfeat), 0});
            stack.emplace_back(node->child2, index); // patched when popped
            stack.emplace_back(node->child1, ~0u);   // popped next: lands at index + 1
        }
    }
}

void NeighbourIndex::search(std::span<const std::uint32_t> queries, std::size_t k, KnnScratch& s) const
{
    const std::size_t m = queries.size();
    s.k = k;
    s.queries = m;
    s.keys.assign(m * (k + 1), 0); // the zero before each row stops the insertion loop
    s.counts.assign(m, 0);
    s.worst.assign(m, kNoKey);
    s.worstDistance.assign(m, std::numeric_limits<float>::infinity());
    s.reach.resize(m);
    s.qx.resize(m);
    s.qy.resize(m);
    s.qz.resize(m);
    s.maxWorstBits = std::numeric_limits<std::uint32_t>::max();
    if (m == 0 || k == 0 || m_roots.empty()) return;

    std::array<float, 3> lo{}, hi{};
    lo.fill(std::numeric_limits<float>::max());
    hi.fill(std::numeric_limits<float>::lowest());
    for (std::size_t q = 0; q < m; ++q) {
        const std::uint32_t p = queries[q];
        s.qx[q] = m_x[p];
        s.qy[q] = m_y[p];
        s.qz[q] = m_z[p];
        const float c[3] = {m_x[p], m_y[p], m_z[p]};
        for (int d = 0; d < 3; ++d) {
            lo[d] = std::min(lo[d], c[d]);
            hi[d] = std::max(hi[d], c[d]);
        }
    }
    // The queries' own tree first: it holds most neighbours and tightens the bounds for the others.
    std::size_t own = 0;
    while (own + 1 < m_roots.size() && m_roots[own + 1].begin <= queries[0]) ++own;
    for (std::size_t i = 0; i < m_roots.size(); ++i) {
        const TreeRoot& root = m_roots[i == 0 ? own : (i <= own ? i - 1 : i)];
        std::array<float, 3> gaps{};
        for (int d = 0; d < 3; ++d) gaps[d] = std::max({0.0f, root.box.lo[d] - hi[d], lo[d] - root.box.hi[d]});
        const float reach = gaps[0] * gaps[0] + gaps[1] * gaps[1] + gaps[2] * gaps[2];
        if (bitsOf(reach) <= s.maxWorstBits) descend(root.node, gaps, lo, hi, s);
    }
}

void NeighbourIndex::descend(std::uint32_t index, std::array<float, 3>& gaps, const std::array<float, 3>& lo,
                             const std::array<float, 3>& hi, KnnScratch& s) const
{
    const Node& node = m_nodes[index];
    if (node.axis == 3) {
        visitLeaf(node.payload, s);
        return;
    }
    const std::uint32_t axis = node.axis;
    // Child1 holds coordinates ≤ divLow, child2 coordinates ≥ divHigh (both actual point coordinates).
    const float gap1 = std::max(gaps[axis], lo[axis] - node.divLow);
    const float gap2 = std::max(gaps[axis], node.divHigh - hi[axis]);
    bool firstIsChild1 = gap1 < gap2;
    if (gap1 == gap2) firstIsChild1 = (lo[axis] + hi[axis]) < (node.divLow + node.divHigh);
    const std::uint32_t children[2] = {firstIsChild1 ? index + 1 : node.payload,
                                       firstIsChild1 ? node.payload : index + 1};
    const float childGaps[2] = {firstIsChild1 ? gap1 : gap2, firstIsChild1 ? gap2 : gap1};
    const float saved = gaps[axis];
    for (int c = 0; c < 2; ++c) {
        gaps[axis] = childGaps[c];
        // Same float operations as the point distances, so the bound never exceeds a true distance.
        const float reach = gaps[0] * gaps[0] + gaps[1] * gaps[1] + gaps[2] * gaps[2];
        if (bitsOf(reach) <= s.maxWorstBits) descend(children[c], gaps, lo, hi, s);
    }
    gaps[axis] = saved;
}

void NeighbourIndex::visitLeaf(std::uint32_t leafIndex, KnnScratch& s) const
{
    constexpr std::uint32_t kChunk = 32;
    float distances[kChunk];
    const Leaf& leaf = m_leaves[leafIndex];
    const LeafBox& box = m_leafBoxes[leafIndex];
    const std::size_t k = s.k, m = s.queries;
    // Distance from each query to the leaf's box (vectorised over the queries).
    for (std::size_t q = 0; q < m; ++q) {
        const float gx = std::max(std::max(0.0f, box.lo[0] - s.qx[q]), s.qx[q] - box.hi[0]);
        const float gy = std::max(std::max(0.0f, box.lo[1] - s.qy[q]), s.qy[q] - box.hi[1]);
        const float gz = std::max(std::max(0.0f, box.lo[2] - s.qz[q]), s.qz[q] - box.hi[2]);
        s.reach[q] = gx * gx + gy * gy + gz * gz;
    }
    for (std::size_t q = 0; q < m; ++q) {
        float worstDistance = s.worstDistance[q];
        if (s.reach[q] > worstDistance) continue; // the whole leaf is too far for this query
        const float qx = s.qx[q], qy = s.qy[q], qz = s.qz[q];
        std::uint64_t* keys = &s.keys[q * (k + 1) + 1];
        std::uint32_t count = s.counts[q];
        std::uint64_t worst = s.worst[q];
        for (std::uint32_t chunk = leaf.begin; chunk < leaf.end; chunk += kChunk) {
            const std::uint32_t chunkEnd = std::min(leaf.end, chunk + kChunk);
            for (std::uint32_t j = chunk; j < chunkEnd; ++j) { // vectorised
                const float dx = qx - m_x[j], dy = qy - m_y[j], dz = qz - m_z[j];
                distances[j - chunk] = dx * dx + dy * dy + dz * dz;
            }
            for (std::uint32_t j = chunk; j < chunkEnd; ++j) {
                const float distance = distances[j - chunk];
                if (distance > worstDistance) continue;
                const std::uint64_t key = (std::uint64_t(bitsOf(distance)) << 32) | m_rankAt[j];
                if (key >= worst) continue; // a tie at the k-th distance, lost on rank
                // Insertion into the sorted row; keys[-1] == 0 is below every key, so no bound check.
                std::uint64_t* slot = keys + (count < k ? count++ : k - 1);
                while (slot[-1] > key) {
                    *slot = slot[-1];
                    --slot;
                }
                *slot = key;
                if (count == k) {
                    worst = keys[k - 1];
                    worstDistance = std::bit_cast<float>(static_cast<std::uint32_t>(worst >> 32));
                }
            }
        }
        s.counts[q] = count;
        s.worst[q] = worst;
        s.worstDistance[q] = worstDistance;
    }
    std::uint32_t maxWorst = 0;
    for (std::size_t q = 0; q < m; ++q) maxWorst = std::max(maxWorst, static_cast<std::uint32_t>(s.worst[q] >> 32));
    s.maxWorstBits = maxWorst;
}

} // namespace stylos::core::normals::detail
