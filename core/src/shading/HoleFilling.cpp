#include "stylos/core/shading/HoleFilling.h"

#include "stylos/core/shading/FieldCoverage.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace stylos::core::shading {
namespace {

struct Offset {
    int dc, dr;
};
constexpr Offset kNeighbours[8] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}, {-1, -1}, {1, -1}, {-1, 1}, {1, 1}};

/** One hole being examined: its pixels (sorted element indices) and, once layered, their depths. */
class Hole {
public:
    Hole(const HeightField& field, int neighbours) : m_field(field), m_neighbours(neighbours) {}

    /** Collects the component of Empty pixels containing @p seed, marking them in @p visited. */
    void collect(std::uint32_t seed, std::vector<std::uint8_t>& visited)
    {
        m_pixels.clear();
        m_touchesBorder = false;
        const int width = m_field.width();
        visited[seed] = 1;
        m_pixels.push_back(seed);
        for (std::size_t head = 0; head < m_pixels.size(); ++head) {
            const int c = int(m_pixels[head] % std::uint32_t(width));
            const int r = int(m_pixels[head] / std::uint32_t(width));
            if (c == 0 || r == 0 || c == width - 1 || r == m_field.height() - 1) m_touchesBorder = true;
            for (int k = 0; k < m_neighbours; ++k) {
                const int nc = c + kNeighbours[k].dc, nr = r + kNeighbours[k].dr;
                if (!m_field.contains(nc, nr)) continue;
                const std::uint32_t n = std::uint32_t(m_field.index(nc, nr));
                if (visited[n] || m_field.states()[n] != PixelState::Empty) continue;
                visited[n] = 1;
                m_pixels.push_back(n);
            }
        }
    }

    /** Keeps only the pixels where @p keep is set (call before layer()). */
    void restrictTo(const std::vector<std::uint8_t>& keep)
    {
        std::erase_if(m_pixels, [&keep](std::uint32_t p) { return keep[p] == 0; });
    }

    std::size_t area() const { return m_pixels.size(); }
    /** Pixels that fill() gives a value: those layer() reached from a pixel with a height. */
    std::size_t reached() const { return m_order.size(); }
    bool touchesBorder() const { return m_touchesBorder; }

    /** Depth of every pixel (1 = next to a non-empty pixel), by breadth-first search; the largest. */
    int layer()
    {
        std::sort(m_pixels.begin(), m_pixels.end());
        m_depth.assign(m_pixels.size(), 0);
        m_order.clear();
        for (std::uint32_t i = 0; i < m_pixels.size(); ++i) {
            bool nearData = false;
            forNeighbours(m_pixels[i], [&](std::uint32_t n, std::int64_t local) { nearData |= local < 0 && hasHeight(n); });
            if (nearData) {
                m_depth[i] = 1;
                m_order.push_back(i);
            }
        }
        int deepest = 1;
        for (std::size_t head = 0; head < m_order.size(); ++head) {
            const std::uint32_t i = m_order[head];
            forNeighbours(m_pixels[i], [&](std::uint32_t, std::int64_t local) {
                if (local >= 0 && m_depth[std::size_t(local)] == 0) {
                    m_depth[std::size_t(local)] = m_depth[i] + 1;
                    deepest = std::max(deepest, m_depth[i] + 1);
                    m_order.push_back(std::uint32_t(local));
                }
            });
        }
        return deepest;
    }

    /** Appends (element index, filled height) for every pixel, border inward (call layer() first). */
    void fill(std::vector<std::pair<std::uint32_t, float>>& out)
    {
        m_values.assign(m_pixels.size(), 0.0f);
        const std::span<const float> heights = m_field.heights();
        for (const std::uint32_t i : m_order) { // breadth-first: depths never decrease
            double sum = 0.0;
            int count = 0;
            forNeighbours(m_pixels[i], [&](std::uint32_t n, std::int64_t local) {
                if (local < 0) {
                    if (!hasHeight(n)) return; // a pixel of the hole left out by restrictTo()
                    sum += heights[n];
                    ++count;
                } else if (m_depth[std::size_t(local)] < m_depth[i]) {
                    sum += m_values[std::size_t(local)];
                    ++count;
                }
            });
            m_values[i] = float(sum / count); // count ≥ 1: a pixel of depth k touches one of depth k − 1
            out.emplace_back(m_pixels[i], m_values[i]);
        }
    }

private:
    /** Whether pixel @p n has a height (a whole hole's outside neighbours all do; a restricted one's may not). */
    bool hasHeight(std::uint32_t n) const { return m_field.states()[n] != PixelState::Empty; }

