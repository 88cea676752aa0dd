#include "stylos/widgets/view3d/PoseBenchmark.h"

#include "stylos/core/view/ScenePick.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace stylos::widgets {

PoseBenchmark::PoseBenchmark(ViewportWidget& viewport, Options options, QObject* parent)
    : FrameBenchmark(viewport, {options.frames, options.waitUntilRefined, options.waitTimeoutMs}, parent),
      m_options(std::move(options))
{
}

bool PoseBenchmark::prepare(ViewportWidget& viewport)
{
    const auto& fragments = viewport.fragments();
    const auto it = std::find_if(fragments.begin(), fragments.end(), [&](const core::view::ViewFragment& f) {
        return m_options.fragmentId == 0 || f.id == m_options.fragmentId;
    });
    if (it == fragments.end()) {
        m_error = QStringLiteral("the view has no fragment %1").arg(m_options.fragmentId);
        return false;
    }
    m_options.fragmentId = it->id;
    m_start = it->pose;
    core::view::ViewFragment alone = *it;
    alone.visible = true;
    m_centre = core::view::sceneBounds({alone}).center();
    if (!m_options.setPose)
        m_options.setPose = [&viewport](std::uint64_t id, const Eigen::Matrix4d& pose) { viewport.setFragmentPose(id, pose); };
    return true;
}

void PoseBenchmark::advance(ViewportWidget&, int frame)
{
    const double angle = double(frame + 1) * m_options.degreesPerFrame * M_PI / 180.0;
    Eigen::Affine3d turn = Eigen::Translation3d(m_centre) * Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()) *
                           Eigen::Translation3d(-m_centre);
    m_options.setPose(m_options.fragmentId, turn.matrix() * m_start);
}

void PoseBenchmark::describe(QJsonObject& result) const
{
    result["degreesPerFrame"] = m_options.degreesPerFrame;
    result["fragmentId"] = double(m_options.fragmentId);
}

} // namespace stylos::widgets
