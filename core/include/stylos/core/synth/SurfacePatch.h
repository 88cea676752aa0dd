#pragma once
/** @file
 * @brief One piece of a synthetic object's surface, parameterised by (a, b), both roughly arc lengths
 *        in metres, so that a grid of step s in (a, b) samples the surface at about s. Rows are lines of
 *        constant b; each row has its own range of a (a disc's rows around its centre grow with the
 *        radius). Patches are immutable after construction and thread-safe.
 */
#include <Eigen/Core>

#include <cmath>
#include <numbers>

namespace stylos::core::synth {

/** @p angle (radians) brought into [-π, π]; cheaper than std::remainder. */
inline double wrapAngle(double angle)
{
    constexpr double twoPi = 2.0 * std::numbers::pi;
    return angle - twoPi * std::nearbyint(angle * (1.0 / twoPi));
}

/** @brief A closed range of a parameter, metres. @c wraps: the row is a full circle (a and a + length
 *         are the same point), sampled with an integer number of steps and no seam. */
struct ParameterRange {
    double min = 0.0;
    double max = 0.0;
    bool wraps = false;

    double length() const { return max - min; }
};

class SurfacePatch {
public:
    virtual ~SurfacePatch() = default;

    /** Range of the row parameter b, metres. */
    virtual ParameterRange rows() const = 0;
    /** Range of the column parameter a on row @p b, metres. */
    virtual ParameterRange columns(double b) const = 0;
    /**
     * Azimuth (radians) about the object's vertical scan axis of the undisplaced point (a, b); decides
     * which scans see it. Must be cheap: it is asked of every grid node of every scan.
     */
    virtual double azimuth(double a, double b) const = 0;
    /** k > 0 when azimuth(a, b) = k·a on row @p b exactly (a row around the scan axis), so a scan's
     *  window maps to a range of columns; 0 otherwise (each node is then tested). */
    virtual double azimuthScale(double /*b*/) const { return 0.0; }
    /** Position (metres, object frame) of (a, b). Defined also slightly outside the patch. */
    virtual Eigen::Vector3d position(double a, double b) const = 0;
    /** Whether the point (a, b) at @p p belongs to the patch (false where the patch is clipped). */
    virtual bool contains(double /*a*/, double /*b*/, const Eigen::Vector3d& /*p*/) const { return true; }
    /** Outward unit normal at (a, b); by default central differences of position(), moving along
     *  rows and across them with carry(). */
    virtual Eigen::Vector3d normal(double a, double b) const;

    /** The a on row @p to at the same fraction of the row as @p a on row @p from: on a surface of
     *  revolution, the same azimuth. Lets jitter and differences across rows keep the azimuth. */
    double carry(double a, double from, double to) const;

protected:
    /** +1 when ∂p/∂a × ∂p/∂b points out of the object, -1 when it points in. */
    double m_orientation = 1.0;
    /** Step of the central differences, metres. */
    double m_normalStep = 1e-4;
};

} // namespace stylos::core::synth
