#pragma once
/** @file
 * @brief An omphalos after the Delphi stone: an ovoid (egg-shaped surface of revolution, about 1.2 m
 *        high with its base) covered by a raised net (the agrenon: two families of crossing bands
 *        forming a lozenge lattice, each band a rounded ridge standing proud of the ovoid), set on a
 *        cylindrical plinth. The whole visible surface is one meridian (up the plinth side, in along its
 *        top, up the ovoid to the apex) revolved about +z; z = 0 at the plinth's bottom.
 *        Units: metres, radians. Immutable once built; thread-safe.
 */
#include "stylos/core/synth/SurfacePatch.h"
#include "stylos/core/synth/SyntheticObject.h"

#include <memory>
#include <vector>

namespace stylos::core::synth {

class Random;

/** @brief Every number that defines an omphalos. */
struct OmphalosParameters {
    double plinthRadius = 0.5;     ///< metres
    double plinthHeight = 0.12;    ///< metres
    double semiAxis = 0.675;       ///< vertical semi-axis of the egg, metres
    double radius = 0.42;          ///< horizontal semi-axis of the egg, metres
    double asymmetry = 0.12;       ///< > 0: narrower towards the apex
    double cut = -0.6;             ///< the egg is cut at w = cut·semiAxis (w from its centre) and set on the plinth
    int meshesAround = 16;         ///< lozenges of the net around the ovoid
    double bandHeight = 0.005;     ///< how far the net's bands stand proud of the ovoid, metres
    double bandHalfWidth = 0.012;  ///< metres
    double netBottom = 0.08;       ///< the net spans the meridian from this far above the plinth (metres)...
    double netTop = 0.18;          ///< ...to this far below the apex (metres, along the meridian)
    double netPhase = 0.0;         ///< azimuth of a crossing of the bands, radians

    /** Defaults with a random net phase drawn from @p random. */
    static OmphalosParameters random(Random& random);
};

class OmphalosShape final : public SyntheticObject {
public:
    explicit OmphalosShape(const OmphalosParameters& parameters);
    OmphalosShape(const OmphalosShape&) = delete; // its patch refers to it
    OmphalosShape& operator=(const OmphalosShape&) = delete;
    ~OmphalosShape() override;

    const OmphalosParameters& parameters() const { return m_p; }

    /** @brief A point of the bare meridian: radius, height and outward unit normal in the (r, z) plane. */
    struct MeridianPoint {
        double r, z, nr, nz;
    };
    /** The bare meridian at arc length @p s from the plinth's bottom edge (clamped to the meridian). */
    MeridianPoint meridian(double s) const;
    double meridianLength() const { return m_length; }
    /** Arc length where the ovoid begins (the plinth's inner top edge), metres. */
    double bodyStart() const { return m_bodyStart; }
    /** Radius of the bare ovoid at height @p z (0 outside it), metres. */
    double bodyRadius(double z) const;
    /** How far the net stands proud of the ovoid at (θ, s), metres (≥ 0). */
    double netHeight(double theta, double s) const;

    std::vector<const SurfacePatch*> patches() const override;
    Eigen::Vector3d scanCentre() const override;
    double extent() const override { return m_p.plinthRadius; }
    double height() const override;
    void describe(nlohmann::json& truth) const override;

private:
    class Patch;

    OmphalosParameters m_p;
    std::vector<MeridianPoint> m_table; ///< the meridian at uniform arc length steps
    double m_step = 0.0;
    double m_length = 0.0;
    double m_bodyStart = 0.0;
    double m_meshLength = 0.0;          ///< lozenge length along the meridian, metres
    std::unique_ptr<Patch> m_patch;
};

} // namespace stylos::core::synth
