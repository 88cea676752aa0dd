#include "NeighbourIndex.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <exception>
#include <limits>
#include <thread>

namespace stylos::core::normals::detail {
namespace {

constexpr std::uint64_t kNoKey = std::numeric_limits<std::uint64_t>::max();

/** nanoflann dataset adaptor: a rank range of the double local copy, seen as float. */
struct FloatAdaptor {
    const double* local = nullptr;
    std::size_t count = 0;

    std::size_t kdtree_get_point_count() const { return count; }
    float kdtree_get_pt(std::size_t i, std::size_t d) const { return static_cast<float>(local[3 * i + d]); }
    template <class Box> bool kdtree_get_bbox(Box&) const { return false; }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<
    nanoflann::L2_Simple_Adaptor<float, FloatAdaptor, float, std::uint32_t>, FloatAdaptor, 3, std::uint32_t>;
using KdNode = KdTree::Node;

std::uint32_t bitsOf(float value) { return std::bit_cast<std::uint32_t>(value); }

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
 * Returns rank → index. Two LSD radix passes of 15 bits over (code << 32 | index).
 */
std::vector<std::uint32_t> mortonOrder(std::span<const double> positions, const std::array<double, 3>& origin)
{
    const std::size_t n = positions.size() / 3;
    std::array<double, 3> lo{}, hi{};
    lo.fill(std::numeric_limits<double>::max());
    hi.fill(std::numeric_limits<double>::lowest());
    for (std::size_t i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d) {
            const double v = positions[3 * i + d] - origin[d];
            lo[d] = std::min(lo[d], v);
            hi[d] = std::max(hi[d], v);
        }
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    const double scale = extent > 0 ? 1023.999 / extent : 0.0;
    std::vector<std::uint64_t> keys(n), sorted(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::uint64_t code = 0;
        for (int d = 0; d < 3; ++d) {
            const double cell = std::clamp((positions[3 * i + d] - origin[d] - lo[d]) * scale, 0.0, 1023.0);
            code |= spreadBits(static_cast<std::uint64_t>(cell)) << d;
        }
        keys[i] = (code << 32) | i;
    }
    for (int shift : {32, 47}) {
        std::vector<std::size_t> start(1u << 15, 0);
        for (std::uint64_t key : keys) ++start[(key >> shift) & 0x7fff];
        std::size_t sum = 0;
        for (std::size_t& s : start) sum += std::exchange(s, sum);
        for (std::uint64_t key : keys) sorted[start[(key >> shift) & 0x7fff]++] = key;
        keys.swap(sorted);
    }
    std::vector<std::uint32_t> order(n);
    for (std::size_t r = 0; r < n; ++r) order[r] = static_cast<std::uint32_t>(keys[r]);
    return order;
}

} // namespace

struct NeighbourIndex::Tree {
    FloatAdaptor adaptor;
    std::uint32_t base = 0;
    std::unique_ptr<KdTree> kd;
};

float KnnScratch::squaredDistance(std::size_t q, std::size_t j) const
{
    return std::bit_cast<float>(static_cast<std::uint32_t>(keys[q * k + j] >> 32));
}

NeighbourIndex::NeighbourIndex(std::span<const double> positions, const std::array<double, 3>& origin,
                               std::size_t leafSize, unsigned trees)
{
    const std::size_t n = positions.size() / 3;
    assert(n < std::numeric_limits<std::uint32_t>::max() && "NeighbourIndex: too many points");
    assert(leafSize >= 1 && trees >= 1 && "NeighbourIndex: leafSize and trees must be positive");
    m_source = mortonOrder(positions, origin);
    m_local.resize(3 * n);
    for (std::size_t r = 0; r < n; ++r)
        for (int d = 0; d < 3; ++d) m_local[3 * r + d] = positions[3 * std::size_t(m_source[r]) + d] - origin[d];
    if (n == 0) return;

    // One tree per contiguous rank range (spatially compact, thanks to the Morton order), built in parallel.
    const std::size_t treeCount = std::clamp<std::size_t>(std::min<std::size_t>(trees, n / 4096), 1, 64);
    std::vector<std::exception_ptr> failures(treeCount);
    auto build = [&](std::size_t t) {
        try {
            m_trees[t]->kd = std::make_unique<KdTree>(3, m_trees[t]->adaptor,
                                                      nanoflann::KDTreeSingleIndexAdaptorParams(leafSize));
        } catch (...) {
            failures[t] = std::current_exception();
        }
    };
    for (std::size_t t = 0; t < treeCount; ++t) {
        auto tree = std::make_unique<Tree>();
        const std::size_t begin = n * t / treeCount, end = n * (t + 1) / treeCount;
        tree->adaptor = FloatAdaptor{m_local.data() + 3 * begin, end - begin};
        tree->base = static_cast<std::uint32_t>(begin);
        m_trees.push_back(std::move(tree));
    }
    std::vector<std::thread> workers;
    for (std::size_t t = 1; t < treeCount; ++t) workers.emplace_back(build, t);
    build(0);
    for (auto& worker : workers) worker.join();
    for (auto& failure : failures)
        if (failure) std::rethrow_exception(failure);

    // Structure-of-arrays copy in tree order, so that a leaf is a contiguous range; then the leaves.
    m_x.resize(n);
    m_y.resize(n);
    m_z.resize(n);
    m_rankAt.resize(n);
    for (std::size_t t = 0; t < treeCount; ++t) {
        Tree& tree = *m_trees[t];
        for (std::size_t i = 0; i < tree.adaptor.count; ++i) {
            const std::uint32_t rank = tree.base + tree.kd->vAcc[i];
            const std::size_t position = tree.base + i;
            m_rankAt[position] = rank;
            m_x[position] = static_cast<float>(m_local[3 * std::size_t(rank)]);
            m_y[position] = static_cast<float>(m_local[3 * std::size_t(rank) + 1]);
            m_z[position] = static_cast<float>(m_local[3 * std::size_t(rank) + 2]);
        }
        std::vector<std::uint32_t>().swap(tree.kd->vAcc); // never searched through nanoflann again
        std::vector<const KdNode*> stack{tree.kd->root_node};
        while (!stack.empty()) {
            const KdNode* node = stack.back();
            stack.pop_back();
            if (!node->child1 && !node->child2) {
                m_leaves.push_back(Leaf{tree.base + static_cast<std::uint32_t>(node->node_type.lr.left),
                                        tree.base + static_cast<std::uint32_t>(node->node_type.lr.right),
                                        static_cast<std::uint32_t>(t)});
            } else {
                stack.push_back(node->child2);
                stack.push_back(node->child1);
            }
        }
    }
}

NeighbourIndex::~NeighbourIndex() = default;

void NeighbourIndex::search(std::span<const std::uint32_t> queries, std::size_t k, KnnScratch& s) const
{
    const std::size_t m = queries.size();
    s.k = k;
    s.queries = m;
    s.keys.resize(m * k);
    s.counts.assign(m, 0);
    s.worst.assign(m, kNoKey);
    s.qx.resize(m);
    s.qy.resize(m);
    s.qz.resize(m);
    s.maxWorstBits = std::numeric_limits<std::uint32_t>::max();
    if (m == 0 || k == 0 || m_trees.empty()) return;

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
    while (own + 1 < m_trees.size() && m_trees[own + 1]->base <= queries[0]) ++own;
    for (std::size_t i = 0; i < m_trees.size(); ++i) {
        const Tree& tree = *m_trees[i == 0 ? own : (i <= own ? i - 1 : i)];
        std::array<float, 3> gaps{};
        for (int d = 0; d < 3; ++d)
            gaps[d] = std::max({0.0f, tree.kd->root_bbox[d].low - hi[d], lo[d] - tree.kd->root_bbox[d].high});
        const float reach = gaps[0] * gaps[0] + gaps[1] * gaps[1] + gaps[2] * gaps[2];
        if (bitsOf(reach) <= s.maxWorstBits) descend(tree.kd->root_node, tree.base, gaps, lo, hi, s);
    }
}

void NeighbourIndex::descend(const void* nodePtr, std::uint32_t base, std::array<float, 3>& gaps,
                             const std::array<float, 3>& lo, const std::array<float, 3>& hi,
                             KnnScratch& s) const
{
    const auto* node = static_cast<const KdNode*>(nodePtr);
    if (!node->child1 && !node->child2) {
        visitLeaf(base + static_cast<std::uint32_t>(node->node_type.lr.left),
                  base + static_cast<std::uint32_t>(node->node_type.lr.right), s);
        return;
    }
    const int axis = node->node_type.sub.divfeat;
    const float divLow = node->node_type.sub.divlow;   // largest coordinate in child1
    const float divHigh = node->node_type.sub.divhigh; // smallest coordinate in child2
    const float gap1 = std::max(gaps[axis], lo[axis] - divLow);
    const float gap2 = std::max(gaps[axis], divHigh - hi[axis]);
    bool firstIsChild1 = gap1 < gap2;
    if (gap1 == gap2) firstIsChild1 = (lo[axis] + hi[axis]) < (divLow + divHigh);
    const KdNode* children[2] = {firstIsChild1 ? node->child1 : node->child2,
                                 firstIsChild1 ? node->child2 : node->child1};
    const float childGaps[2] = {firstIsChild1 ? gap1 : gap2, firstIsChild1 ? gap2 : gap1};
    const float saved = gaps[axis];
    for (int c = 0; c < 2; ++c) {
        gaps[axis] = childGaps[c];
        // Same float operations as the point distances, so the bound never exceeds a true distance.
        const float reach = gaps[0] * gaps[0] + gaps[1] * gaps[1] + gaps[2] * gaps[2];
        if (bitsOf(reach) <= s.maxWorstBits) descend(children[c], base, gaps, lo, hi, s);
    }
    gaps[axis] = saved;
}

void NeighbourIndex::visitLeaf(std::uint32_t begin, std::uint32_t end, KnnScratch& s) const
{
    constexpr std::uint32_t kChunk = 32;
    float distances[kChunk];
    const std::size_t k = s.k;
    std::uint32_t maxWorst = 0;
    for (std::size_t q = 0; q < s.queries; ++q) {
        const float qx = s.qx[q], qy = s.qy[q], qz = s.qz[q];
        std::uint64_t* keys = &s.keys[q * k];
        std::uint32_t count = s.counts[q];
        std::uint64_t worst = s.worst[q];
        for (std::uint32_t chunk = begin; chunk < end; chunk += kChunk) {
            const std::uint32_t chunkEnd = std::min(end, chunk + kChunk);
            for (std::uint32_t j = chunk; j < chunkEnd; ++j) { // vectorised
                const float dx = qx - m_x[j], dy = qy - m_y[j], dz = qz - m_z[j];
                distances[j - chunk] = dx * dx + dy * dy + dz * dz;
            }
            for (std::uint32_t j = chunk; j < chunkEnd; ++j) {
                const std::uint32_t bits = bitsOf(distances[j - chunk]);
                if (bits > (worst >> 32)) continue;
                const std::uint64_t key = (std::uint64_t(bits) << 32) | m_rankAt[j];
                if (key >= worst) continue;
                std::size_t i = count < k ? count++ : k - 1;
                while (i > 0 && keys[i - 1] > key) {
                    keys[i] = keys[i - 1];
                    --i;
                }
                keys[i] = key;
                worst = count == k ? keys[k - 1] : kNoKey;
            }
        }
        s.counts[q] = count;
        s.worst[q] = worst;
        maxWorst = std::max(maxWorst, static_cast<std::uint32_t>(worst >> 32));
    }
    s.maxWorstBits = maxWorst;
}

} // namespace stylos::core::normals::detail
