#pragma once
/** @file
 * @brief The patches of a drum's surface: the lateral (fluted) surface over a range of azimuth and
 *        height, and a bed face (a disc, or a sector of an annulus for a fragment). An optional clip
 *        keeps only the points inside a solid (a fragment). Parameters: lateral a = R·θ, b = z;
 *        bed a = ρ·θ, b = ρ. Units: metres, radians. Immutable; thread-safe.
 */
#include "stylos/core/synth/SurfacePatch.h"

#include <functional>

namespace stylos::core::synth {

class DrumShape;

/** Keeps a point of the object frame (true) or drops it. */
using PointClip = std::function<bool(const Eigen::Vector3d&)>;

/** @brief Angular and radial or axial ranges of a drum patch; the whole drum by default. */
struct DrumPatchRange {
    double thetaMin = 0.0;       ///< radians
    double thetaMax = 0.0;       ///< radians; thetaMax == thetaMin: the full circle
    double min = 0.0;            ///< z (lateral) or ρ (bed), metres
    double max = 0.0;
};

class DrumLateralPatch final : public SurfacePatch {
public:
    DrumLateralPatch(const DrumShape& drum, DrumPatchRange range, Eigen::Vector2d scanCentre,
                     PointClip clip = {});
    ParameterRange rows() const override { return {m_range.min, m_range.max, false}; }
    ParameterRange columns(double b) const override;
    double azimuth(double a, double b) const override;
    double azimuthScale(double) const override { return m_centred ? 1.0 / m_radius : 0.0; }
    Eigen::Vector3d position(double a, double b) const override;
    bool contains(double a, double b, const Eigen::Vector3d& p) const override;

private:
    const DrumShape& m_drum;
    DrumPatchRange m_range;
    Eigen::Vector2d m_scanCentre;
    bool m_centred;
    PointClip m_clip;
    double m_radius;
};

class DrumBedPatch final : public SurfacePatch {
public:
    DrumBedPatch(const DrumShape& drum, bool top, DrumPatchRange range, Eigen::Vector2d scanCentre,
                 PointClip clip = {});
    ParameterRange rows() const override { return {m_range.min, m_range.max, false}; }
    ParameterRange columns(double b) const override;
    double azimuth(double a, double b) const override;
    double azimuthScale(double b) const override { return m_centred && b > 0.0 ? 1.0 / b : 0.0; }
    Eigen::Vector3d position(double a, double b) const override;
    bool contains(double a, double b, const Eigen::Vector3d& p) const override;
    Eigen::Vector3d normal(double a, double b) const override;

private:
    const DrumShape& m_drum;
    bool m_top;
    DrumPatchRange m_range;
    Eigen::Vector2d m_scanCentre;
    bool m_centred;
    PointClip m_clip;
    double m_clear; ///< radius inside which the lateral surface cannot clip the face, metres
};

} // namespace stylos::core::synth
