#include "stylos/widgets/docking/ContactJob.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/dock/FragmentContact.h"
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
    const double share = 0.8 / double(1 + m_others.size());
    core::SubProgress reading(progress, 0.0, share);
    core::cloud::CloudLoadOptions load;
    load.keepNormals = true;
    auto cloud = core::cloud::loadPointCloud(m_path.toStdString(), load, &reading);
    if (!cloud) return cloud.error();
    cloud->source = m_path.toStdString();
    auto readout = core::dock::measureContact(*cloud, *m_guides, m_pose);
    if (!readout) return readout.error();
    ContactJobResult result{m_fragmentId, m_drumId, m_pose, *readout, {}, {}};
    for (std::size_t k = 0; k < m_others.size(); ++k) {
        const Other& other = m_others[k];
        MemberContact member{other.id, other.name, {}, {}};
        core::SubProgress step(progress, share * double(k + 1), share * double(k + 2));
        auto loaded = core::cloud::loadPointCloud(other.octreePath.toStdString(), load, &step);
        if (loaded && loaded->source.empty()) loaded->source = other.octreePath.toStdString();
        auto contact = loaded ? core::dock::measureFragmentContact(*cloud, *loaded, other.toFragment)
                              : core::Result<core::dock::ContactReadout>(loaded.error());
        if (!contact && contact.error().code == core::ErrorCode::Cancelled) return contact.error();
        if (contact) member.readout = *contact;
        else member.error = ErrorText::reason(contact.error().code) + QStringLiteral(": ") +
                            QString::fromStdString(contact.error().message);
        result.members.push_back(std::move(member));
    }
    if (progress) progress->update(1.0);
    return result;
}

void ContactJob::operator()(QPromise<ContactJobResult>& promise, core::ProgressSink& progress) const
{
    deliverJobResult(promise, progress, [this](core::ProgressSink* sink) { return run(sink); },
                     [this](const core::Error& error) {
        ContactJobResult failed{m_fragmentId, m_drumId, m_pose, {}, {}, {}};
        failed.error = tr("Could not measure the contact of %1: %2.")
                           .arg(m_name.isEmpty() ? QFileInfo(m_path).fileName() : m_name, ErrorText::reason(error.code)) +
                       QLatin1Char('\n') + QString::fromStdString(error.message);
        return failed;
    });
}

} // namespace stylos::widgets
