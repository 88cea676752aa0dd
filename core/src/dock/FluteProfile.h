#pragma once
// The flutes of a drum seen as a periodic radial profile about its axis: the single-frequency sums that
// find the flute count and the phase, and the profile folded onto one flute pitch (median radius per
// bin) that refines the phase and gives the leading radius and the depth. Internal to core/dock.
// Units: metres, radians. Thread-safety: value types; the functions are reentrant.
#include <complex>
#include <cstddef>
#include <vector>

namespace stylos::core::dock {

/** @brief Lateral points of a drum: azimuth about the axis and distance from it. */
struct LateralSamples {
    std::vector<double> theta; ///< radians
    std::vector<double> rho;   ///< metres
    std::vector<double> t;     ///< along the axis from its point, metres (the taper's fit)
    std::size_t size() const { return theta.size(); }
};

/** @brief The strongest single frequency of the radial heights. */
struct FluteFrequency {
    int count = 0;          ///< N
    double phase = 0.0;     ///< first estimate of the bottom of flute 0, in [0, 2π/N)
    double amplitude = 0.0; ///< |S_N| / n, metres
    double noise = 0.0;     ///< √(Σ h²) / n, metres: |S| of a profile with no flutes
    double medianAmplitude = 0.0; ///< median over the scanned N of |S_N| / n
};

/** S_N = Σ h·e^(−iNθ) over @p samples (h = ρ − @p medianRho) for N in [@p minCount, @p maxCount] using at
 *  most @p maxPoints of them (fixed stride); the N with the largest |S_N|. */
FluteFrequency strongestFrequency(const LateralSamples& samples, double medianRho, int minCount, int maxCount,
                                  std::size_t maxPoints);

/** @brief Median radius per bin of the azimuth folded onto one flute pitch, centred on a flute bottom. */
class FluteProfile {
public:
    static constexpr int Bins = 64;

    /** Folds @p samples with @p count flutes whose flute 0 bottom is at azimuth @p phase. */
    FluteProfile(const LateralSamples& samples, int count, double phase);

    /** The bottom's offset from the phase, by a parabola through the bins within a quarter pitch. */
    double bottomOffset() const;
    /** Mean of the 3 highest bin medians: the fillets' radius, metres. */
    double leadingRadius() const;
    /** Mean of the two bins beside the bottom, metres. */
    double bottomRadius() const;
    /** The profile at folded offset @p phi from the bottom (linear between bin centres, periodic). */
    double at(double phi) const;
    /** The median radius of each bin (NaN where a bin is empty), metres. */
    const std::vector<double>& medians() const { return m_median; }
    /** Offset of azimuth @p theta from the nearest flute bottom, in [−pitch/2, pitch/2). */
    double fold(double theta) const;

private:
    double m_pitch;
    double m_phase;
    std::vector<double> m_median; ///< per bin; bin b covers [−pitch/2 + b·w, −pitch/2 + (b+1)·w)
};

} // namespace stylos::core::dock
