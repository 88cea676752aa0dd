#pragma once
/** @file
 * @brief Private to core/normals: exact k-nearest-neighbour queries for every point of a cloud, built
 *        on nanoflann's KD-tree and searched one tree leaf at a time.
 *
 * nanoflann builds the tree (one tree per contiguous Morton range, built in parallel); the tree is then
 * flattened into a compact depth-first node array with a bounding box per leaf, and nanoflann's copy is
 * freed. Why not nanoflann's knnSearch() per point: measured at ~1.4 µs per query for k = 16 on 1 M
 * points (one core of the 2.5 GHz Xeon of the dev box), it alone would miss the 1 M points/s target on
 * 2 cores. Instead, the points of one leaf (≤ leafSize, all close together) are searched together: one
 * descent per leaf, pruned against the queries' box, and each visited leaf compared, query by query
 * (skipped when the leaf's box is beyond the query's current k-th distance), in a tight loop over
 * structure-of-arrays floats. Results are identical to a brute-force search.
 *
 * Exactness and determinism: coordinates are searched as float relative to @p origin (a cloud 300 m
 * across still resolves 15 µm). A neighbour is ranked by the key (float squared distance, Morton rank),
 * which is unique, so the k nearest are a well-defined set in a well-defined order whatever the number
 * of trees, threads or visiting order. Node pruning compares the box-to-region lower bound computed with
 * the same float operations as the distances, so no tie at the k-th distance is lost.
 *
 * Memory: about 52 bytes per point kept (double local copy 24, float SoA 12, ranks 8, nodes and leaf
 * boxes ~6) and 28 more during construction (sort keys 16, float copy 12). After construction, search() is const and
 * thread-safe with one KnnScratch per thread.
 */
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace stylos::core::normals::detail {

/** @brief Per-thread working memory of NeighbourIndex::search(). */
struct KnnScratch {
    std::size_t k = 0;
    std::size_t queries = 0;
    std::vector<std::uint64_t> keys;   ///< per query a 0 sentinel then k keys, ascending
    std::vector<std::uint32_t> counts; ///< neighbours found per query (≤ k)
    std::vector<std::uint64_t> worst;  ///< key of the k-th neighbour, or UINT64_MAX while not full
    std::vector<float> worstDistance;  ///< its squared distance, or +infinity while not full
    std::vector<float> qx, qy, qz;     ///< query coordinates (search frame)
    std::vector<float> reach;          ///< per query: squared distance to the leaf being visited
    std::uint32_t maxWorstBits = 0;    ///< float bits of the largest k-th distance in the batch

    /** Neighbour j of query q as its Morton rank. */
    std::uint32_t neighbour(std::size_t q, std::size_t j) const
    {
        return static_cast<std::uint32_t>(keys[q * (k + 1) + 1 + j]);
    }
    /** Squared distance (search frame, float) of neighbour j of query q. */
    float squaredDistance(std::size_t q, std::size_t j) const;
};

/** @brief A search tree over a fixed cloud; see the file comment. Not copyable. */
class NeighbourIndex {
public:
    /** A leaf of one of the trees: a range of tree positions. */
    struct Leaf {
        std::uint32_t begin;
        std::uint32_t end;
        std::uint32_t tree;
    };

    /**
     * @brief Builds the index over @p positions (x y z interleaved, metres), at most 2^32 − 1 points,
     *        all finite. @p origin is subtracted before anything else; choose it near the cloud's centre.
     * @param trees number of trees built in parallel (≥ 1); it changes speed, never results.
     */
    NeighbourIndex(std::span<const double> positions, const std::array<double, 3>& origin,
                   std::size_t leafSize, unsigned trees);
    ~NeighbourIndex();
    NeighbourIndex(const NeighbourIndex&) = delete;
    NeighbourIndex& operator=(const NeighbourIndex&) = delete;

    std::size_t size() const { return m_source.size(); }
    std::span<const Leaf> leaves() const { return m_leaves; }

    /** Morton rank of the point at tree position @p position (ranks identify points everywhere else). */
    std::uint32_t rankAt(std::uint32_t position) const { return m_rankAt[position]; }
    /** Index in the caller's array of the point of Morton rank @p rank. */
    std::uint32_t sourceOf(std::uint32_t rank) const { return m_source[rank]; }
    /** Position of rank @p rank relative to the origin, in double (x y z). */
    const double* localPosition(std::uint32_t rank) const { return &m_local[3 * std::size_t(rank)]; }

    /**
     * @brief Finds the min(k, size()) nearest points (the query itself included) of each tree position
     *        in @p queries, which must all lie in one leaf. Results land in @p scratch, ascending.
     */
    void search(std::span<const std::uint32_t> queries, std::size_t k, KnnScratch& scratch) const;

private:
    /** A node of the flattened tree, in depth-first order: child1 of an inner node is the next node. */
    struct Node {
        float divLow;          ///< inner: largest coordinate on the low side
        float divHigh;         ///< inner: smallest coordinate on the high side
        std::uint32_t axis;    ///< 0, 1, 2 for an inner node; 3 for a leaf
        std::uint32_t payload; ///< inner: index of child2; leaf: index in m_leaves
    };
    struct LeafBox {
        std::array<float, 3> lo, hi;
    };
    struct TreeRoot {
        std::uint32_t node;  ///< index of the root in m_nodes
        std::uint32_t begin; ///< first tree position
        LeafBox box;
    };

    void flatten(const void* nanoflannTree, std::uint32_t base, std::uint32_t tree);
    void descend(std::uint32_t node, std::array<float, 3>& gaps, const std::array<float, 3>& lo,
                 const std::array<float, 3>& hi, KnnScratch& scratch) const;
    void visitLeaf(std::uint32_t leaf, KnnScratch& scratch) const;

    std::vector<double> m_local;          ///< rank order, relative to the origin
    std::vector<std::uint32_t> m_source;  ///< rank → caller index
    std::vector<float> m_x, m_y, m_z;     ///< tree-position order, search frame
    std::vector<std::uint32_t> m_rankAt;  ///< tree position → rank
    std::vector<Leaf> m_leaves;
    std::vector<LeafBox> m_leafBoxes;
    std::vector<Node> m_nodes;
    std::vector<TreeRoot> m_roots;
};

} // namespace stylos::core::normals::detail
