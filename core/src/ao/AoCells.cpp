#include "stylos/core/ao/AoCells.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace stylos::core::ao {

std::array<double, 3> AoCells::centre(std::size_t i) const
{
    return {origin[0] + (coords[i][0] + 0.5) * edge, origin[1] + (coords[i][1] + 0.5) * edge,
            origin[2] + (coords[i][2] + 0.5) * edge};
}

Result<AoCells> cellsAtLevel(const octree::PackedOctree& octree, int level, ProgressSink* progress)
{
    const int depth = octree.depth();
    if (level < 0 || level > depth)
        return Error::at(ErrorCode::InvalidArgument, octree.path().string(), "",
                         "level " + std::to_string(level) + " is outside the octree's levels 0.." +
                             std::to_string(depth));
    const std::uint64_t count = octree.cellCount(level);
    const std::uint64_t leaves = octree.cellCount(depth);
    AoCells cells;
    cells.level = level;
    cells.edge = octree.root().size / double(std::uint64_t{1} << level);
    const octree::CellView root = octree.root();
    for (int a = 0; a < 3; ++a) cells.origin[a] = root.centre[a] - 0.5 * root.size;
    cells.coords.reserve(count);
    cells.normals.reserve(count);
    cells.opacity.reserve(count);
    cells.leafBegin.reserve(count + 1);

    constexpr std::uint64_t kCheckEvery = 64 * 1024;
    bool cancelled = false;
    octree.forEachCell(level, [&](const octree::CellView& cell) {
        if (cell.index % kCheckEvery == 0 && progress) {
            if (progress->isCancelRequested()) {
                cancelled = true;
                return false;
            }
            progress->update(double(cell.index) / double(count));
        }
        cells.coords.push_back(cell.coords);
        cells.normals.push_back(cell.normal);
        std::uint64_t first = cell.index;
        for (int l = level; l < depth; ++l) first = octree.firstChild(l, first);
        cells.leafBegin.push_back(first);
        return true;
    });
    if (cancelled) return Error::at(ErrorCode::Cancelled, octree.path().string(), "", "skydome cancelled while reading the cells");
    cells.leafBegin.push_back(leaves);

    // n leaves under a cell k levels up: a crossing surface fills about 4^k of its slots.
    const double surfaceSlots = std::pow(4.0, depth - level);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const double n = double(cells.leafBegin[i + 1] - cells.leafBegin[i]);
        cells.opacity.push_back(float(std::min(1.0, n / surfaceSlots)));
    }
    if (progress) progress->update(1.0);
    return cells;
}

Result<AoReceivers> leafReceivers(const octree::PackedOctree& octree, const AoCells& occluders, ProgressSink* progress)
{
    const int depth = octree.depth();
    const std::uint64_t count = octree.cellCount(depth);
    // A leaf with coordinates c spans [c, c + 1] / 2^(depth − level) occluder edges.
    const double scale = 1.0 / double(std::uint64_t{1} << (depth - occluders.level));
    AoReceivers receivers;
    receivers.positions.reserve(count);
    receivers.normals.reserve(count);
    constexpr std::uint64_t kCheckEvery = 64 * 1024;
    bool cancelled = false;
    octree.forEachCell(depth, [&](const octree::CellView& leaf) {
        if (leaf.index % kCheckEvery == 0 && progress) {
            if (progress->isCancelRequested()) {
                cancelled = true;
                return false;
            }
            progress->update(double(leaf.index) / double(count));
        }
        receivers.positions.push_back({float((leaf.coords[0] + 0.5) * scale), float((leaf.coords[1] + 0.5) * scale),
                                       float((leaf.coords[2] + 0.5) * scale)});
        receivers.normals.push_back(leaf.normal);
        return true;
    });
    if (cancelled)
        return Error::at(ErrorCode::Cancelled, octree.path().string(), "", "skydome cancelled while reading the leaves");
    if (progress) progress->update(1.0);
    return receivers;
}

int closedSurfaceLevel(const octree::PackedOctree& octree)
{
    constexpr double kClosedRatio = 3.0;
    for (int level = octree.depth(); level >= 1; --level)
        if (double(octree.cellCount(level)) >= kClosedRatio * double(octree.cellCount(level - 1))) return level;
    return octree.depth();
}

std::vector<float> valuesPerLeaf(const AoCells& cells, std::span<const float> values)
{
    std::vector<float> leaves(cells.leafBegin.empty() ? 0 : cells.leafBegin.back());
    for (std::size_t i = 0; i < cells.size() && i < values.size(); ++i)
        std::fill(leaves.begin() + std::ptrdiff_t(cells.leafBegin[i]), leaves.begin() + std::ptrdiff_t(cells.leafBegin[i + 1]),
                  values[i]);
    return leaves;
}

} // namespace stylos::core::ao
