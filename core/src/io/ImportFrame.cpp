#include "stylos/core/io/ImportFrame.h"

#include <algorithm>
#include <cctype>
#include <utility>

namespace stylos::core::io {

namespace {

/** R as a signed permutation: out[i] = sign[i] · in[source[i]]. */
struct SignedPermutation {
    std::array<int, 3> source;
    std::array<double, 3> sign;
};

SignedPermutation permutation(UpAxis up)
{
    switch (up) {
    case UpAxis::PosX: return {{2, 1, 0}, {-1.0, 1.0, 1.0}};   // (−z, y, x)
    case UpAxis::NegX: return {{2, 1, 0}, {1.0, 1.0, -1.0}};   // (z, y, −x)
    case UpAxis::PosY: return {{0, 2, 1}, {1.0, -1.0, 1.0}};   // (x, −z, y)
    case UpAxis::NegY: return {{0, 2, 1}, {1.0, 1.0, -1.0}};   // (x, z, −y)
    case UpAxis::NegZ: return {{0, 1, 2}, {1.0, -1.0, -1.0}};  // (x, −y, −z)
    case UpAxis::PosZ: break;
    }
    return {{0, 1, 2}, {1.0, 1.0, 1.0}};
}

constexpr std::pair<UpAxis, const char*> AxisNames[] = {
    {UpAxis::PosX, "+X"}, {UpAxis::NegX, "-X"}, {UpAxis::PosY, "+Y"},
    {UpAxis::NegY, "-Y"}, {UpAxis::PosZ, "+Z"}, {UpAxis::NegZ, "-Z"},
};

constexpr std::pair<LengthUnit, const char*> UnitNames[] = {
    {LengthUnit::Millimetre, "mm"}, {LengthUnit::Centimetre, "cm"}, {LengthUnit::Metre, "m"}};

std::string upper(std::string_view text)
{
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return out;
}

} // namespace

const char* upAxisName(UpAxis axis)
{
    for (const auto& [a, name] : AxisNames)
        if (a == axis) return name;
    return "+Z";
}

std::optional<UpAxis> upAxisFromName(std::string_view name)
{
    std::string text = upper(name);
    if (text.rfind("\xE2\x88\x92", 0) == 0) text.replace(0, 3, "-");  // U+2212 MINUS SIGN
    if (text.size() == 1) text.insert(text.begin(), '+');
    for (const auto& [a, axisName] : AxisNames)
        if (text == axisName) return a;
    return std::nullopt;
}

const char* lengthUnitName(LengthUnit unit)
{
    for (const auto& [u, name] : UnitNames)
        if (u == unit) return name;
    return "m";
}

std::optional<LengthUnit> lengthUnitFromName(std::string_view name)
{
    std::string text(name);
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const auto& [u, unitName] : UnitNames)
        if (text == unitName) return u;
    return std::nullopt;
}

double unitsPerMetre(LengthUnit unit)
{
    switch (unit) {
    case LengthUnit::Millimetre: return 1000.0;
    case LengthUnit::Centimetre: return 100.0;
    case LengthUnit::Metre: break;
    }
    return 1.0;
}

std::string upAxisChoices()
{
    return "+X, -X, +Y, -Y, +Z or -Z";
}

std::string lengthUnitChoices()
{
    return "mm, cm or m";
}

bool ImportFrame::isIdentity() const
{
    return up == UpAxis::PosZ && unit == LengthUnit::Metre && offset == std::array<double, 3>{0.0, 0.0, 0.0};
}

std::array<double, 9> ImportFrame::rotation() const
{
    const SignedPermutation r = permutation(up);
    std::array<double, 9> m{};
    for (int i = 0; i < 3; ++i) m[std::size_t(3 * i + r.source[i])] = r.sign[i];
    return m;
}

std::array<double, 3> ImportFrame::applyToPosition(const std::array<double, 3>& p) const
{
    std::array<double, 3> out = p;
    applyToPositions(out.data(), 1);
    return out;
}

std::array<float, 3> ImportFrame::applyToNormal(const std::array<float, 3>& n) const
{
    std::array<float, 3> out = n;
    applyToNormals(out.data(), 1);
    return out;
}

void ImportFrame::applyToPositions(double* xyz, std::size_t count) const
{
    const SignedPermutation r = permutation(up);
    const double scale = unitsPerMetre(unit);
    for (std::size_t i = 0; i < count; ++i, xyz += 3) {
        double local[3];
        for (int k = 0; k < 3; ++k) local[k] = (xyz[k] - offset[std::size_t(k)]) / scale;
        for (int k = 0; k < 3; ++k) xyz[k] = r.sign[std::size_t(k)] * local[r.source[std::size_t(k)]];
    }
}

void ImportFrame::applyToNormals(float* xyz, std::size_t count) const
{
    if (up == UpAxis::PosZ) return;
    const SignedPermutation r = permutation(up);
    for (std::size_t i = 0; i < count; ++i, xyz += 3) {
        const float local[3] = {xyz[0], xyz[1], xyz[2]};
        for (int k = 0; k < 3; ++k) xyz[k] = float(r.sign[std::size_t(k)]) * local[r.source[std::size_t(k)]];
    }
}

void ImportFrame::applyToBounds(std::array<double, 3>& min, std::array<double, 3>& max) const
{
    std::array<double, 3> a = applyToPosition(min), b = applyToPosition(max);
    for (std::size_t k = 0; k < 3; ++k) {
        min[k] = std::min(a[k], b[k]);
        max[k] = std::max(a[k], b[k]);
    }
}

} // namespace stylos::core::io
