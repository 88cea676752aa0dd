#include "stylos/widgets/docking/GizmoReadout.h"

#include <QLocale>

#include <cmath>
#include <numbers>

namespace stylos::widgets {

namespace {

/** @p v with its sign always written ("+1.5", "−1.5"; zero without one) in the locale's format. */
QString signedNumber(double v, int decimals)
{
    const QLocale locale;
    const QString magnitude = locale.toString(std::abs(v), 'f', decimals);
    if (magnitude == locale.toString(0.0, 'f', decimals)) return magnitude;
    return (v < 0 ? QStringLiteral("\u2212") : locale.positiveSign()) + magnitude;
}

} // namespace

QString GizmoReadout::text(core::view::HandleRole role, core::view::GizmoFrame frame, double value, double pitch)
{
    using core::view::HandleRole;
    const QString mm = signedNumber(value * 1000.0, 1);
    const QString degrees = signedNumber(value * 180.0 / std::numbers::pi, 2);
    const bool own = frame == core::view::GizmoFrame::Fragment;
    QString what;
    switch (role) {
    case HandleRole::MoveX: what = own ? tr("Along the fragment's X: %1 mm").arg(mm) : tr("Along X: %1 mm").arg(mm); break;
    case HandleRole::MoveY: what = own ? tr("Along the fragment's Y: %1 mm").arg(mm) : tr("Along Y: %1 mm").arg(mm); break;
    case HandleRole::MoveZ: what = own ? tr("Along the fragment's Z: %1 mm").arg(mm) : tr("Along Z: %1 mm").arg(mm); break;
    case HandleRole::TurnX: what = own ? tr("About the fragment's X: %1°").arg(degrees) : tr("About X: %1°").arg(degrees); break;
    case HandleRole::TurnY: what = own ? tr("About the fragment's Y: %1°").arg(degrees) : tr("About Y: %1°").arg(degrees); break;
    case HandleRole::TurnZ: what = own ? tr("About the fragment's Z: %1°").arg(degrees) : tr("About Z: %1°").arg(degrees); break;
    case HandleRole::DrumZ: what = tr("Along the drum axis: %1 mm").arg(mm); break;
    case HandleRole::DrumRadial: what = tr("Radially: %1 mm").arg(mm); break;
    case HandleRole::TiltRadial: what = tr("Tilt about the radial direction: %1°").arg(degrees); break;
    case HandleRole::TiltTangential: what = tr("Tilt about the tangent: %1°").arg(degrees); break;
    case HandleRole::DrumTheta: {
        const double flutes = pitch > 0 ? value / pitch : 0.0;
        const long whole = std::lround(flutes);
        // The flute count where the turn is a whole number of flutes (the snapped θ; Ctrl turns by degrees).
        if (pitch > 0 && std::abs(flutes - double(whole)) < 1e-6 && whole != 0)
            what = tr("About the drum axis: %1° (%n flute(s))", nullptr, int(std::abs(whole))).arg(degrees);
        else
            what = tr("About the drum axis: %1°").arg(degrees);
        break;
    }
    }
    return tr("%1 · Esc cancels").arg(what);
}

} // namespace stylos::widgets
