#include "stylos/core/octree/LeafSpacing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace stylos::core::octree {

namespace {

/** Level m (the ancestors) and the two levels below it (capped at the depth). */
struct SpacingLevels {
    int m = 0, coarse = 0, fine = 0;
};
SpacingLevels spacingLevels(const OctreeDescription& desc, int m)
{
    SpacingLevels s;
    s.m = m;
    s.fine = std::min(desc.depth, s.m + 2);
    s.coarse = std::min(desc.depth, s.m + 1);
    return s;
}

/** The ancestors are 2^k leaf edges wide, k = 4 unless the samples are sparser than that measures: see the file
 *  comment. */
constexpr int kFirstAncestorSpan = 4, kLastAncestorSpan = 8;

bool hasLeaves(const OctreeDescription& desc) { return !desc.cellsPerLevel.empty() && desc.cellsPerLevel.back() > 0; }

/** Calls @p run(first, last, h) for each run of leaves [first, last) that share the spacing h, from @p shape;
 *  false when the octree has no leaf. */
template <typename Run>
bool leafSpacingRuns(const OctreeLevels& levels, const LeafSpacingShape& shape, Run run)
{
    const OctreeDescription& desc = levels.description();
    if (!hasLeaves(desc)) return false;
    const SpacingLevels s = spacingLevels(desc, shape.ancestorLevel);
    const std::uint64_t ancestors = desc.cellsPerLevel[static_cast<std::size_t>(s.m)];

    std::vector<float> l1(ancestors, 1.0f);
    {
        const std::array<float, 3>* table = normalDecodeTable(desc.normalCode);
        const std::uint16_t codeMask = desc.normalCode == NormalCodeKind::Paper15 ? 0x7FFF : 0xFFFF;
        std::size_t i = 0;
        levels.visitLevel(s.m, [&](const CellBlock& block) {
            for (const std::uint16_t code : block.normals) {
                const auto& u = table[code & codeMask];
                l1[i++] = std::clamp(std::abs(u[0]) + std::abs(u[1]) + std::abs(u[2]), 1.0f, 1.7320508f);
            }
        });
    }

    // Each ancestor's leaves are the next run of leaves in breadth-first order.
    const double coarseEdge = desc.box.cellSize(s.coarse), fineEdge = desc.box.cellSize(s.fine);
    std::uint64_t first = 0;
    for (std::uint64_t i = 0; i < ancestors; ++i) {
        const auto o1 = double(shape.counts[0][i]), o2 = double(shape.counts[1][i]);
        const std::uint64_t leaves = shape.counts[2][i];
        const auto n = double(leaves);
        const double area = n >= 2 * o2 ? o2 * fineEdge * fineEdge / l1[i] : o1 * coarseEdge * coarseEdge / l1[i];
        const auto h = static_cast<float>(std::sqrt(area / std::max(n, 1.0)));
        run(first, first + leaves, h);
        first += leaves;
    }
    return true;
}

} // namespace

std::vector<float> computeLeafSpacing(const OctreeLevels& levels)
{
    std::vector<float> spacing;
    const auto& cells = levels.description().cellsPerLevel;
    if (!cells.empty()) spacing.resize(cells.back());
    if (!leafSpacingRuns(levels, leafSpacingShape(levels), [&](std::uint64_t first, std::uint64_t last, float h) {
            std::fill(spacing.begin() + std::ptrdiff_t(first), spacing.begin() + std::ptrdiff_t(last), h);
        }))
        return {};
    return spacing;
}

LeafSpacingShape leafSpacingShape(const OctreeLevels& levels)
{
    LeafSpacingShape shape;
    const OctreeDescription& desc = levels.description();
    if (!hasLeaves(desc)) return shape;
    // The first span whose coarse level is saturated (n ≥ 2 o₁) for at least half the leaves: samples sparser than
    // 8 leaf edges (an octree deeper than its scan: 4 mm samples at depth 12, 0.42 mm leaves) occupy one coarse cell
    // each, o₁ ≈ n, and the estimate would stop at that cell's edge (~3 mm) whatever the true spacing.
    for (int k = kFirstAncestorSpan; k <= kLastAncestorSpan; ++k) {
        const SpacingLevels s = spacingLevels(desc, std::max(0, desc.depth - k));
        shape.ancestorLevel = s.m;
        const std::array<int, 3> below{s.coarse, s.fine, desc.depth};
        shape.counts = levels.descendantCounts(s.m, below);
        if (s.m == 0) break;
        std::uint64_t saturated = 0, all = 0;
        for (std::size_t i = 0; i < shape.counts[2].size(); ++i) {
            all += shape.counts[2][i];
            if (shape.counts[2][i] >= 2 * shape.counts[0][i]) saturated += shape.counts[2][i];
        }
        if (2 * saturated >= all) break;
    }
    return shape;
}

AttributeLayer leafSpacingLayer(const OctreeLevels& levels)
{
    return leafSpacingLayer(levels, leafSpacingShape(levels));
}

AttributeLayer leafSpacingLayer(const OctreeLevels& levels, const LeafSpacingShape& shape)
{
    // Straight into the layer's bytes: the build's peak holds 4 bytes a leaf for it, not 8 (a vector and its copy).
    AttributeLayer layer;
    layer.name = LeafSpacingLayerName;
    layer.type = AttributeType::Float32;
    layer.components = 1;
    const auto& cells = levels.description().cellsPerLevel;
    if (!cells.empty()) layer.bytes.resize(std::size_t(cells.back()) * sizeof(float));
    std::uint8_t* bytes = layer.bytes.data();
    if (!leafSpacingRuns(levels, shape, [&](std::uint64_t first, std::uint64_t last, float h) {
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
