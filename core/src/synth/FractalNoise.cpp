#include "stylos/core/synth/FractalNoise.h"

#include <cassert>
#include <cmath>

namespace stylos::core::synth {
namespace {

std::uint64_t mix(std::uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double smooth(double t) { return t * t * (3.0 - 2.0 * t); }

} // namespace

FractalNoise::FractalNoise(std::uint64_t seed, double wavelength, double amplitude, int octaves)
    : m_seed(seed), m_frequency(1.0 / wavelength), m_amplitude(amplitude), m_octaves(octaves)
{
    assert(wavelength > 0.0 && octaves >= 1 && "FractalNoise::FractalNoise(): bad wavelength or octaves");
    double sum = 0.0;
    double a = std::fabs(amplitude);
    for (int o = 0; o < octaves; ++o, a *= 0.5) sum += a;
    m_bound = sum;
}

double FractalNoise::lattice(std::int64_t i, std::int64_t j, int octave) const
{
    const std::uint64_t h = mix(m_seed ^ (static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull)
                                ^ (static_cast<std::uint64_t>(j) * 0xC2B2AE3D27D4EB4Full)
                                ^ (static_cast<std::uint64_t>(octave) * 0x165667B19E3779F9ull));
    return static_cast<double>(h >> 11) * 0x1.0p-52 - 1.0; // [-1, 1)
}

double FractalNoise::octave(double x, double y, int o) const
{
    const double fx = std::floor(x);
    const double fy = std::floor(y);
    const auto i = static_cast<std::int64_t>(fx);
    const auto j = static_cast<std::int64_t>(fy);
    const double tx = smooth(x - fx);
    const double ty = smooth(y - fy);
    const double v00 = lattice(i, j, o);
    const double v10 = lattice(i + 1, j, o);
    const double v01 = lattice(i, j + 1, o);
    const double v11 = lattice(i + 1, j + 1, o);
    const double a = v00 + (v10 - v00) * tx;
    const double b = v01 + (v11 - v01) * tx;
    return a + (b - a) * ty;
}

double FractalNoise::value(double x, double y) const
{
    double sum = 0.0;
    double frequency = m_frequency;
    double amplitude = m_amplitude;
    for (int o = 0; o < m_octaves; ++o) {
        // Each octave is shifted so the lattices of different octaves do not line up.
        sum += amplitude * octave(x * frequency + 0.37 * o, y * frequency + 0.71 * o, o);
        frequency *= 2.0;
        amplitude *= 0.5;
    }
    return sum;
}

} // namespace stylos::core::synth
