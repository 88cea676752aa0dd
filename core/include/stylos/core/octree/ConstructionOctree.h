#pragma once
/** @file
 * @brief The construction structure of the packed octree (Duguet et al., VAST 2004, section 3): 7-byte
 *        cells (10 with colour) in a CellArena — child mask, normal code, and the child-table index of an
 *        inner cell or the weight (points averaged) of a leaf. Both builders fill it; it then hands its
 *        levels, breadth-first, to the `.poct` writer (OctreeLevels).
 *
 * Operations, by builder:
 *  - Streaming: populate() inserts one point down to the leaf level, growing child tables by
 *    allocate(k + 1) / copy / release(k).
 *  - Optimal: mark()/markAll() set, for each point, the child bit of its cell at the level being built
 *    (several threads may mark at once); allocateLevel() then gives every cell of that level its
 *    exact-size child table; findLeaf()/findLeaves() locate points' leaves (read-only, any thread) and
 *    average() adds each point to its leaf, in input order.
 *  - Both: pull() computes the inner cells' normals (subtrees on several threads); visitLevel() lists a
 *    level in breadth-first order through a depth-first walk restricted to the level (one frame per
 *    level, no memory proportional to the tree; large levels walked by setThreads() threads, subtree by
 *    subtree, handed out in order). The writer takes every level at once instead: visitLevels() (one
 *    depth-first walk) or, for a tree not pulled yet, pullAndVisitLevels(), which hands the cells out
 *    as the pull finishes each subtree (buildOctree: the file is written without a walk of its own).
 *
 * Leaf averaging and pull follow the shared definitions exactly (see OctreeBuild.h): a leaf's first point
 * sets its code; each later one re-encodes decode(code) · w + n̂ (float); colour channels by the rounded
 * integer running mean; weights saturate at 2^32 − 1.
 *
 * Each populate()/mark()/findLeaf() call restarts its descent at the deepest level where the point shares
 * its cell with the previous point of the same Path (scanner input is spatially coherent); markAll() and
 * findLeaves() send the points that share little with it down in groups of prefetched descents (random
 * input), which the read-only Optimal passes allow.
 * Thread-safety: see each function; otherwise one thread at a time.
 */
#include "stylos/core/octree/CellArena.h"
#include "stylos/core/octree/OctreeLevels.h"
#include "stylos/core/octree/PreparedPoint.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace stylos::core::octree {

class ConstructionOctree final : public OctreeLevels {
public:
    /** @brief The cells on the way to the previous point, to restart the next descent (one per thread). */
    struct Path {
        std::array<std::uint32_t, 3> coords{};                ///< leaf coordinates of the previous point
        std::array<std::uint32_t, MaxOctreeDepth + 1> cells{}; ///< its cell at each level; [0] the root
        int levels = 0;                                        ///< cells[0..levels] are valid
        int marked = -1;                                       ///< mark(): level whose bit it set last
    };

    /**
     * @brief An octree holding only its root (a leaf at level 0 until it gets children), in @p box, with
     *        leaves at @p depth (MinOctreeDepth..MaxOctreeDepth), whose arena never passes @p memoryLimit
     *        bytes (0: no limit). Precondition: @p memoryLimit is 0 or at least minimumBytes(hasColour).
     */
    ConstructionOctree(const RootBox& box, int depth, NormalCodeKind kind, bool hasColour, std::uint64_t memoryLimit);

    /** @brief Bytes of the smallest tree (the root's chunk). */
    static std::uint64_t minimumBytes(bool hasColour);

    const OctreeDescription& description() const override { return m_description; }
    /** @brief Precondition: the tree is complete (every leaf at the leaf level) and pulled. */
    void visitLevel(int level, const std::function<void(const CellBlock&)>& sink) const override;
    /** @brief All levels in one depth-first walk (each cell read once). Precondition: as visitLevel(). */
    void visitLevels(const std::function<void(int level, const CellBlock&)>& sink) const override;
    /** @brief One walk below each ancestor, on the setThreads() threads. Precondition: a complete tree. */
    std::vector<std::vector<std::uint64_t>> descendantCounts(int ancestorLevel,
                                                             std::span<const int> levels) const override;

    // ---- Streaming ----
    /**
     * @brief Populate: inserts @p point down to the leaf level and averages it into its leaf; counts it.
     * @return false when a child table could not be allocated within the memory limit (the tree is then
     *         incomplete and only good for reporting the failure).
     */
    bool populate(const PreparedPoint& point, Path& path);

