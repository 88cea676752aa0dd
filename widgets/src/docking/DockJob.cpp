#include "stylos/widgets/docking/DockJob.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/util/SubProgress.h"
#include "tasks/ErrorText.h"
#include "tasks/JobResult.h"

#include <QLocale>
#include <QFileInfo>
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

QString DockJob::errorText(const QString& name, const core::Error& error)
{
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
                       .arg(QLocale().toString(r.dock.fluteShift, 'f', 2))
                       .arg(QLocale().toString(r.seconds, 'f', 1));
    if (!sigmas.isEmpty()) text += tr("; ", "between the parts of a status line") + tr("uncertainty %1").arg(sigmas.join(QStringLiteral(", ")));
    if (!unobservable.isEmpty())
        text += tr("; ", "between the parts of a status line") + tr("not fixed by the flutes, left as it was: %1").arg(unobservable.join(QStringLiteral(", ")));
    return text;
}

core::Result<DockJobResult> DockJob::run(core::ProgressSink* progress) const
{
    const auto started = std::chrono::steady_clock::now();
    core::SubProgress reading(progress, 0.0, 0.2);
    core::cloud::CloudLoadOptions load;
    load.keepNormals = true;
    auto cloud = core::cloud::loadPointCloud(m_path.toStdString(), load, &reading);
    if (!cloud) return cloud.error();
    cloud->source = m_path.toStdString();
    core::SubProgress docking(progress, 0.2, 1.0);
    auto docked = dock::dockFragment(*cloud, *m_guides, m_start, m_options, &docking);
    if (!docked) return docked.error();
    DockJobResult result;
    result.fragmentId = m_fragmentId;
    result.drumId = m_drumId;
    result.start = m_start;
    result.dock = std::move(docked).value();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (progress) progress->update(1.0);
    return result;
}

void DockJob::operator()(QPromise<DockJobResult>& promise, core::ProgressSink& progress) const
{
    deliverJobResult(promise, progress, [this](core::ProgressSink* sink) { return run(sink); },
                     [this](const core::Error& error) {
        DockJobResult failed;
        failed.fragmentId = m_fragmentId;
        failed.drumId = m_drumId;
        failed.start = m_start;
        failed.error = errorText(m_name.isEmpty() ? QFileInfo(m_path).fileName() : m_name, error);
        return failed;
    });
}

} // namespace stylos::widgets
