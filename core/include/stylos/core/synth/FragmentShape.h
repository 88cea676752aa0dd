#pragma once
/** @file
 * @brief A fragment broken off a fluted drum: a wedge-like piece spanning an angular sector of the
 *        drum's lateral surface, from a broken lower face up to the drum's upper bed face, and inwards
 *        to a broken inner face. The four fracture faces are rough (fractal noise displacement along
 *        their normals); each face is sampled only where the point lies inside all the others, so the
 *        piece closes. Object frame: the parent drum's frame (axis +z through the origin, z = 0 at its
 *        lower bed). Units: metres, radians. Immutable once built; thread-safe.
 */
#include "stylos/core/synth/DrumShape.h"
#include "stylos/core/synth/FractalNoise.h"
#include "stylos/core/synth/SyntheticObject.h"

#include <array>
#include <memory>

namespace stylos::core::synth {

class Random;

/** @brief Where the piece was in its drum. */
struct FragmentParameters {
    double thetaCentre = 0.0;   ///< azimuth of the sector's middle, radians (drum frame)
    double halfAngle = 0.436;   ///< half the sector, radians (≈ 25°)
    double zMin = 0.225;        ///< nominal height of the lower fracture face, metres
    double thickness = 0.18;    ///< nominal radial depth of the piece from the fillet circle, metres
    double roughness = 0.006;   ///< amplitude of the coarsest octave of the fracture faces, metres
    std::uint64_t noiseSeed = 1;

    /** Scaled to @p drum, with a random sector and noise seed drawn from @p random. */
    static FragmentParameters random(const DrumParameters& drum, Random& random);
};

class FragmentShape final : public SyntheticObject {
public:
    /** The faces of the piece. */
    enum class Face { Outer, Top, SideLow, SideHigh, Inner, Bottom, None /* no face: all are tested */ };

    FragmentShape(const DrumParameters& drum, const FragmentParameters& fragment);
    FragmentShape(const FragmentShape&) = delete; // its patches refer to it
    FragmentShape& operator=(const FragmentShape&) = delete;
    ~FragmentShape() override;

    const DrumShape& drum() const { return m_drum; }
    const FragmentParameters& parameters() const { return m_f; }

    /** Whether @p p (drum frame) lies inside the piece, ignoring the face @p except (the one @p p was
     *  generated on, so rounding cannot drop it). */
    bool inside(const Eigen::Vector3d& p, Face except) const;
    /** Whether @p p (drum frame) lies inside the piece: inside every face (the solid of the analytic
     *  skydome, AnalyticSkydome.h). */
    bool inside(const Eigen::Vector3d& p) const { return inside(p, Face::None); }
    /** Radius of the nominal inner fracture face, metres. */
    double innerRadius() const { return m_drum.parameters().radius - m_f.thickness; }
    /** A point of fracture face @p face (SideLow, SideHigh, Inner or Bottom) at parameters (a, b). */
    Eigen::Vector3d fracturePoint(Face face, double a, double b) const;
    /** Largest displacement of a fracture face from its nominal surface, metres. */
    double fractureBound() const { return m_sideLow.bound(); }

    std::vector<const SurfacePatch*> patches() const override;
    Eigen::Vector3d scanCentre() const override;
    double extent() const override;
    double height() const override { return m_drum.parameters().height; }
    void describe(nlohmann::json& truth) const override;

private:
    class FracturePatch;

    DrumShape m_drum;
    FragmentParameters m_f;
    FractalNoise m_sideLow;
    FractalNoise m_sideHigh;
    FractalNoise m_inner;
    FractalNoise m_bottom;
    std::unique_ptr<DrumLateralPatch> m_outer;
    std::unique_ptr<DrumBedPatch> m_top;
    std::array<std::unique_ptr<FracturePatch>, 4> m_fractures;
};

} // namespace stylos::core::synth
