#include "HorizonBand.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace stylos::core::shading::detail {

WalkGeometry::WalkGeometry(const DirectionRaster& raster, double pixelSize)
{
    const bool columnMajor = raster.columnMajor();
    along = float(std::fabs(columnMajor ? raster.columnStep() : raster.rowStep()) * pixelSize);
    across = float(std::fabs(columnMajor ? raster.rowStep() : raster.columnStep()) * pixelSize);
    const int size = raster.majorSize();
    keys.resize(std::size_t(size));
    if (size == 0) return;
    // A forward walk runs against the direction: from the last major index when it points forward.
    const bool backward = raster.majorStep() > 0;
    const int start = raster.offset(backward ? size - 1 : 0);
    for (int a = 0; a < size; ++a) {
        const int step = backward ? size - 1 - a : a;
        const int moves = std::abs(raster.offset(a) - start);
        keys[std::size_t(a)] = std::int32_t(moves) * 65536 + std::int32_t(step);
    }
}

HorizonBand::HorizonBand(int longestLine)
    : m_heights(std::size_t(longestLine) * kLines), m_values(m_heights.size()), m_keys(std::size_t(longestLine)),
      m_offsets(std::size_t(longestLine)), m_inside(std::size_t(longestLine)), m_stacks(longestLine)
{
}

void HorizonBand::prepare(const DirectionRaster& raster, const WalkGeometry& geometry, int firstLine, int count,
                          const BandSource& source)
{
    m_source = source;
    const int intercept = raster.intercept(firstLine);
    const auto [f0, l0] = raster.lineSpan(firstLine);
    const auto [f1, l1] = raster.lineSpan(firstLine + count - 1);
    const int first = std::min(f0, f1), last = std::max(l0, l1);
    m_steps = last - first;
    const bool backward = raster.majorStep() > 0; // steps in the order of a forward walk
    for (int s = 0; s < m_steps; ++s) {
        const int a = backward ? last - 1 - s : first + s;
        const int b0 = intercept + raster.offset(a); // minor index of lane 0
        const int lo = std::max(0, -b0), hi = std::min(count, raster.minorSize() - b0);
        m_keys[std::size_t(s)] = geometry.keys[std::size_t(a)];
        m_offsets[std::size_t(s)] = std::int64_t(a) * std::int64_t(source.stride) + b0;
        m_inside[std::size_t(s)] = lo < hi ? std::uint16_t(((1u << (hi - lo)) - 1u) << lo) : std::uint16_t(0);
    }
}

void HorizonBand::walk(GroupKernel kernel, const WalkGeometry& geometry, bool reverse, WalkOutput output,
                       HorizonValue value, float* sum)
{
    GroupWalk w;
    w.source = m_source.heights;
    w.offsets = m_offsets.data();
    w.inside = m_inside.data();
    w.heights = m_heights.data();
    w.values = m_values.data();
    w.sum = sum;
    w.keys = m_keys.data();
    w.steps = m_steps;
    w.reverse = reverse;
    w.fromSource = !reverse;
    w.output = output;
    w.value = value;
    w.along = geometry.along;
    w.across = geometry.across;
    kernel(w, m_stacks);
}

} // namespace stylos::core::shading::detail
