// Surface area per annotation class: the crossing density of the cells at the area level, shared by leaves.
#include "stylos/core/annotation/LabelArea.h"

#include "stylos/core/ao/AoCells.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace stylos::core::annotation {

Result<std::vector<double>> leafAreas(const octree::PackedOctree& octree, const LeafAreaOptions& options,
                                      ProgressSink* progress)
{
    const int level = std::max(0, ao::closedSurfaceLevel(octree) - std::max(0, options.levelsUp));
    auto cells = ao::cellsAtLevel(octree, level, progress);
    if (!cells) return cells.error();
    const double edge2 = cells->edge * cells->edge;
    std::vector<double> areas(cells->leafBegin.back(), 0.0);
    for (std::size_t i = 0; i < cells->size(); ++i) {
        const auto& n = cells->normals[i];
        const double l1 = std::abs(double(n[0])) + std::abs(double(n[1])) + std::abs(double(n[2]));
        const double norm = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
        // |n|₁ of the unit normal lies in [1, √3]; a degenerate normal (cancelled children) counts as 1.
        const double cellArea = edge2 / (norm > 0 ? std::clamp(l1 / norm, 1.0, std::sqrt(3.0)) : 1.0);
        const std::uint64_t begin = cells->leafBegin[i], end = cells->leafBegin[i + 1];
        if (end == begin) continue;
        const double share = cellArea / double(end - begin);
        std::fill(areas.begin() + std::ptrdiff_t(begin), areas.begin() + std::ptrdiff_t(end), share);
    }
    return areas;
}

std::vector<ClassMeasure> measureClasses(std::span<const std::uint8_t> labels, std::span<const double> areas)
{
    assert(labels.size() == areas.size() && "measureClasses(): one area per label");
    std::vector<ClassMeasure> measures(256);
    for (std::size_t i = 0; i < labels.size(); ++i) {
        ++measures[labels[i]].cells;
        measures[labels[i]].areaM2 += areas[i];
    }
    return measures;
}

} // namespace stylos::core::annotation
