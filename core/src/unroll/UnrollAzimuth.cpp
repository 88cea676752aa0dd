#include "UnrollAzimuth.h"

#include <algorithm>
#include <cmath>

namespace stylos::core::unroll::detail {

UnrollAzimuth::UnrollAzimuth(const UnrollMap& map)
    : m_map(map), m_cut(map.cutAngle()), m_lastColumn(map.width() - 1),
      m_radius(map.surface().referenceRadius()), m_pixel(map.pixelSize()), m_columnsPerRadian(m_radius / m_pixel),
      m_period(map.circumference() / map.pixelSize())
{
    // The fast angle is off by kFastAtanError plus the rounding of the reduction and the wrap (a few
    // ulp of 2π); the column by that times R / s plus the rounding of the products and the quotient
    // (a few ulp of the column). Doubled for safety.
    m_margin = 2.0 * ((kFastAtanError + 1e-14) * m_columnsPerRadian + 1e-14 * m_period);
}

int UnrollAzimuth::exactColumn(double x, double y) const
{
    const double exact = std::floor(m_radius * m_map.angleFrom(x, y) / m_pixel);
    return int(std::clamp(exact, 0.0, double(m_lastColumn)));
}

} // namespace stylos::core::unroll::detail
