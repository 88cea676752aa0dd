#pragma once
// Internal to the unroller: the azimuth of millions of points without a libm call per point, and the
// image column of a point exactly as UnrollMap::pixelOf() computes it.
#include "stylos/core/unroll/UnrollMap.h"

#include <cmath>

namespace stylos::core::unroll::detail {

/** Bound on |fastAtan2(y, x) − atan2(y, x)|, radians (measured worst 4.1e-8, rounding included). */
inline constexpr double kFastAtanError = 1e-7;

/** atan t ≈ t · P(t²) on [0, 1]: least squares on 4000 Chebyshev nodes, worst error 4.07e-8. */
inline constexpr double kFastAtan[8] = {0.99999943684314818,  -0.33330106677689053, 0.1994850898576743,
                                        -0.13915802260695628, 0.096562564704600701, -0.056063176729059659,
                                        0.021946611032579465, -0.0040733094644638613};

/**
 * @brief atan2(y, x) in [−π, π] within kFastAtanError, branch-free (loops over arrays of points
 *        vectorise), one division, no libm call: t = min/max ∈ [0, 1] of |x|, |y|, an odd polynomial of
 *        degree 15 in t, then the octant (π/2 − a when |y| > |x|, π − a when x is negative, −0
 *        included, the sign of y as atan2 gives it). (±0, ±0) gives NaN.
 */
inline double fastAtan2(double y, double x)
{
    constexpr double kPi = 3.141592653589793;
    const double ax = x < 0.0 ? -x : x, ay = y < 0.0 ? -y : y;
    const double t = (ax < ay ? ax : ay) / (ax < ay ? ay : ax);
    const double z = t * t;
    double p = kFastAtan[7];
    for (int k = 6; k >= 0; --k) p = p * z + kFastAtan[k];
    double a = t * p;
    a = ay > ax ? 0.5 * kPi - a : a;
    a = std::signbit(x) ? kPi - a : a;
    return std::copysign(a, y);
}

/**
 * @brief The azimuth of points on a map: an approximate angle for histograms and the exact column.
 *        Immutable; thread-safe.
 */
class UnrollAzimuth {
public:
    explicit UnrollAzimuth(const UnrollMap& map);

    /** Angle from the cut in [0, 2π) of a point with axialCoords (x, y), within kFastAtanError + 1e-15
     *  (0 for (0, 0)). Branch-free and inline, for loops over arrays. */
    double approxAngle(double x, double y) const
    {
        double angle = fastAtan2(y, x) - m_cut; // (−3π, π]: the cut is in [0, 2π)
        angle += angle < 0.0 ? kTwoPi : 0.0;
        angle += angle < 0.0 ? kTwoPi : 0.0;
        return angle < kTwoPi ? angle : 0.0; // also NaN → 0
    }
    /** approxAngle() in columns (× R / s): within margin() of the exact continuous column. */
    double approxColumn(double x, double y) const { return approxAngle(x, y) * m_columnsPerRadian; }
    /**
     * The image column of a point with axialCoords (x, y) whose approxColumn() is @p approx:
     * floor(referenceRadius · map.angleFrom(x, y) / pixelSize), bit for bit what map.pixelOf() gives,
     * clamped to [0, width − 1]. Falls back to map.angleFrom() (libm) only when @p approx lies within
     * margin() of a column boundary or of the seam (a fraction of about 4e-7 · R / s of the points:
     * 0.05 % at R = 0.55 m, s = 0.5 mm).
     */
    int column(double x, double y, double approx) const
    {
        const double low = approx - m_margin, high = approx + m_margin;
        if (low >= 0.0 && high < m_period) {
            const int a = int(low), b = int(high); // floor: both are ≥ 0
            if (a == b) return a < m_lastColumn ? a : m_lastColumn;
        }
        return exactColumn(x, y);
    }
    int column(double x, double y) const { return column(x, y, approxColumn(x, y)); }
    /** Bound on |approxColumn() − exact continuous column|, columns. */
    double margin() const { return m_margin; }

private:
    static constexpr double kTwoPi = 6.283185307179586;
    int exactColumn(double x, double y) const;

    const UnrollMap& m_map;
    double m_cut;
    int m_lastColumn;
    double m_radius;
    double m_pixel;
    double m_columnsPerRadian; ///< R / s
    double m_period;           ///< columns per turn, 2π·R / s
    double m_margin;           ///< bound on |fast column − exact column|, columns
};

} // namespace stylos::core::unroll::detail
