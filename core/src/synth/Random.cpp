#include "stylos/core/synth/Random.h"

#include <cmath>
#include <numbers>

namespace stylos::core::synth {

std::uint64_t Random::derive(std::uint64_t seed, std::uint64_t stream)
{
    std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (stream + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double Random::normal()
{
    if (m_hasSpare) {
        m_hasSpare = false;
        return m_spare;
    }
    const double u1 = 1.0 - uniform(); // (0, 1]: log is finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * std::numbers::pi * u2;
    m_spare = radius * std::sin(angle);
    m_hasSpare = true;
    return radius * std::cos(angle);
}

Eigen::Vector3d Random::unitVector()
{
    for (;;) {
        const Eigen::Vector3d v(normal(), normal(), normal());
        const double n = v.norm();
        if (n > 1e-9) return v / n;
    }
}

Eigen::Matrix3d Random::rotation()
{
    for (;;) {
        Eigen::Quaterniond q(normal(), normal(), normal(), normal());
        const double n = q.norm();
        if (n > 1e-9) {
            q.coeffs() /= n;
            return q.toRotationMatrix();
        }
    }
}

} // namespace stylos::core::synth