    /** Calls f(element index, local index or −1 when the neighbour is not in this hole). */
    template <typename F>
    void forNeighbours(std::uint32_t pixel, F&& f) const
    {
        const int width = m_field.width();
        const int c = int(pixel % std::uint32_t(width)), r = int(pixel / std::uint32_t(width));
        for (int k = 0; k < m_neighbours; ++k) {
            const int nc = c + kNeighbours[k].dc, nr = r + kNeighbours[k].dr;
            if (!m_field.contains(nc, nr)) continue;
            const std::uint32_t n = std::uint32_t(m_field.index(nc, nr));
            const auto it = std::lower_bound(m_pixels.begin(), m_pixels.end(), n);
            f(n, it != m_pixels.end() && *it == n ? std::int64_t(it - m_pixels.begin()) : std::int64_t(-1));
        }
    }

    const HeightField& m_field;
    int m_neighbours;
    bool m_touchesBorder = false;
    std::vector<std::uint32_t> m_pixels; ///< element indices (sorted by layer())
    std::vector<int> m_depth;            ///< per local pixel
    std::vector<std::uint32_t> m_order;  ///< local indices, breadth-first from the hole's rim
    std::vector<float> m_values;         ///< per local pixel, once filled
};

/**
 * Visits every component of Empty pixels of @p field once, in row order (cancel checked every 64 rows, named
 * @p what), calling fillOne(hole, pending, report) with the component collected; then writes the values it left
 * in pending as Filled. Nothing is written on a cancel.
 */
template <typename FillOne>
Result<HoleFillReport> forEachHole(HeightField& field, Connectivity connectivity, ProgressSink* progress,
                                   const char* what, FillOne fillOne)
{
    HoleFillReport report;
    const std::span<const PixelState> states = field.states();
    std::vector<std::uint8_t> visited(field.pixelCount(), 0);
    std::vector<std::pair<std::uint32_t, float>> pending;
    Hole hole(field, int(connectivity));
    for (int r = 0; r < field.height(); ++r) {
        if (progress && r % 64 == 0) {
            if (progress->isCancelRequested()) return Error{ErrorCode::Cancelled, std::string(what) + ": cancelled"};
            progress->update(double(r) / field.height());
        }
        for (int c = 0; c < field.width(); ++c) {
            const std::uint32_t i = std::uint32_t(field.index(c, r));
            if (visited[i] || states[i] != PixelState::Empty) continue;
            hole.collect(i, visited);
            ++report.holes;
            fillOne(hole, pending, report);
        }
    }
    std::span<float> heights = field.heights();
    std::span<PixelState> writable = field.states();
    for (const auto& [i, value] : pending) {
        heights[i] = value;
        writable[i] = PixelState::Filled;
    }
    if (progress) progress->update(1.0);
    return report;
}

using Pending = std::vector<std::pair<std::uint32_t, float>>;

} // namespace

Result<HoleFillReport> fillHoles(HeightField& field, const HoleFillOptions& options, ProgressSink* progress)
{
    if (options.maxArea == 0)
        return Error{ErrorCode::InvalidArgument, "hole filling: the largest hole area must be at least 1 pixel"};
    if (options.maxDepth < 0)
        return Error{ErrorCode::InvalidArgument,
                     "hole filling: negative largest hole depth " + std::to_string(options.maxDepth)};
    if (options.connectivity != Connectivity::Four && options.connectivity != Connectivity::Eight)
        return Error{ErrorCode::InvalidArgument, "hole filling: connectivity must be 4 or 8"};
    return forEachHole(field, options.connectivity, progress, "hole filling",
                       [&options](Hole& hole, Pending& pending, HoleFillReport& report) {
        if (hole.touchesBorder()) {
            report.borderPixels += hole.area();
            return;
        }
        if (hole.area() > options.maxArea) {
            report.largeHolePixels += hole.area();
            return;
        }
        const int depth = hole.layer();
        if (options.maxDepth > 0 && depth > options.maxDepth) {
            report.largeHolePixels += hole.area();
            return;
        }
        hole.fill(pending);
        ++report.filledHoles;
        report.filledPixels += hole.area();
        report.deepestFill = std::max(report.deepestFill, depth);
    });
}

Result<HoleFillReport> fillFootprintGaps(HeightField& field, int radius, Connectivity connectivity, ProgressSink* progress)
{
    if (radius < 1) return Error{ErrorCode::InvalidArgument, "gap filling: the footprint radius must be at least 1 pixel"};
    if (connectivity != Connectivity::Four && connectivity != Connectivity::Eight)
        return Error{ErrorCode::InvalidArgument, "gap filling: connectivity must be 4 or 8"};
    const std::vector<std::uint8_t> footprint = footprintMask(field, radius);
    return forEachHole(field, connectivity, progress, "gap filling",
                       [&footprint](Hole& hole, Pending& pending, HoleFillReport& report) {
        const std::size_t area = hole.area();
        hole.restrictTo(footprint);
        if (hole.area() == 0) {
            report.largeHolePixels += area;
            return;
        }
        const int depth = hole.layer();
        hole.fill(pending);
        ++report.filledHoles;
        report.filledPixels += hole.reached();
        report.largeHolePixels += area - hole.reached();
        report.deepestFill = std::max(report.deepestFill, depth);
    });
}

} // namespace stylos::core::shading
