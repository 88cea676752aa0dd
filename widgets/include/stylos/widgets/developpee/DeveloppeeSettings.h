#pragma once
/** @file
 * @brief What the Développée dock asks of a computation: the surface to fit, the shading, its skydome
 *        directions and light, the pixel size (0 = the cloud's own spacing) and an optional axis given
 *        in the octree's frame (then only the radius, slope or profile is fitted; a fragment needs it).
 *        Plain data with the translated names the dock shows, a check of its ranges, and persistence in
 *        QSettings. Units: metres and radians, as the core. Thread-safety: a value type.
 */
#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/shading/LightShading.h"
#include "stylos/core/unroll/Surface.h"

#include <QCoreApplication>
#include <QMetaType>
#include <QString>

#include <optional>

class QSettings;

namespace stylos::widgets {

/** @brief How the height field becomes grey: the core's one table (core::developpee::shadings()). */
using DeveloppeeShading = core::developpee::Shading;

struct DeveloppeeSettings {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::DeveloppeeSettings)

public:
    static constexpr int MinDirections = core::developpee::DeveloppeeOptions::kMinDirections;
    static constexpr int MaxDirections = core::developpee::DeveloppeeOptions::kMaxDirections;

    core::unroll::SurfaceKind surface = core::unroll::SurfaceKind::Cylinder;
    DeveloppeeShading shading = DeveloppeeShading::Skydome;
    int directions = 40;          ///< skydome azimuths, [MinDirections, MaxDirections]
    core::shading::LightShadingOptions light; ///< light shading: azimuth, elevation (radians)
    bool stretch = true;          ///< skydome: stretch the 1–99 % range to [0, 1] (false: the exact Ω / 2π)
    double pixelSize = 0.0;       ///< metres; 0 = automatic (the core's rule: the sampling spacing, ≥ 3 leaf edges)
    bool smooth = true;           ///< skydome: smooth the scanner's noise out of the heights first (false: raw heights)
    double smoothing = 0.0;       ///< with smooth: the Gaussian σ, metres; 0 = automatic (from the measured noise)
    /** Given axis in the octree's frame (unit direction not required: normalised by the job). */
    std::optional<core::unroll::Axis> axis;
    /** With the axis: the unrolling radius (metres), the leading radius of the drum's guides, so that a fragment and
     *  its drum unroll at the same scale (core::developpee::DeveloppeeOptions::radius); not saved. */
    std::optional<double> radius;
    /** With the radius: the guides' taper (core::developpee::DeveloppeeOptions::radiusSlope); not saved. */
    std::optional<double> radiusSlope;

    /** @brief An empty string when usable; else a translated reason (directions, pixel size or axis out of range). */
    QString problem() const;

    /** @brief The core's options for these settings (the same pixels as `stylos-cli unroll` with the same values). */
    core::developpee::DeveloppeeOptions options() const;

    /** @brief "Cylinder", "Cone", "Surface of revolution" (translated). */
    static QString surfaceName(core::unroll::SurfaceKind kind);
    /** @brief The table's display name, translated ("Skydome", "Light", "Height"). */
    static QString shadingName(DeveloppeeShading shading);
    /** @brief "height", "light", "skydome": the CLI's words, used as settings values. */
    static const char* shadingKey(DeveloppeeShading shading);
    static std::optional<DeveloppeeShading> shadingFromKey(const QString& key);

    /** @brief Writes everything but the axis and radius (they belong to a fragment) under the group "developpee". */
    void save(QSettings& settings) const;
    /** @brief Reads what save() wrote; missing or invalid values keep their defaults. */
    static DeveloppeeSettings load(QSettings& settings);

    bool operator==(const DeveloppeeSettings& other) const;
};

} // namespace stylos::widgets

Q_DECLARE_METATYPE(stylos::widgets::DeveloppeeSettings)
