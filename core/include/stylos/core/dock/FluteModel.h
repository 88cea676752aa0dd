#pragma once
/** @file
 * @brief The guides' flute profile as a smooth periodic surface about the drum axis: the distance from
 *        the axis ρ = P(φ) as a function of the azimuth φ, what a fragment's outer face is registered
 *        against (no kd-tree, O(1) per point). P is the Fourier series of the guides' 64-bin profile
 *        (DrumGuides::profile) up to harmonic 12 of the flute frequency: smooth, with an exact derivative,
 *        and within the bins' medians by the profile's own detail (a circular-arc flute with fillets is
 *        reproduced within 0.1 mm). Coordinates are the drum frame's (DrumFrame): azimuth from the guides'
 *        reference direction about the axis, z along it from the axis point. A tapering drum (guides with a
 *        radius slope) is the cone ρ = (1 + τ·z)·P(φ), τ = slope / radius: the axis point's cross-section
 *        scaled with the height. Units: metres, radians. Immutable; thread-safe.
 */
#include "stylos/core/dock/DrumGuides.h"
#include "stylos/core/util/Result.h"

#include <Eigen/Core>

#include <complex>
#include <vector>

namespace stylos::core::dock {

/** @brief The drum's frame: origin on the axis (the guides' axis point), e1 (azimuth 0), e2, axis d. */
struct DrumFrame {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    Eigen::Matrix3d rows = Eigen::Matrix3d::Identity(); ///< rows e1, e2, d: world → frame rotation

    explicit DrumFrame(const DrumGuides& guides);
    /** The frame of an axis alone (a drum's Axis guide): e1 = unroll::defaultReferenceDir(d), as the fitted
     *  guides' reference (so azimuths read the same as theirs and the développée's). */
    explicit DrumFrame(const unroll::Axis& axis);
    DrumFrame() = default;
    Eigen::Vector3d toFrame(const Eigen::Vector3d& world) const { return rows * (world - origin); }
    Eigen::Vector3d toWorld(const Eigen::Vector3d& frame) const { return origin + rows.transpose() * frame; }
};

class FluteModel {
public:
    static constexpr int Harmonics = 12;

    /** From @p guides (flutes ≥ 3, a full profile). InvalidArgument otherwise. */
    static Result<FluteModel> fromGuides(const DrumGuides& guides);

    int flutes() const { return m_flutes; }
    double pitch() const { return m_pitch; }
    double phase() const { return m_phase; }     ///< azimuth of flute 0's bottom
    double meanRadius() const { return m_mean; } ///< P's mean: the cylinder of the flutes' mean radius
    double depth() const { return m_depth; }     ///< max P − min P
    /** P(φ) and dP/dφ at azimuth @p phi: the cross-section at the axis point. */
    double radius(double phi, double* slope = nullptr) const;
    /** τ: the relative change of the cross-section per metre along the axis (0 for a cylinder). */
    double taper() const { return m_taper; }
    /** The cross-section's scale at height @p z: 1 + τ·z. */
    double scaleAt(double z) const { return 1.0 + m_taper * z; }
    /** Signed distance of the drum-frame point @p p from the surface ρ = scaleAt(z)·P(φ), to first order
     *  (the implicit function over its gradient's length), positive outside; @p normal: the unit outward
     *  normal there. */
    double distance(const Eigen::Vector3d& p, Eigen::Vector3d* normal = nullptr) const;
    /** Σ P(φ)·e^(−iNφ) over one period, normalised by the sample count: the flutes' fundamental, whose
     *  argument places the bottoms the way a fragment's own sum does (FluteSnap). */
    std::complex<double> fundamental() const { return m_fundamental; }

private:
    int m_flutes = 0;
    double m_pitch = 0.0, m_phase = 0.0, m_mean = 0.0, m_depth = 0.0, m_taper = 0.0;
    std::vector<std::complex<double>> m_coefficients; ///< c_k, k = 1..Harmonics: P = mean + 2 Re Σ c_k e^(ikN(φ−phase))
    std::complex<double> m_fundamental;
};

} // namespace stylos::core::dock
