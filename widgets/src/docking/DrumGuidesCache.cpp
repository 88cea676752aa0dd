#include "stylos/widgets/docking/DrumGuidesCache.h"

#include "stylos/core/scene/SceneEigen.h"
#include "stylos/widgets/docking/GuideFitJob.h"

#include <algorithm>
#include <cstdio>

namespace stylos::widgets {

DrumGuidesCache::DrumGuidesCache(SceneDocument& document, QObject* parent)
    : QObject(parent), m_document(document), m_jobs(document)
{
}

std::optional<core::dock::GuideOptions> DrumGuidesCache::guideOptionsOf(const core::scene::Fragment& drum)
{
    return core::dock::guideOptionsFor(drum);
}

std::optional<std::string> DrumGuidesCache::keyOf(FragmentId drum) const
{
    const core::scene::Fragment* f = m_document.fragment(drum);
    if (!f) return std::nullopt;
    const auto options = guideOptionsOf(*f);
    if (!options) return std::nullopt;
    const Eigen::Vector3d& p = options->axis->point;
    const Eigen::Vector3d& d = options->axis->direction;
    char text[256];
    std::snprintf(text, sizeof text, "|%.17g,%.17g,%.17g|%.17g,%.17g,%.17g|%d", p.x(), p.y(), p.z(), d.x(), d.y(),
                  d.z(), options->flutes);
    return f->octreePath.string() + text;
}

DrumGuidesCache::GuidesPtr DrumGuidesCache::guides(FragmentId drum) const
{
    const auto key = keyOf(drum);
    if (!key) return nullptr;
    const auto it = m_guides.find(*key);
    return it == m_guides.end() ? nullptr : it->second;
}

DrumGuidesCache::State DrumGuidesCache::request(FragmentId drum)
{
    if (guides(drum)) return State::Ready;
    if (m_jobs.isRunning(drum)) return State::Fitting;
    const core::scene::Fragment* f = m_document.fragment(drum);
    const auto key = keyOf(drum);
    if (!f || !key || !m_document.octree(drum)) return State::Unavailable;
    const GuideFitJob job(QString::fromStdString(f->octreePath.string()), drum, *guideOptionsOf(*f),
                          QString::fromStdString(f->name));
    const auto deliver = [this, key = *key](FragmentId id, const QFuture<GuideFitResult>& future) {
        if (!future.isCanceled() && future.resultCount() > 0) delivered(id, key, future.result());
    };
    if (!m_jobs.start<GuideFitResult>(drum, job.label(), job, deliver)) return State::Unavailable;
    ++m_fits;
    return State::Fitting;
}

void DrumGuidesCache::delivered(FragmentId drum, const std::string& key, const GuideFitResult& result)
{
    if (!result.ok() || !result.drum) {
        Q_EMIT failed(drum, result.error);
        return;
    }
    m_guides[key] = result.drum; // kept under the key it was fitted for, even if the drum's guides changed since
    Q_EMIT ready(drum);
}

} // namespace stylos::widgets
