#include "stylos/widgets/docking/ContactJob.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/util/SubProgress.h"
#include "tasks/ErrorText.h"
#include "tasks/JobResult.h"

#include <QFileInfo>

#include <utility>

namespace stylos::widgets {

ContactJob::ContactJob(QString octreePath, quint64 fragmentId, quint64 drumId,
                       std::shared_ptr<const core::dock::DrumGuides> guides, const Eigen::Isometry3d& pose, QString name)
    : m_path(std::move(octreePath)), m_fragmentId(fragmentId), m_drumId(drumId), m_guides(std::move(guides)),
      m_pose(pose), m_name(std::move(name))
{
    Q_ASSERT_X(m_guides, "ContactJob::ContactJob()", "no guides");
}

QString ContactJob::label() const
{
    return tr("Contact of %1 with the drum").arg(m_name.isEmpty() ? QFileInfo(m_path).fileName() : m_name);
}

core::Result<ContactJobResult> ContactJob::run(core::ProgressSink* progress) const
{
    core::SubProgress reading(progress, 0.0, 0.8);
    core::cloud::CloudLoadOptions load;
    load.keepNormals = true;
    auto cloud = core::cloud::loadPointCloud(m_path.toStdString(), load, &reading);
    if (!cloud) return cloud.error();
    cloud->source = m_path.toStdString();
    auto readout = core::dock::measureContact(*cloud, *m_guides, m_pose);
    if (!readout) return readout.error();
    if (progress) progress->update(1.0);
    return ContactJobResult{m_fragmentId, m_drumId, m_pose, *readout, {}};
}

void ContactJob::operator()(QPromise<ContactJobResult>& promise, core::ProgressSink& progress) const
{
    deliverJobResult(promise, progress, [this](core::ProgressSink* sink) { return run(sink); },
                     [this](const core::Error& error) {
        ContactJobResult failed{m_fragmentId, m_drumId, m_pose, {}, {}};
        failed.error = tr("Could not measure the contact of %1: %2.")
                           .arg(m_name.isEmpty() ? QFileInfo(m_path).fileName() : m_name, ErrorText::reason(error.code)) +
                       QLatin1Char('\n') + QString::fromStdString(error.message);
        return failed;
    });
}

} // namespace stylos::widgets
