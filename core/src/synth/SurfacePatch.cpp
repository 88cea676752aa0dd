#include "stylos/core/synth/SurfacePatch.h"

#include <Eigen/Geometry>

namespace stylos::core::synth {

Eigen::Vector3d SurfacePatch::normal(double a, double b) const
{
    const double h = m_normalStep;
    const Eigen::Vector3d da = position(a + h, b) - position(a - h, b);
    const Eigen::Vector3d db = position(a, b + h) - position(a, b - h);
    const Eigen::Vector3d n = m_orientation * da.cross(db);
    const double length = n.norm();
    return length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::UnitZ();
}

} // namespace stylos::core::synth
