#include "stylos/core/octree/ViewCut.h"

#include "CutQueue.h"
#include "Frustum.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace stylos::core::octree {

namespace {

/** Number of set bits of each byte (child counts of masks). */
constexpr std::array<std::uint8_t, 256> bitCounts = [] {
    std::array<std::uint8_t, 256> t{};
    for (unsigned m = 0; m < 256; ++m) t[m] = std::uint8_t((m & 1) + ((m >> 1) & 1) + ((m >> 2) & 1) + ((m >> 3) & 1) +
                                                           ((m >> 4) & 1) + ((m >> 5) & 1) + ((m >> 6) & 1) + (m >> 7));
    return t;
}();

/** A cell being looked at (a child of the cell being refined, or the root). */
struct Look {
    std::uint64_t index;
    std::uint32_t x, y, z;
    int level;
    std::uint8_t planes;
    double priority;
    double distance2;
};

class CutBuilder {
public:
    CutBuilder(const PackedOctree& octree, const CutCamera& camera, const CutOptions& options)
        : m_octree(octree), m_threshold(options.pixelThreshold), m_budget(std::max<std::uint64_t>(1, options.pointBudget)),
          m_orthographic(camera.orthographic),
          m_queue(queueCapacity(octree, options))
    {
        const int depth = octree.depth();
        m_maxLevel = (options.maxLevel < 0 || options.maxLevel > depth) ? depth : options.maxLevel;
        const RootBox& box = octree.box();
        for (int l = 0; l <= depth; ++l) m_sizes[static_cast<std::size_t>(l)] = box.cellSize(l);
        for (int a = 0; a < 3; ++a) m_eye[static_cast<std::size_t>(a)] = camera.eye[a] - box.origin[a];
        m_cull = camera.cullToFrustum;
        if (m_cull) m_frustum = Frustum::fromViewProjection(camera.viewProjection, box.origin);
        m_scale = camera.orthographic ? camera.pixelsPerMetre : camera.pixelsPerRadian;
    }

    /** The queue never holds more than the budget, nor more than the cells above the deepest level;
     *  beyond InitialCapacity it grows as needed. */
    static std::size_t queueCapacity(const PackedOctree& octree, const CutOptions& options)
    {
        const int depth = octree.depth();
        const int deepest = (options.maxLevel < 0 || options.maxLevel > depth) ? depth : options.maxLevel;
        std::uint64_t inner = 0;
        for (int l = 0; l < deepest; ++l) inner += octree.cellCount(l);
        return static_cast<std::size_t>(std::clamp<std::uint64_t>(std::min(options.pointBudget, inner), 1, InitialCapacity));
    }

    CutResult run()
    {
        const std::uint64_t reserve = std::min({m_budget, m_octree.totalCells(), InitialCapacity});
        m_result.cells.reserve(static_cast<std::size_t>(reserve));
        Look root{0, 0, 0, 0, 0, m_cull ? Frustum::AllPlanes : std::uint8_t(0), 0, 0};
        if (!look(root)) return std::move(m_result);
        if (isCandidate(root)) m_queue.push(candidate(root));
        else keep(root);
        while (!m_queue.empty()) {
            if (slack() == 0 && m_zeroPending == 0 && m_failedDrains < MaxFailedDrains) drain();
            else step();
        }
        return std::move(m_result);
    }

private:
    /** Fills in priority and distance; false when the cell is culled. */
    bool look(Look& e) const
    {
        const double size = m_sizes[static_cast<std::size_t>(e.level)];
        const double half = 0.5 * size;
        const std::array<double, 3> c{(double(e.x) + 0.5) * size, (double(e.y) + 0.5) * size,
                                      (double(e.z) + 0.5) * size};
        if (e.planes != 0 && !m_frustum.keep(c, half, e.planes)) return false;
        const double dx = c[0] - m_eye[0], dy = c[1] - m_eye[1], dz = c[2] - m_eye[2];
        e.distance2 = dx * dx + dy * dy + dz * dz;
        if (m_orthographic) {
            e.priority = size * m_scale;
        } else if (std::abs(dx) <= half && std::abs(dy) <= half && std::abs(dz) <= half) {
            e.priority = std::numeric_limits<double>::infinity();
        } else {
            e.priority = size * m_scale / std::sqrt(e.distance2);
        }
        return true;
    }

    bool isCandidate(const Look& e) const { return e.priority > m_threshold && e.level < m_maxLevel; }

    static CutCandidate candidate(const Look& e)
    {
        return {e.priority, e.distance2, CutCandidate::packCoords(e.x, e.y, e.z),
                CutCandidate::packTag(e.level, e.index, e.planes)};
    }

    /** Looks at the children of @p c; @p children receives the visible ones, in slot order. */
    std::size_t expand(const CutCandidate& c, Look (&children)[8]) const
    {
        const int level = c.level();
        const std::uint64_t index = c.index();
        const std::uint8_t mask = m_octree.mask(level, index);
        std::uint64_t childIndex = m_octree.firstChild(level, index);
        const std::uint32_t x = 2 * c.x(), y = 2 * c.y(), z = 2 * c.z();
        std::size_t n = 0;
        for (unsigned slot = 0; slot < 8; ++slot) {
            if ((mask & (1u << slot)) == 0) continue;
            Look& child = children[n];
            child.index = childIndex++;
            child.x = x + (slot & 1u);
            child.y = y + ((slot >> 1) & 1u);
            child.z = z + ((slot >> 2) & 1u);
            child.level = level + 1;
            child.planes = c.planes();
            if (look(child)) ++n;
        }
        return n;
    }

