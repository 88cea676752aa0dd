#include "stylos/widgets/view3d/LodScheduler.h"

#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace stylos::widgets {

LodScheduler::LodScheduler(QObject* parent) : QObject(parent)
{
    qRegisterMetaType<std::shared_ptr<const core::view::SceneCut>>();
    m_idleTimer.setSingleShot(true);
    m_idleTimer.setInterval(250);
    m_motionTimer.setSingleShot(true);
    m_motionTimer.setInterval(400);
    connect(&m_idleTimer, &QTimer::timeout, this, [this] {
        m_moving = false;
        m_motionTimer.stop();
        m_motionDue = false;
        Q_EMIT motionStopped();
        pump();
    });
    connect(&m_motionTimer, &QTimer::timeout, this, [this] {
        m_motionDue = true;
        pump();
    });
}

LodScheduler::~LodScheduler()
{
    if (m_watcher) m_watcher->waitForFinished();
}

void LodScheduler::invalidate()
{
    ++m_version;
    m_refined = false;
}

void LodScheduler::setFragments(Fragments fragments)
{
    m_fragments = std::move(fragments);
    invalidate();
    pump();
}

void LodScheduler::setFragments(Fragments fragments, const Camera& camera)
{
    m_fragments = std::move(fragments);
    cameraSettled(camera);
}

bool LodScheduler::setFragmentPose(std::uint64_t id, const Eigen::Matrix4d& pose, const Camera& camera)
{
    const auto it = std::find_if(m_fragments.begin(), m_fragments.end(),
                                 [id](const core::view::ViewFragment& f) { return f.id == id; });
    if (it == m_fragments.end()) return false;
    it->pose = pose;
    m_camera = camera;
    m_moving = true;
    invalidate();       // the cut for the new poses comes when they stop changing (the idle timer), not now
    m_idleTimer.start();
    return true;
}

void LodScheduler::cameraChanged(const Camera& camera)
{
    m_camera = camera;
    m_haveCamera = true;
    m_moving = true;
    invalidate();
    m_idleTimer.start();
    if (!m_motionTimer.isActive()) m_motionTimer.start();
    pump();
}

void LodScheduler::cameraSettled(const Camera& camera)
{
    m_camera = camera;
    m_haveCamera = true;
    m_moving = false;
    m_idleTimer.stop();
    m_motionTimer.stop();
    m_motionDue = false;
    invalidate();
    pump();
}

void LodScheduler::setSettings(const Settings& settings)
{
    m_settings = settings;
    invalidate();
    pump();
}

void LodScheduler::setPointBudget(std::uint64_t points)
{
    m_budget = std::max<std::uint64_t>(points, 1);
    m_drawLimit = std::min(m_drawLimit, m_budget);
    invalidate();
    pump();
}

void LodScheduler::reportFrame(double ms, std::uint64_t points)
{
    if (points == 0 || !(ms > 0)) return;
    const double proposal = double(points) * 0.85 * m_targetMs / ms;
    const double next = std::min(0.5 * double(m_drawLimit) + 0.5 * proposal, 2.0 * double(m_drawLimit));
    m_drawLimit = std::clamp<std::uint64_t>(std::uint64_t(next), std::min(m_minDraw, m_budget), m_budget);
}

std::uint64_t LodScheduler::stageBudget(int stage) const
{
    if (m_settings.mode == Mode::GlobalLevel) return m_budget;
    const double b = double(std::max<std::uint64_t>(m_stageBase, 1)) * std::pow(4.0, stage);
    return b >= double(m_budget) ? m_budget : std::uint64_t(b);
}

void LodScheduler::pump()
{
    if (m_watcher || !m_haveCamera || m_fragments.empty()) return;
    if (m_moving) {
        if (m_motionDue && m_lastJobVersion != m_version && m_settings.mode == Mode::Budget) {
            m_motionDue = false;
            start({m_version, std::min(m_drawLimit, m_budget), true, 0});
        }
        return;
    }
    if (m_stageVersion != m_version) {
        m_stageVersion = m_version;
        m_nextStage = 0;
        m_refined = false;
        m_stageBase = std::min(m_budget, std::max(m_drawLimit, m_minDraw)); // fixed for this view's stages
    }
    if (!m_refined) start({m_version, stageBudget(m_nextStage), false, m_nextStage});
}

void LodScheduler::start(const Job& job)
{
    m_running = job;
    m_lastJobVersion = job.version;
    ++m_cutsStarted;
    m_watcher = new QFutureWatcher<core::view::SceneCut>(this);
    connect(m_watcher, &QFutureWatcherBase::finished, this, &LodScheduler::finished);
    m_watcher->setFuture(QtConcurrent::run([fragments = m_fragments, camera = m_camera, settings = m_settings,
                                            budget = job.budget, motion = job.motion] {
        core::view::SceneCut batch = core::view::computeSceneCut(fragments, camera, settings, budget);
        batch.motion = motion;
        return batch;
    }));
}

void LodScheduler::finished()
{
    auto batch = std::make_shared<core::view::SceneCut>(m_watcher->future().takeResult());
    m_watcher->deleteLater();
    m_watcher = nullptr;
    const Job job = m_running;
    const bool lastStage = job.budget >= m_budget || !batch->budgetReached; // more budget would change nothing
    batch->final = !job.motion && job.version == m_version && lastStage;
    if (!job.motion && job.version == m_stageVersion) m_nextStage = job.stage + 1;
    const bool final = batch->final;
    if (final) m_refined = true;
    Q_EMIT cutReady(std::move(batch)); // a receiver may change the view: then m_version moves on
    if (final && job.version == m_version) Q_EMIT refined();
    pump();
}

} // namespace stylos::widgets
