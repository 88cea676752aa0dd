#pragma once
/** @file
 * @brief A fragment's placement read in the drum frame (DrumFrame), with the unknowns DockRegistration solves
 *        for as absolute values: θ, the azimuth of the fragment's centre about the drum axis (from the frame's
 *        e1); z, its height along the axis (from the frame's origin); r, its distance from the axis; and its
 *        orientation relative to the cylindrical frame that turns with θ (u_r radial, u_t tangential, d the
 *        axis at the centre): R_cyl = Rz(θ)ᵀ · R = Ry(tiltLean) · Rx(tiltRoll) · Rz(spin) in (u_r, u_t, d)
 *        coordinates. tiltLean turns the piece about u_t through its centre (leans it in or out), tiltRoll about
 *        u_r (turns its flutes sideways) — DockUnknown::TiltLean and TiltRoll; spin, its turn about its own
 *        line parallel to the axis, is what θ carries along (a fragment cut from the drum's design in the drum's
 *        frame reads spin = −θ, tilts 0). The tangential offset of DockRegistration is 0 here by definition:
 *        the centre's azimuth is θ.
 *
 * Changing one value and placing again (placeInDrumFrame) keeps the others exactly (to rounding): θ turns the
 * fragment rigidly about the drum axis, z slides it along, r moves it along u_r, a tilt turns it about its
 * centre. Units: metres, radians; θ and spin in (−π, π], tiltRoll in [−π/2, π/2]. At tiltRoll = ±π/2 the spin
 * is 0 and the lean takes the rest. Thread-safety: pure functions.
 */
#include "stylos/core/dock/DockRegistration.h"
#include "stylos/core/dock/FluteModel.h"

#include <Eigen/Geometry>

namespace stylos::core::dock {

struct DrumFramePose {
    double theta = 0.0;    ///< radians about the drum axis, from the frame's e1
    double z = 0.0;        ///< metres along the axis, from the frame's origin
    double r = 0.0;        ///< metres from the axis
    double tiltLean = 0.0; ///< radians about u_t
    double tiltRoll = 0.0; ///< radians about u_r
    double spin = 0.0;     ///< radians about the axis direction, in the turning frame

    /** @brief The value of @p unknown (Theta, Z, R, TiltLean, TiltRoll; Tangent is 0). */
    double value(DockUnknown unknown) const;
    /** @brief Sets @p unknown (Tangent: no change). */
    void set(DockUnknown unknown, double value);
};

/** @brief The placement of the fragment whose centre is @p centre (its own frame) when @p pose (its own
 *         frame → the frame @p frame is expressed in) places it. */
DrumFramePose drumFramePose(const DrumFrame& frame, const Eigen::Isometry3d& pose, const Eigen::Vector3d& centre);

/** @brief The inverse: the pose (fragment frame → @p frame's frame) that places the fragment's @p centre and
 *         orientation as @p value says. */
Eigen::Isometry3d placeInDrumFrame(const DrumFrame& frame, const DrumFramePose& value, const Eigen::Vector3d& centre);

} // namespace stylos::core::dock