    /** Cells the budget still allows: budget − (cells in the cut + candidates). */
    std::uint64_t slack() const { return m_budget - m_result.cells.size() - m_queue.size(); }

    /** Takes the first candidate: refines it within the budget, else keeps it. */
    void step()
    {
        const CutCandidate top = m_queue.top();
        if (top.planes() == 0 && childCount(top) > slack() + 1) {
            // Entirely in view (or no culling): every child is visible, and there are too many.
            refuse(top);
            return;
        }
        Look children[8];
        const std::size_t n = expand(top, children);
        if (n > slack() + 1) {
            refuse(top);
            return;
        }
        ++m_result.refinements;
        if (n == 0 && m_zeroPending > 0) --m_zeroPending;
        bool replaced = false;
        for (std::size_t i = 0; i < n; ++i) {
            if (!isCandidate(children[i])) {
                keep(children[i]);
            } else if (!replaced) {
                m_queue.replaceTop(candidate(children[i]));
                replaced = true;
            } else {
                m_queue.push(candidate(children[i]));
            }
        }
        if (!replaced) m_queue.pop();
    }

    std::size_t childCount(const CutCandidate& c) const { return bitCounts[m_octree.mask(c.level(), c.index())]; }

    void refuse(const CutCandidate& c)
    {
        m_result.budgetReached = true;
        m_queue.pop();
        keep(c);
    }

    /**
     * With no slack left, the priority order only matters through candidates without visible
     * children (removing them frees a cell for the next ones): a candidate with one visible child is
     * refined whenever it comes, one with more is refused. So this pass takes the whole queue in
     * storage order, refines the one-child candidates (and their one-child descendants), and — when
     * no candidate without visible children turned up — refuses all the others at once, exactly as
     * the priority order would, without the heap's cost. Otherwise the queue is rebuilt from what is
     * left and the caller goes on in priority order.
     */
    void drain()
    {
        m_work.assign(m_queue.data(), m_queue.data() + m_queue.size());
        m_queue.clear();
        std::size_t pending = 0, zeros = 0;
        Look children[8];
        for (std::size_t i = 0; i < m_work.size(); ++i) {
            const CutCandidate c = m_work[i];
            if (c.planes() == 0 && childCount(c) >= 2) { // all children visible: refused
                m_work[pending++] = c;
                continue;
            }
            const std::size_t n = expand(c, children);
            if (n == 1) {
                ++m_result.refinements;
                if (isCandidate(children[0])) m_work.push_back(candidate(children[0]));
                else keep(children[0]);
            } else {
                zeros += n == 0 ? 1 : 0;
                m_work[pending++] = c;
            }
        }
        if (zeros == 0) {
            for (std::size_t k = 0; k < pending; ++k) keep(m_work[k]);
            m_result.budgetReached = m_result.budgetReached || pending > 0;
        } else {
            m_queue.assign(m_work.data(), pending);
            m_zeroPending = zeros;
            ++m_failedDrains;
        }
    }

    void keep(const CutCandidate& c) { keep(Look{c.index(), c.x(), c.y(), c.z(), c.level(), 0, 0, 0}); }

    void keep(const Look& e)
    {
        const double size = m_sizes[static_cast<std::size_t>(e.level)];
        CutCell cell;
        cell.centre = {static_cast<float>((double(e.x) + 0.5) * size), static_cast<float>((double(e.y) + 0.5) * size),
                       static_cast<float>((double(e.z) + 0.5) * size)};
        cell.size = static_cast<float>(size);
        cell.normal = m_octree.normal(e.level, e.index);
        cell.level = e.level;
        cell.index = e.index;
        m_result.deepestLevel = std::max(m_result.deepestLevel, e.level);
        m_result.cells.push_back(cell);
    }

    const PackedOctree& m_octree;
    double m_threshold;
    std::uint64_t m_budget;
    bool m_orthographic;
    bool m_cull = false;
    int m_maxLevel = 0;
    std::array<double, MaxOctreeDepth + 1> m_sizes{};
    std::array<double, 3> m_eye{};
    double m_scale = 1;
    Frustum m_frustum;
    CutQueue m_queue;
    CutResult m_result;
    std::vector<CutCandidate> m_work;     ///< drain(): the queue's entries, then those left
    std::size_t m_zeroPending = 0;        ///< candidates without visible children left by drain()
    int m_failedDrains = 0;
    static constexpr int MaxFailedDrains = 4;
    static constexpr std::uint64_t InitialCapacity = std::uint64_t(1) << 20;
};

} // namespace

CutResult computeViewCut(const PackedOctree& octree, const CutCamera& camera, const CutOptions& options)
{
    assert(options.pointBudget >= 1 && "computeViewCut(): pointBudget must be at least 1");
    assert(options.maxLevel >= -1 && "computeViewCut(): maxLevel must be -1 or a level");
    assert((camera.orthographic ? camera.pixelsPerMetre : camera.pixelsPerRadian) > 0 &&
           "computeViewCut(): pixels per radian / metre must be positive");
    return CutBuilder(octree, camera, options).run();
}

} // namespace stylos::core::octree