    // ---- Optimal ----
    /**
     * @brief Sets the bit of @p point's child slot at @p level + 1 in its cell at @p level; the levels
     *        above must have been marked and allocated for the same point. Thread-safe against other
     *        mark() calls (atomic OR), with one Path per thread.
     * @return false when a cell on the way lacks the point's child (the input changed between passes).
     */
    bool mark(const std::array<std::uint32_t, 3>& coords, int level, Path& path);
    /**
     * @brief mark() for every point of @p points (any order: the result does not depend on it); points
     *        far from the one before descend in groups with prefetching. Thread-safe like mark().
     * @return false if some point lacks a cell on the way (the input changed between passes).
     */
    bool markAll(std::span<const PreparedPoint> points, int level, Path& path);
    /** @brief Exact bytes the arena would hold after allocateLevel(@p level) (walks the level). */
    std::uint64_t bytesAfterAllocating(int level) const;
    /**
     * @brief Gives every cell of @p level (all marked) its child table of popcount(mask) zeroed cells,
     *        in breadth-first order. @return false (nothing done) if that would pass the memory limit.
     */
    bool allocateLevel(int level);
    /**
     * @brief The leaf index of @p coords (the tree must be complete down to the leaf level), or
     *        CellArena::Exhausted if a cell on the way lacks the child. Read-only: safe to call while
     *        another thread runs average() on leaves.
     */
    std::uint32_t findLeaf(const std::array<std::uint32_t, 3>& coords, Path& path) const;
    /** @brief findLeaf() of every point into @p leaves (same size), the far ones in prefetching groups. */
    void findLeaves(std::span<const PreparedPoint> points, std::span<std::uint32_t> leaves, Path& path) const;
    /** @brief Averages @p point into leaf @p leaf (input order is the caller's business); counts it. */
    void average(std::uint32_t leaf, const PreparedPoint& point);

    // ---- Both ----
    /** @brief Computes every inner cell's normal from its children (the shared pull) on @p threads threads. */
    void pull(unsigned threads);
    /**
     * @brief pull(), handing every level's cells to @p sink as they are pulled (as visitLevels() would after
     *        the pull: each level in breadth-first order, the levels interleaved; one call at a time, from
     *        any of the threads), so that writing the file needs no walk of its own. A null @p sink: pull().
     *        While it runs, other threads may read the cells' masks and child tables (not their normals).
     */
    void pullAndVisitLevels(unsigned threads, const std::function<void(int level, const CellBlock&)>* sink);
    /** @brief Threads visitLevel() may use to walk large levels (default 1); the output does not change. */
    void setThreads(unsigned threads) { m_threads = threads < 1 ? 1 : threads; }
    /** @brief A Path starting at the root. */
    Path rootPath() const;

    /** @brief Weights of the cells of @p level in breadth-first order (inner cells: sum of their leaves). */
    std::vector<std::uint64_t> weights(int level) const;
    /** @brief Cell indices of @p level in breadth-first order (tests and diagnostics). */
    std::vector<std::uint32_t> cellIndices(int level) const;

    const CellArena& arena() const { return m_arena; }
    std::uint32_t root() const { return m_root; }
    NormalCodeKind kind() const { return m_description.normalCode; }
    int depth() const { return m_description.depth; }
    /** @brief Bytes of the construction structure now (its peak: the arena never shrinks). */
    std::uint64_t bytes() const { return m_arena.bytes(); }

private:
    template <unsigned CellBytes>
    void visitCells(int level, const std::function<void(const CellBlock&)>& sink) const;
    template <unsigned CellBytes>
    void visitAllCells(const std::function<void(int level, const CellBlock&)>& sink) const;
    template <unsigned CellBytes>
    bool populateCells(const PreparedPoint& point, Path& path);
    template <unsigned CellBytes>
    void averageCell(std::uint8_t* cell, const PreparedPoint& point);
    /** The deepest level, at most @p cap, whose cell @p coords shares with @p path's point. */
    int restartLevel(const std::array<std::uint32_t, 3>& coords, const Path& path, int cap) const
    {
        const std::uint32_t diff =
            (coords[0] ^ path.coords[0]) | (coords[1] ^ path.coords[1]) | (coords[2] ^ path.coords[2]);
        const int common = m_description.depth - int(std::bit_width(diff));
        return std::min({common, path.levels, cap});
    }
    struct Probe;
    /** Moves every probe down to @p target (or until a cell lacks its child), a level per round. */
    void descendGroup(Probe* probes, unsigned count, int target) const;
    /** Weights of the cells of one level, pulled already, in breadth-first order. */
    struct PulledSubtrees {
        int level = 0;
        std::vector<std::uint64_t> weights;
        std::size_t next = 0;
    };
    /** The cells of one subtree, level by level, as its pull visits them (SubtreeCells.h). */
    struct SubtreeCells;
    /** Pulls the @p count cells from @p first (a table) at @p level; their weights go to @p weights, the cells
     *  (when @p out) to @p out. */
    void pullTable(std::uint32_t first, unsigned count, int level, PulledSubtrees* pulled, std::uint64_t* weights,
                   SubtreeCells* out = nullptr);

    OctreeDescription m_description;
    CellArena m_arena;
    std::uint32_t m_root = 0;
    NormalEncoder m_encode;
    const std::array<float, 3>* m_decode = nullptr;
    const std::uint16_t* m_reencode = nullptr;   ///< encode(decode(code)) of every code
    std::uint16_t m_codeMask = 0xFFFF;
    unsigned m_threads = 1;
};

} // namespace stylos::core::octree
