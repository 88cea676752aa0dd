#include "stylos/widgets/developpee/DeveloppeeSettings.h"

#include <QSettings>

#include <cmath>
#include <numbers>

namespace stylos::widgets {

namespace {

using core::unroll::SurfaceKind;

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

bool sameAxis(const std::optional<core::unroll::Axis>& a, const std::optional<core::unroll::Axis>& b)
{
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->point == b->point && a->direction == b->direction);
}

} // namespace

QString DeveloppeeSettings::problem() const
{
    if (directions < MinDirections || directions > MaxDirections)
        return tr("the number of directions must be between %1 and %2").arg(MinDirections).arg(MaxDirections);
    if (!std::isfinite(pixelSize) || pixelSize < 0.0)
        return tr("the pixel size must be a positive length, or 0 for automatic");
    if (!std::isfinite(light.azimuth) || !(light.elevation >= 0.0 && light.elevation <= 0.5 * std::numbers::pi))
        return tr("the light elevation must be between 0° and 90°");
    if (axis && (!finite(axis->point) || !finite(axis->direction) || axis->direction.norm() < 1e-12))
        return tr("the axis needs a finite point and a non-zero direction");
    if (radius && !(std::isfinite(*radius) && *radius > 0.0)) return tr("the unrolling radius must be a positive length");
    if (!std::isfinite(smoothing) || smoothing < 0.0)
        return tr("the smoothing must be a positive length, or 0 for automatic");
    return {};
}

QString DeveloppeeSettings::surfaceName(SurfaceKind kind)
{
    switch (kind) {
    case SurfaceKind::Cylinder: return tr("Cylinder");
    case SurfaceKind::Cone: return tr("Cone");
    case SurfaceKind::Revolution: return tr("Surface of revolution");
    }
    return tr("Cylinder");
}

// The display names of core::developpee::shadings(), marked for lupdate in this class's context.
[[maybe_unused]] constexpr const char* kShadingNames[] = {QT_TRANSLATE_NOOP("stylos::widgets::DeveloppeeSettings", "Skydome"),
                                                         QT_TRANSLATE_NOOP("stylos::widgets::DeveloppeeSettings", "Light"),
                                                         QT_TRANSLATE_NOOP("stylos::widgets::DeveloppeeSettings", "Height")};

QString DeveloppeeSettings::shadingName(DeveloppeeShading shading)
{
    return tr(core::developpee::shadingInfo(shading).displayName);
}

const char* DeveloppeeSettings::shadingKey(DeveloppeeShading shading) { return core::developpee::shadingInfo(shading).key; }

std::optional<DeveloppeeShading> DeveloppeeSettings::shadingFromKey(const QString& key)
{
    return core::developpee::shadingFromKey(key.toStdString());
}

core::developpee::DeveloppeeOptions DeveloppeeSettings::options() const
{
    core::developpee::DeveloppeeOptions o;
    o.surface = surface;
    o.axis = axis;
    if (axis) o.radius = radius;
    if (axis && radius) o.radiusSlope = radiusSlope;
    o.shading = shading;
    o.directions = directions;
    o.light = light;
    o.stretch = stretch;
    if (pixelSize > 0.0) o.pixelSize = pixelSize;
    if (!smooth) o.smoothing = 0.0;
    else if (smoothing > 0.0) o.smoothing = smoothing;
    return o;
}

void DeveloppeeSettings::save(QSettings& settings) const
{
    settings.beginGroup(QStringLiteral("developpee"));
    settings.setValue(QStringLiteral("surface"), QString::fromLatin1(core::unroll::surfaceKindName(surface)));
    settings.setValue(QStringLiteral("shading"), QString::fromLatin1(shadingKey(shading)));
    settings.setValue(QStringLiteral("directions"), directions);
    settings.setValue(QStringLiteral("lightAzimuth"), light.azimuth);
    settings.setValue(QStringLiteral("lightElevation"), light.elevation);
    settings.setValue(QStringLiteral("stretch"), stretch);
    settings.setValue(QStringLiteral("pixelSize"), pixelSize);
    settings.setValue(QStringLiteral("smooth"), smooth);
    settings.setValue(QStringLiteral("smoothing"), smoothing);
    settings.endGroup();
}

DeveloppeeSettings DeveloppeeSettings::load(QSettings& settings)
{
    DeveloppeeSettings s;
    settings.beginGroup(QStringLiteral("developpee"));
    if (auto kind = core::unroll::surfaceKindFromName(settings.value(QStringLiteral("surface")).toString().toStdString()))
        s.surface = *kind;
    if (auto shading = shadingFromKey(settings.value(QStringLiteral("shading")).toString())) s.shading = *shading;
    s.directions = settings.value(QStringLiteral("directions"), s.directions).toInt();
    s.light.azimuth = settings.value(QStringLiteral("lightAzimuth"), s.light.azimuth).toDouble();
    s.light.elevation = settings.value(QStringLiteral("lightElevation"), s.light.elevation).toDouble();
    s.stretch = settings.value(QStringLiteral("stretch"), s.stretch).toBool();
    s.pixelSize = settings.value(QStringLiteral("pixelSize"), s.pixelSize).toDouble();
    s.smooth = settings.value(QStringLiteral("smooth"), s.smooth).toBool();
    s.smoothing = settings.value(QStringLiteral("smoothing"), s.smoothing).toDouble();
    settings.endGroup();
    const DeveloppeeSettings defaults;
    if (s.directions < MinDirections || s.directions > MaxDirections) s.directions = defaults.directions;
    if (!std::isfinite(s.pixelSize) || s.pixelSize < 0.0) s.pixelSize = defaults.pixelSize;
    if (!std::isfinite(s.smoothing) || s.smoothing < 0.0) s.smoothing = defaults.smoothing;
    if (!s.problem().isEmpty()) s.light = defaults.light;
    return s;
}

bool DeveloppeeSettings::operator==(const DeveloppeeSettings& o) const
{
    return surface == o.surface && shading == o.shading && directions == o.directions &&
           light.azimuth == o.light.azimuth && light.elevation == o.light.elevation &&
           light.verticalExaggeration == o.light.verticalExaggeration && stretch == o.stretch &&
           pixelSize == o.pixelSize && smooth == o.smooth && smoothing == o.smoothing && sameAxis(axis, o.axis) &&
           radius == o.radius;
}

} // namespace stylos::widgets
