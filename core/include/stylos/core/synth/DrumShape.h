#pragma once
/** @file
 * @brief A fluted column drum, after the Delphi "Dancers Column": a cylinder of radius R (to the
 *        fillets) and height H whose lateral surface carries N circular-arc flutes separated by narrow
 *        fillets (or sharp arrises), a band of claw-chisel tooth marks, and a broken-away region (a
 *        rough fracture cavity); both bed faces carry an optional anathyrosis (a smooth contact ring
 *        around a slightly recessed, rougher centre). Drum frame: axis along +z through the origin,
 *        z = 0 at the lower bed; azimuth θ counter-clockwise from +x. Units: metres, radians.
 *        Immutable once built; thread-safe.
 */
#include "stylos/core/synth/DrumPatches.h"
#include "stylos/core/synth/FractalNoise.h"
#include "stylos/core/synth/SyntheticObject.h"

#include <cstdint>
#include <memory>
#include <string>

namespace stylos::core::synth {

class Random;
struct SyntheticOptions;

/** @brief Every number that defines a drum. */
struct DrumParameters {
    double radius = 0.55;          ///< to the fillets, metres
    double height = 0.5;           ///< between the bed faces, metres
    int grooves = 48;              ///< flutes; 0: a plain cylinder
    double grooveDepth = 0.008;    ///< from the fillet circle to the bottom of a flute, metres
    double filletFraction = 0.1;   ///< share of the flute pitch taken by the fillet (0: sharp arrises)
    double groovePhase = 0.0;      ///< azimuth of the centre of groove 0, radians
    bool clawBand = true;
    double clawMin = 0.42;         ///< claw band, z range, metres
    double clawMax = 0.46;
    double clawDepth = 0.0003;     ///< depth of the tooth marks, metres
    double clawPitch = 0.003;      ///< spacing of the teeth, metres
    bool broken = true;
    double brokenCentre = 1.0;     ///< azimuth of the centre of the broken region, radians
    double brokenHalfAngle = 0.26; ///< half its angular extent, radians
    double brokenZMin = 0.1;       ///< its z range, metres
    double brokenZMax = 0.28;
    double brokenDepth = 0.035;    ///< depth of the cavity at its centre, from the fillet circle, metres
    double fractureRoughness = 0.004; ///< amplitude of the coarsest octave of the fracture, metres
    bool anathyrosis = true;
    double ringWidth = 0.08;       ///< width of the smooth contact ring, metres
    double recess = 0.002;         ///< depth of the recessed centre of a bed face, metres
    double bedRoughness = 0.0004;  ///< amplitude of the point-dressing in the recess, metres
    std::uint64_t noiseSeed = 1;   ///< seed of the fracture and dressing noise
    /** Radius lost from the lower bed to the upper one, metres (a tapering drum: a cone's frustum whose
     *  cross-section at height z is the lower bed's scaled by scaleAt(z)); 0: a cylinder. */
    double taper = 0.0;

    /** Defaults scaled to the options' radius, height, groove count and depth, random phase and broken
     *  region drawn from @p random. Does not validate. */
    static DrumParameters fromOptions(const SyntheticOptions& options, Random& random);
    /** Empty when the parameters make a drum; otherwise what is wrong, e.g. "groove depth ...". */
    std::string problem() const;
};

class DrumShape final : public SyntheticObject {
public:
    explicit DrumShape(const DrumParameters& parameters);
    DrumShape(const DrumShape&) = delete; // its patches refer to it
    DrumShape& operator=(const DrumShape&) = delete;

    const DrumParameters& parameters() const { return m_p; }

    /** Radius of the fluted outline (flutes only) at azimuth @p theta, metres. */
    double fluteRadius(double theta) const;
    /** Radius of the lateral surface (flutes, claw marks, broken region) at (θ, z), metres. */
    double lateralRadius(double theta, double z) const;
    /** The cross-section's scale at height z: 1 − taper · z / (radius · height) (1 at the lower bed). */
    double scaleAt(double z) const { return 1.0 - m_p.taper * z / (m_p.radius * m_p.height); }
    /** How far below its plane (into the drum) a bed face lies at (x, y), metres (≥ 0). */
    double bedDepth(double x, double y, bool top) const;
    /** Deepest the lateral surface goes below the fillet circle anywhere, metres. */
    double maxLateralDepth() const;
    /** Whether @p p (drum frame) lies strictly inside the solid: bedDepth(x, y, false) < z <
     *  height − bedDepth(x, y, true) and hypot(x, y) < lateralRadius(atan2(y, x), z). */
    bool inside(const Eigen::Vector3d& p) const;

    std::vector<const SurfacePatch*> patches() const override;
    Eigen::Vector3d scanCentre() const override { return {0.0, 0.0, 0.5 * m_p.height}; }
    double extent() const override { return m_p.radius; }
    double height() const override { return m_p.height; }
    void describe(nlohmann::json& truth) const override;

    /** The drum's own truth object ("radius", "grooves", "clawBand", "broken", "anathyrosis"...). */
    nlohmann::json drumTruth() const;

private:
    double clawMarks(double theta, double z) const;
    double cavityRadius(double theta, double z) const;

    DrumParameters m_p;
    double m_pitch = 0.0;          ///< angle between groove centres
    double m_halfWidth = 0.0;      ///< half the angular width of a groove
    double m_arcCentre = 0.0;      ///< distance from the axis to the centre of a groove's arc
    double m_arcRadius = 0.0;
    FractalNoise m_fracture;
    FractalNoise m_dressing;
    std::unique_ptr<DrumLateralPatch> m_lateral;
    std::unique_ptr<DrumBedPatch> m_bottom;
    std::unique_ptr<DrumBedPatch> m_top;
};

} // namespace stylos::core::synth
