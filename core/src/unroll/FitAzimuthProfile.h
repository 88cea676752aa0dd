#pragma once
// Internal to the surface fit: the radial profile around the axis (flutes), subtracted from the
// residuals so that trimming works at the scale of the noise rather than of the flutes.
#include <Eigen/Core>
#include <algorithm>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace stylos::core::unroll::detail {

/**
 * @brief f(φ): the median radial residual as a function of the azimuth φ about the axis, in B equal bins
 *        of fastAngle() (a cheap monotone stand-in for atan2), linearly interpolated between bin centres, with its mean
 * and first harmonics (cos φ, sin φ) over the points removed — those are the radius and the axis position, which the
 * fit itself must find, so f cannot absorb them. A fluted drum's flutes are such a profile; subtracting it leaves the
 * noise, so the trimming threshold comes down to a few σ of the noise and the rim of a broken cavity (shallower than
 * the flutes) no longer passes as inliers and pulls the axis. Disabled (f = 0) unless nearly all bins of the covered
 * arc (the circle less its longest run of empty bins; at least 8 % of it, a fragment's outer face) hold points. Immutable between estimate() calls; value() is thread-safe.
 */
class FitAzimuthProfile {
  public:
    /** An approximation of atan2(y, x) mod 2π in [0, 2π), within 0.004 rad of it and strictly monotone
     *  in it (so bins of it are bins of azimuth), at the cost of one division; 0 at the origin. */
    static double fastAngle(double x, double y)
    {
        constexpr double pi = 3.14159265358979323846;
        const double ax = std::abs(x), ay = std::abs(y);
        const double z = std::min(ax, ay) / std::max(std::max(ax, ay), 1e-300);
        double a = z * (0.25 * pi + 0.273 * (1.0 - z)); // atan(z) on [0, 1], monotone
        // Octants without branches (points come in no order): selections as 0/1 factors.
        a += double(ay > ax) * (0.5 * pi - 2.0 * a);
        a += double(x < 0.0) * (pi - 2.0 * a);
        a += double(y < 0.0) * (2.0 * pi - 2.0 * a);
        return a * double(a < 2.0 * pi);
    }
    /** The true azimuth (radians) whose fastAngle() is @p a (bisection). */
    static double trueAngle(double a);

    bool enabled() const { return !m_values.empty(); }
    int bins() const { return int(m_values.size()); }
    /** f at fastAngle() @p a, metres; 0 when disabled. */
    double value(double a) const
    {
        return m_values.empty() ? 0.0 : interpolate(m_values.data(), m_slopes.data(), bins(), m_perRadian, a);
    }

    /** The raw tables, for a per-point loop that interpolates itself (interpolate()). */
    const double* values() const { return m_values.data(); }
    const double* slopes() const { return m_slopes.data(); }
    double perRadian() const { return m_perRadian; }

    /** f at fastAngle() @p a from the tables: values at the bin centres, slopes to the next one. */
    static double interpolate(const double* values, const double* slopes, int bins, double perRadian, double a)
    {
        const double x = a * perRadian - 0.5; // in [−0.5, bins − 0.5)
        int i = int(x + 1.0) - 1;             // floor(x), x > −1
        const double fraction = x - i;
        i += bins * int(i < 0);
        return values[i] + fraction * slopes[i];
    }

    /**
     * @brief Sets f from (bin, residual) samples over @p bins bins: the median per bin, empty bins (fewer
     *        than 5 samples) interpolated around the circle, then the least-squares fit of
     *        a + b·cos φ + c·sin φ weighted by the bins' samples removed (so that f sums to about zero
     *        over the points, and the radius stays their least-squares radius). Disables the profile
     *        when the covered arc (the circle less its longest run of empty bins) is under 8 % of the
     *        circle or fewer than @p coverage of its bins hold samples.
     * @return the RMS change of f over the bins, metres (the previous profile counting as 0 when disabled).
     */
    double estimate(int bins, const std::vector<std::pair<std::uint32_t, float>>& samples, double coverage);
    void disable()
    {
        m_values.clear();
        m_slopes.clear();
    }
    /** f(−φ): for the same points seen about the reversed axis. */
    void mirror()
    {
        std::reverse(m_values.begin(), m_values.end());
        setSlopes();
    }

  private:
    void setSlopes();

    std::vector<double> m_values;
    std::vector<double> m_slopes; ///< m_values[b + 1] − m_values[b], around the circle
    double m_perRadian = 0.0;     ///< bins / 2π
    // The harmonics' basis at the bin centres, for m_basisBins bins.
    std::vector<Eigen::Vector3d> m_basis;
    int m_basisBins = 0;
};

} // namespace stylos::core::unroll::detail
