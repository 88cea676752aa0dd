#include "stylos/widgets/docking/DockJob.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/util/SubProgress.h"
#include "tasks/ErrorText.h"
#include "tasks/JobResult.h"

#include <QLocale>
#include <QFileInfo>

#include <cmath>
#include <QStringList>

#include <chrono>
#include <numbers>
#include <utility>

namespace stylos::widgets {

namespace dock = core::dock;

DockJob::DockJob(QString octreePath, quint64 fragmentId, quint64 drumId, std::shared_ptr<const dock::DrumGuides> guides,
                 const Eigen::Isometry3d& start, dock::DockOptions options, QString name)
    : m_path(std::move(octreePath)), m_fragmentId(fragmentId), m_drumId(drumId), m_guides(std::move(guides)),
      m_start(start), m_options(options), m_name(std::move(name))
{
    Q_ASSERT_X(m_guides, "DockJob::DockJob()", "no guides");
}

QString DockJob::label() const
{
    return tr("Dock %1 to the flutes").arg(m_name.isEmpty() ? QFileInfo(m_path).fileName() : m_name);
}

QString DockJob::errorText(const QString& name, const core::Error& error, const dock::DockFailure& failure,
                           const QLocale& locale)
{
    using Kind = dock::DockFailure::Kind;
    switch (failure.kind) {
    case Kind::TooFewPoints:
        return tr("Could not dock %1: its %2 points are too few (at least 200 are needed).")
            .arg(name, locale.toString(qulonglong(failure.points)));
    case Kind::TooFar:
        return tr("Could not dock %1: it is too far from the drum; %2 of its points lie within %3 mm of the drum's "
                  "surface (at least 200 are needed). Bring it nearer its place on the drum (the Move tool, or its "
                  "placement in the drum frame in Properties) and dock again.")
            .arg(name, locale.toString(qulonglong(failure.points)), locale.toString(failure.reachM * 1e3, 'f', 1));
    case Kind::LeftTheDrum:
        return tr("Could not dock %1: from where it stands its outer face does not meet the drum's surface. Bring it "
                  "nearer its place on the drum and dock again.").arg(name);
    case Kind::NoFlutes:
        return tr("Could not dock %1: no flutes can be read on its outer face (flute signal %2, at least %3 needed). "
                  "Lock θ (Tools › Docking locks) to dock it against the drum's surface alone.")
            .arg(name, locale.toString(failure.strength, 'f', 2), locale.toString(failure.needed, 'f', 2));
    case Kind::LostOuterFace:
        return tr("Could not dock %1: fewer than 200 of its points stayed on the flutes. Start it nearer its place "
                  "and dock again.").arg(name);
    case Kind::NotConverged:
        if (failure.thetaLocked)
            return tr("Could not dock %1: the registration did not settle in %2 iterations. θ is locked and may hold it "
                      "off its flute: unlock θ (Tools › Docking locks), or bring it onto its flute first.")
                .arg(name, locale.toString(failure.iterations));
        return tr("Could not dock %1: the registration did not settle in %2 iterations.")
            .arg(name, locale.toString(failure.iterations));
    case Kind::None: break;
    }
    return tr("Could not dock %1: %2.").arg(name, ErrorText::reason(error.code)) + QLatin1Char('\n') +
           QString::fromStdString(error.message);
}

QString DockJob::summary(const QString& name, const DockJobResult& r)
{
    const auto unknownText = [](dock::DockUnknown u) {
        switch (u) {
        case dock::DockUnknown::Theta: return tr("θ");
        case dock::DockUnknown::Z: return tr("z");
        case dock::DockUnknown::R: return tr("r");
        case dock::DockUnknown::Tangent: return tr("tangent");
        case dock::DockUnknown::TiltLean: return tr("lean");
        case dock::DockUnknown::TiltRoll: return tr("roll");
        }
        return QString();
    };
    QStringList sigmas;
    for (const dock::DockUncertainty& u : r.dock.uncertainty) {
        const bool angular = u.unknown == dock::DockUnknown::Theta || u.unknown == dock::DockUnknown::TiltLean ||
                             u.unknown == dock::DockUnknown::TiltRoll;
        sigmas << (angular ? tr("%1 ±%2°").arg(unknownText(u.unknown)).arg(QLocale().toString(u.sigma * 180.0 / std::numbers::pi, 'g', 2))
                           : tr("%1 ±%2 mm").arg(unknownText(u.unknown)).arg(QLocale().toString(u.sigma * 1e3, 'g', 2)));
    }
    QStringList unobservable;
    for (dock::DockUnknown u : r.dock.unobservable) unobservable << unknownText(u);
    QString text = tr("Docked %1: RMS %2 mm over %3 points, moved %4 flutes about the axis, %5 s")
                       .arg(name)
                       .arg(QLocale().toString(r.dock.rms * 1e3, 'f', 3))
                       .arg(QLocale().toString(qlonglong(r.dock.inliers)))
                       .arg(QLocale().toString(std::abs(r.dock.fluteShift) < 0.005 ? 0.0 : r.dock.fluteShift, 'f', 2)) // no "-0.00"
                       .arg(QLocale().toString(r.seconds, 'f', 1));
    if (!sigmas.isEmpty()) text += tr("; ", "between the parts of a status line") + tr("uncertainty %1").arg(sigmas.join(QStringLiteral(", ")));
    if (!unobservable.isEmpty())
        text += tr("; ", "between the parts of a status line") + tr("not fixed by the flutes, left as it was: %1").arg(unobservable.join(QStringLiteral(", ")));
    // Far off the profile (good docks: 1–2 times the drum's own RMS): a wrong flute, or a lock holding it off its place.
    if (r.drumRms > 0.0 && r.dock.rms > 3.0 * r.drumRms)
        text += tr("; ", "between the parts of a status line") +
                tr("%1 times the drum's own RMS: it may rest on the wrong flute or be held off its place by a lock")
                    .arg(QLocale().toString(r.dock.rms / r.drumRms, 'f', 1));
    return text;
}

core::Result<DockJobResult> DockJob::run(core::ProgressSink* progress, dock::DockFailure* failure) const
{
    const auto started = std::chrono::steady_clock::now();
    core::SubProgress reading(progress, 0.0, 0.2);
    core::cloud::CloudLoadOptions load;
    load.keepNormals = true;
    auto cloud = core::cloud::loadPointCloud(m_path.toStdString(), load, &reading);
    if (!cloud) return cloud.error();
    cloud->source = m_path.toStdString();
    core::SubProgress docking(progress, 0.2, 1.0);
    auto docked = dock::dockFragment(*cloud, *m_guides, m_start, m_options, &docking, failure);
    if (!docked) return docked.error();
    DockJobResult result;
    result.fragmentId = m_fragmentId;
    result.drumId = m_drumId;
    result.start = m_start;
    result.dock = std::move(docked).value();
    result.drumRms = m_guides->rms;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (progress) progress->update(1.0);
    return result;
}

void DockJob::operator()(QPromise<DockJobResult>& promise, core::ProgressSink& progress) const
{
    dock::DockFailure why;
    deliverJobResult(promise, progress, [this, &why](core::ProgressSink* sink) { return run(sink, &why); },
                     [this, &why](const core::Error& error) {
        DockJobResult failed;
        failed.fragmentId = m_fragmentId;
        failed.drumId = m_drumId;
        failed.start = m_start;
        failed.error = errorText(m_name.isEmpty() ? QFileInfo(m_path).fileName() : m_name, error, why, m_locale);
        return failed;
    });
}

} // namespace stylos::widgets
