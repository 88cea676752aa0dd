#include "stylos/core/octree/LeafSpacing.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace stylos::core::octree {

namespace {

/**
 * @brief From the first index at @p level of each ancestor's descendants (@p starts, one more entry than
 *        ancestors, the last the level's cell count) to the same at level + 1, by a running count of children.
 */
std::vector<std::uint64_t> nextStarts(const OctreeLevels& levels, int level, const std::vector<std::uint64_t>& starts)
{
    std::vector<std::uint64_t> next(starts.size(), 0);
    std::uint64_t cell = 0, children = 0;
    std::size_t ancestor = 0;
    levels.visitLevel(level, [&](const CellBlock& block) {
        for (const std::uint8_t mask : block.masks) {
            while (ancestor < starts.size() && starts[ancestor] == cell) next[ancestor++] = children;
            children += static_cast<std::uint64_t>(std::popcount(mask));
            ++cell;
        }
    });
    while (ancestor < starts.size()) next[ancestor++] = children;
    return next;
}

/** Calls @p run(first, last, h) for each run of leaves [first, last) that share the spacing h; false when the
 *  octree has no leaf. */
template <typename Run>
bool leafSpacingRuns(const OctreeLevels& levels, Run run)
{
    const OctreeDescription& desc = levels.description();
    const int depth = desc.depth;
    if (desc.cellsPerLevel.empty() || desc.cellsPerLevel.back() == 0) return false;
    const int m = std::max(0, depth - 4);
    const int fine = std::min(depth, m + 2), coarse = std::min(depth, m + 1);
    const std::uint64_t ancestors = desc.cellsPerLevel[static_cast<std::size_t>(m)];

    std::vector<float> l1(ancestors, 1.0f);
    {
        const std::array<float, 3>* table = normalDecodeTable(desc.normalCode);
        const std::uint16_t codeMask = desc.normalCode == NormalCodeKind::Paper15 ? 0x7FFF : 0xFFFF;
        std::size_t i = 0;
        levels.visitLevel(m, [&](const CellBlock& block) {
            for (const std::uint16_t code : block.normals) {
                const auto& u = table[code & codeMask];
                l1[i++] = std::clamp(std::abs(u[0]) + std::abs(u[1]) + std::abs(u[2]), 1.0f, 1.7320508f);
            }
        });
    }

    std::vector<std::uint64_t> starts(ancestors + 1);
    for (std::uint64_t i = 0; i <= ancestors; ++i) starts[i] = i;
    std::vector<std::uint64_t> coarseStarts = starts, fineStarts = starts;
    for (int level = m; level < depth; ++level) {
        starts = nextStarts(levels, level, starts);
        if (level + 1 == coarse) coarseStarts = starts;
        if (level + 1 == fine) fineStarts = starts;
    }

    const double coarseEdge = desc.box.cellSize(coarse), fineEdge = desc.box.cellSize(fine);
    for (std::uint64_t i = 0; i < ancestors; ++i) {
        const auto n = double(starts[i + 1] - starts[i]);
        const auto o2 = double(fineStarts[i + 1] - fineStarts[i]);
        const auto o1 = double(coarseStarts[i + 1] - coarseStarts[i]);
        const double area = n >= 2 * o2 ? o2 * fineEdge * fineEdge / l1[i] : o1 * coarseEdge * coarseEdge / l1[i];
        const auto h = static_cast<float>(std::sqrt(area / std::max(n, 1.0)));
        run(starts[i], starts[i + 1], h);
    }
    return true;
}

} // namespace

std::vector<float> computeLeafSpacing(const OctreeLevels& levels)
{
    std::vector<float> spacing;
    const auto& cells = levels.description().cellsPerLevel;
    if (!cells.empty()) spacing.resize(cells.back());
    if (!leafSpacingRuns(levels, [&](std::uint64_t first, std::uint64_t last, float h) {
            std::fill(spacing.begin() + std::ptrdiff_t(first), spacing.begin() + std::ptrdiff_t(last), h);
        }))
        return {};
    return spacing;
}

AttributeLayer leafSpacingLayer(const OctreeLevels& levels)
{
    // Straight into the layer's bytes: the build's peak holds 4 bytes a leaf for it, not 8 (a vector and its copy).
    AttributeLayer layer;
    layer.name = LeafSpacingLayerName;
    layer.type = AttributeType::Float32;
    layer.components = 1;
    const auto& cells = levels.description().cellsPerLevel;
    if (!cells.empty()) layer.bytes.resize(std::size_t(cells.back()) * sizeof(float));
    std::uint8_t* bytes = layer.bytes.data();
    if (!leafSpacingRuns(levels, [&](std::uint64_t first, std::uint64_t last, float h) {
            for (std::uint64_t i = first; i < last; ++i) std::memcpy(bytes + i * sizeof(float), &h, sizeof(float));
        }))
        layer.bytes.clear();
    return layer;
}

AttributeLayer leafSpacingLayer(const std::vector<float>& spacing)
{
    AttributeLayer layer;
    layer.name = LeafSpacingLayerName;
    layer.type = AttributeType::Float32;
    layer.components = 1;
    layer.bytes.resize(spacing.size() * sizeof(float));
    if (!spacing.empty()) std::memcpy(layer.bytes.data(), spacing.data(), layer.bytes.size()); // little-endian host
    return layer;
}

} // namespace stylos::core::octree
