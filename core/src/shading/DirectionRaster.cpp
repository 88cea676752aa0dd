#include "stylos/core/shading/DirectionRaster.h"

#include <cmath>

namespace stylos::core::shading {

DirectionRaster::DirectionRaster(int width, int height, double azimuth)
    : m_azimuth(azimuth), m_width(width), m_height(height), m_dc(std::sin(azimuth)), m_dr(-std::cos(azimuth))
{
    assert(width >= 0 && height >= 0 && std::isfinite(azimuth) && "DirectionRaster: bad size or azimuth");
    m_columnMajor = std::fabs(m_dc) >= std::fabs(m_dr);
    const double major = m_columnMajor ? m_dc : m_dr, minor = m_columnMajor ? m_dr : m_dc;
    m_majorStep = major > 0.0 ? 1 : -1;
    m_minorSize = m_columnMajor ? height : width;
    const int majorSize = m_columnMajor ? width : height;
    // Rounded to a multiple of 2^-32 so that a and a + π (whose sines and cosines differ by rounding)
    // give the same lines, and so that a · slope is exact for every major index (< 2^15).
    const double slope = std::round(minor / major * 0x1p32) * 0x1p-32;
    m_offsets.resize(std::size_t(majorSize));
    for (int a = 0; a < majorSize; ++a) m_offsets[std::size_t(a)] = int(std::floor(a * slope + 0.5));
    const int end = majorSize > 0 ? m_offsets.back() : 0; // offsets run monotonically from 0 to end
    m_firstLine = -std::max(0, end);
    m_lineCount = majorSize > 0 && m_minorSize > 0 ? m_minorSize + std::abs(end) : 0;
}

std::pair<int, int> DirectionRaster::majorRange(int i) const
{
    // Pixel (a, i + offset(a)) is inside when 0 <= i + offset(a) <= minorSize - 1.
    const int low = -i, high = m_minorSize - 1 - i;
    const auto begin = m_offsets.begin(), end = m_offsets.end();
    const bool increasing = m_offsets.empty() || m_offsets.back() >= 0;
    if (increasing) {
        const auto first = std::partition_point(begin, end, [&](int o) { return o < low; });
        const auto last = std::partition_point(first, end, [&](int o) { return o <= high; });
        return {int(first - begin), int(last - begin)};
    }
    const auto first = std::partition_point(begin, end, [&](int o) { return o > high; });
    const auto last = std::partition_point(first, end, [&](int o) { return o >= low; });
    return {int(first - begin), int(last - begin)};
}

} // namespace stylos::core::shading
