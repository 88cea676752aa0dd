#include "stylos/core/scene/Pose.h"

#include <cmath>
#include <cstddef>
#include <numbers>

namespace stylos::core::scene {

namespace {

using Matrix3 = std::array<std::array<double, 3>, 3>;

Matrix3 rotationFromAngles(const std::array<double, 3>& a)
{
    const double ca = std::cos(a[0]), sa = std::sin(a[0]);
    const double cb = std::cos(a[1]), sb = std::sin(a[1]);
    const double cc = std::cos(a[2]), sc = std::sin(a[2]);
    // Rz(c) · Ry(b) · Rx(a)
    return {{{cc * cb, cc * sb * sa - sc * ca, cc * sb * ca + sc * sa},
             {sc * cb, sc * sb * sa + cc * ca, sc * sb * ca - cc * sa},
             {-sb, cb * sa, cb * ca}}};
}

} // namespace

Pose Pose::translation(const std::array<double, 3>& t)
{
    return Pose().withTranslation(t);
}

Pose Pose::fromTranslationAngles(const TranslationAngles& value)
{
    return Pose().withAngles(value.angles).withTranslation(value.translation);
}

Pose Pose::withTranslation(const std::array<double, 3>& t) const
{
    Pose p = *this;
    p.m_m[3] = t[0];
    p.m_m[7] = t[1];
    p.m_m[11] = t[2];
    return p;
}

Pose Pose::withAngles(const std::array<double, 3>& angles) const
{
    Pose p = *this;
    const Matrix3 r = rotationFromAngles(angles);
    for (std::size_t row = 0; row < 3; ++row)
        for (std::size_t col = 0; col < 3; ++col) p.m_m[4 * row + col] = r[row][col];
    return p;
}

TranslationAngles Pose::toTranslationAngles() const
{
    const Pose& r = *this;
    TranslationAngles out;
    out.translation = translationPart();
    const double s = -r(2, 0);
    if (s >= 1.0 - 1e-12 || s <= -1.0 + 1e-12) {
        // Gimbal lock: only angles[2] − angles[0] (or their sum) is defined; put it all in angles[2].
        out.angles[1] = s > 0 ? std::numbers::pi / 2 : -std::numbers::pi / 2;
        out.angles[0] = 0.0;
        out.angles[2] = std::atan2(-r(0, 1), r(1, 1));
    } else {
        out.angles[1] = std::asin(s);
        out.angles[0] = std::atan2(r(2, 1), r(2, 2));
        out.angles[2] = std::atan2(r(1, 0), r(0, 0));
    }
    return out;
}

std::array<double, 3> Pose::apply(const std::array<double, 3>& p) const
{
    std::array<double, 3> out{};
    for (std::size_t row = 0; row < 3; ++row)
        out[row] = m_m[4 * row] * p[0] + m_m[4 * row + 1] * p[1] + m_m[4 * row + 2] * p[2] + m_m[4 * row + 3];
    return out;
}

Pose Pose::operator*(const Pose& other) const
{
    std::array<double, 16> out{};
    for (std::size_t row = 0; row < 4; ++row)
        for (std::size_t col = 0; col < 4; ++col) {
            double sum = 0;
            for (std::size_t k = 0; k < 4; ++k) sum += m_m[4 * row + k] * other.m_m[4 * k + col];
            out[4 * row + col] = sum;
        }
    return Pose(out);
}

Pose Pose::rigidInverse() const
{
    std::array<double, 16> out{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
    for (std::size_t row = 0; row < 3; ++row) {
        for (std::size_t col = 0; col < 3; ++col) out[4 * row + col] = m_m[4 * col + row];
        out[4 * row + 3] = -(m_m[row] * m_m[3] + m_m[4 + row] * m_m[7] + m_m[8 + row] * m_m[11]);
    }
    return Pose(out);
}

bool Pose::isRigid(double tolerance) const
{
    for (double v : m_m)
        if (!std::isfinite(v)) return false;
    if (m_m[12] != 0.0 || m_m[13] != 0.0 || m_m[14] != 0.0 || m_m[15] != 1.0) return false;
    const Pose& r = *this;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double dot = r(0, i) * r(0, j) + r(1, i) * r(1, j) + r(2, i) * r(2, j);
            if (std::abs(dot - (i == j ? 1.0 : 0.0)) > tolerance) return false;
        }
    const double det = r(0, 0) * (r(1, 1) * r(2, 2) - r(1, 2) * r(2, 1)) -
                       r(0, 1) * (r(1, 0) * r(2, 2) - r(1, 2) * r(2, 0)) +
                       r(0, 2) * (r(1, 0) * r(2, 1) - r(1, 1) * r(2, 0));
    return det > 0.0;
}

bool Pose::approxEqual(const Pose& other, double tolerance) const
{
    for (std::size_t i = 0; i < m_m.size(); ++i)
        if (!(std::abs(m_m[i] - other.m_m[i]) <= tolerance)) return false;
    return true;
}

} // namespace stylos::core::scene
