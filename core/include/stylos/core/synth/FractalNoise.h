#pragma once
/** @file
 * @brief Deterministic 2D fractal value noise (fBm) for rough surfaces: fracture faces, point-dressed
 *        bed faces. A hashed integer lattice, smooth-step interpolation, several octaves halving the
 *        wavelength and the amplitude. Pure function of its seed and arguments; thread-safe.
 */
#include <cstdint>

namespace stylos::core::synth {

class FractalNoise {
public:
    /**
     * @param seed        any value; different seeds give unrelated fields
     * @param wavelength  of the coarsest octave, metres (> 0)
     * @param amplitude   of the coarsest octave, metres
     * @param octaves     number of octaves (≥ 1)
     */
    FractalNoise(std::uint64_t seed, double wavelength, double amplitude, int octaves);

    /** Displacement at (x, y) (metres), within ±bound(). */
    double value(double x, double y) const;
    /** Largest |value()| possible, metres. */
    double bound() const { return m_bound; }

private:
    double lattice(std::int64_t i, std::int64_t j, int octave) const;
    double octave(double x, double y, int octave) const;

    std::uint64_t m_seed;
    double m_frequency;
    double m_amplitude;
    int m_octaves;
    double m_bound;
};

} // namespace stylos::core::synth
