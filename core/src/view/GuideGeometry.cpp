#include "stylos/core/view/GuideGeometry.h"

#include "stylos/core/scene/SceneEigen.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <numbers>

namespace stylos::core::view {

std::optional<DrumAxis> drumAxisOf(const scene::Fragment& drum, const scene::Pose* world)
{
    const auto axis = scene::firstGuide(drum, scene::GuideKind::Axis);
    if (!axis) return std::nullopt;
    const Eigen::Matrix4d pose = scene::toEigen(world ? *world : drum.pose);
    DrumAxis result;
    result.point = pose.topLeftCorner<3, 3>() * axis->origin + pose.topRightCorner<3, 1>();
    result.direction = (pose.topLeftCorner<3, 3>() * axis->direction).normalized();
    const auto grooves = std::count_if(drum.guides.begin(), drum.guides.end(),
                                       [](const scene::Guide& g) { return g.kind == scene::GuideKind::Groove; });
    result.pitch = grooves > 0 ? 2 * std::numbers::pi / double(grooves) : 0.0;
    return result;
}

std::vector<GuideSegment> guideSegments(const scene::Fragment& fragment, const Eigen::AlignedBox3d& localBounds,
                                        const scene::Pose* world)
{
    // The box's eight corners as cells of no size: the same projection as the cells'.
    OccupiedCells corners;
    if (!localBounds.isEmpty())
        for (int corner = 0; corner < 8; ++corner) corners.centres.push_back(localBounds.corner(Eigen::AlignedBox3d::CornerType(corner)));
    return guideSegments(fragment, corners, world);
}

OccupiedCells occupiedCells(const octree::PackedOctree& octree, int level)
{
    OccupiedCells cells;
    level = std::clamp(level, 0, octree.depth());
    cells.size = octree.box().cellSize(level);
    cells.centres.reserve(std::size_t(octree.cellCount(level)));
    octree.forEachCell(level, [&cells](const octree::CellView& cell) {
        cells.centres.emplace_back(cell.centre[0], cell.centre[1], cell.centre[2]);
        return true;
    });
    return cells;
}

std::vector<GuideSegment> guideSegments(const scene::Fragment& fragment, const OccupiedCells& cells, const scene::Pose* world)
{
    std::vector<GuideSegment> segments;
    if (cells.centres.empty()) return segments;
    const Eigen::Matrix4d pose = scene::toEigen(world ? *world : fragment.pose);
    const auto toScene = [&pose](const Eigen::Vector3d& p) -> Eigen::Vector3d {
        return pose.topLeftCorner<3, 3>() * p + pose.topRightCorner<3, 1>();
    };
    segments.reserve(fragment.guides.size());
    // The extent along a direction, once per direction (a drum's flute lines all share the axis's).
    Eigen::Vector3d lastDirection = Eigen::Vector3d::Zero();
    double lowest = 0.0, highest = 0.0;
    for (const scene::Guide& guide : fragment.guides) {
        const scene::GuideLine line = scene::guideLine(guide);
        const Eigen::Vector3d d = line.direction.normalized();
        if (d != lastDirection) {
            lastDirection = d;
            const double reach = 0.5 * cells.size * d.cwiseAbs().sum(); // a cube's corners about its centre, along d
            lowest = std::numeric_limits<double>::infinity();
            highest = -lowest;
            for (const Eigen::Vector3d& c : cells.centres) {
                const double s = c.dot(d);
                lowest = std::min(lowest, s - reach);
                highest = std::max(highest, s + reach);
            }
        }
        const double offset = line.origin.dot(d);
        segments.push_back({toScene(line.origin + (lowest - offset) * d), toScene(line.origin + (highest - offset) * d), guide.kind});
    }
    return segments;
}

namespace {

/**
 * The lowest coordinate along @p axis of the cells of @p level, found by branch and bound from the root:
 * children are visited lowest first and a subtree whose own lowest coordinate cannot beat the best so far
 * is skipped, so a descent visits a few cells per level rather than every cell. With @p highest, the
 * highest (as the lowest of the coordinates mirrored).
 */
class ExtremeCell {
public:
    ExtremeCell(const octree::PackedOctree& octree, int level, int axis, bool highest)
        : m_octree(octree), m_level(level), m_axis(axis), m_highest(highest)
    {
    }

    /** The extreme coordinate at the level (mirrored when highest); none when the level has no cell. */
    std::optional<std::uint32_t> find()
    {
        visit(0, 0, 0);
        return m_best;
    }

private:
    /** The cell (depth, index) whose coordinate along the axis is @p coord (mirrored at its depth). */
    void visit(int depth, std::uint64_t index, std::uint32_t coord)
    {
        const int shift = m_level - depth;
        if (m_best && (std::uint64_t(coord) << shift) >= *m_best) return; // cannot be lower than the best
        if (depth == m_level) {
            m_best = coord;
            return;
        }
        const std::uint8_t mask = m_octree.mask(depth, index);
        const std::uint64_t first = m_octree.firstChild(depth, index);
        const unsigned bit = 1u << m_axis;
        // Children on the low side of the axis first (the high side first when mirrored).
        for (const unsigned side : {m_highest ? bit : 0u, m_highest ? 0u : bit}) {
            unsigned rank = 0;
            for (unsigned slot = 0; slot < 8; ++slot) {
                if ((mask & (1u << slot)) == 0) continue;
                const std::uint64_t child = first + rank++;
                if ((slot & bit) != side) continue;
                const std::uint32_t low = (slot & bit) ? 1u : 0u;
                visit(depth + 1, child, 2 * coord + (m_highest ? 1u - low : low));
            }
        }
    }

    const octree::PackedOctree& m_octree;
    int m_level, m_axis;
    bool m_highest;
    std::optional<std::uint32_t> m_best;
};

} // namespace

Eigen::AlignedBox3d occupiedBounds(const octree::PackedOctree& octree, int level)
{
    level = std::clamp(level, 0, octree.depth());
    const std::uint32_t last = (std::uint32_t(1) << level) - 1u; // the highest coordinate of the level
    std::array<std::uint32_t, 3> low{}, high{};
    for (int axis = 0; axis < 3; ++axis) {
        const auto lowest = ExtremeCell(octree, level, axis, false).find();
        const auto highest = ExtremeCell(octree, level, axis, true).find();
        if (!lowest || !highest) return {};
        low[std::size_t(axis)] = *lowest;
        high[std::size_t(axis)] = last - *highest;
    }
    // Corners as centre ± half a cell, as the cells' own centres are computed (RootBox::cellCentre).
    const Eigen::Vector3d half = Eigen::Vector3d::Constant(octree.box().cellSize(level) / 2);
    const Eigen::Vector3d a = scene::toEigen(octree.box().cellCentre(level, low[0], low[1], low[2]));
    const Eigen::Vector3d b = scene::toEigen(octree.box().cellCentre(level, high[0], high[1], high[2]));
    return Eigen::AlignedBox3d(a - half, b + half);
}

} // namespace stylos::core::view
