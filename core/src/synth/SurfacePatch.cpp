#include "stylos/core/synth/SurfacePatch.h"

#include <Eigen/Geometry>

namespace stylos::core::synth {

Eigen::Vector3d SurfacePatch::normal(double a, double b) const
{
    const double h = m_normalStep;
    const Eigen::Vector3d da = position(a + h, b) - position(a - h, b);
    const Eigen::Vector3d db = position(carry(a, b, b + h), b + h) - position(carry(a, b, b - h), b - h);
    const Eigen::Vector3d n = m_orientation * da.cross(db);
    const double length = n.norm();
    return length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::UnitZ();
}

double SurfacePatch::carry(double a, double from, double to) const
{
    const ParameterRange source = columns(from);
    const ParameterRange target = columns(to);
    if (source.length() <= 0.0) return target.min;
    return target.min + (a - source.min) * (target.length() / source.length());
}

} // namespace stylos::core::synth
