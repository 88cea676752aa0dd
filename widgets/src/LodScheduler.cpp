#include "stylos/widgets/LodScheduler.h"

#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace stylos::widgets {

namespace oct = core::octree;

namespace {

/** True when the octree's root box lies entirely outside one clip plane of @p camera. */
bool boxOutsideView(const oct::RootBox& box, const oct::CutCamera& camera)
{
    Eigen::Map<const Eigen::Matrix4d> vp(camera.viewProjection.data());
    std::array<int, 6> outside{};
    for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector4d p(box.origin[0] + ((corner & 1) ? box.size : 0.0),
                                box.origin[1] + ((corner & 2) ? box.size : 0.0),
                                box.origin[2] + ((corner & 4) ? box.size : 0.0), 1.0);
        const Eigen::Vector4d c = vp * p;
        for (int axis = 0; axis < 3; ++axis) {
            outside[2 * axis] += c[axis] < -c.w() ? 1 : 0;
            outside[2 * axis + 1] += c[axis] > c.w() ? 1 : 0;
        }
    }
    return std::any_of(outside.begin(), outside.end(), [](int n) { return n == 8; });
}

/** Cells the octree needs at the threshold: the count of the level whose cells project to ~threshold. */
double estimateDemand(const oct::PackedOctree& octree, const oct::CutCamera& camera, double threshold)
{
    const oct::RootBox& box = octree.box();
    if (camera.cullToFrustum && boxOutsideView(box, camera)) return 0;
    double projected = 0;
    if (camera.orthographic) {
        projected = box.size * camera.pixelsPerMetre;
    } else {
        const Eigen::Vector3d centre(box.origin[0] + 0.5 * box.size, box.origin[1] + 0.5 * box.size,
                                     box.origin[2] + 0.5 * box.size);
        const double distance = (centre - Eigen::Vector3d(camera.eye[0], camera.eye[1], camera.eye[2])).norm();
        projected = box.size * camera.pixelsPerRadian / std::max(distance, 0.5 * box.size);
    }
    int level = octree.depth();
    if (threshold > 0) level = std::clamp(int(std::ceil(std::log2(std::max(projected / threshold, 1.0)))), 0, octree.depth());
    return double(std::max<std::uint64_t>(octree.cellCount(level), 1));
}

} // namespace

LodScheduler::LodScheduler(QObject* parent) : QObject(parent)
{
    qRegisterMetaType<std::shared_ptr<const CutBatch>>();
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

void LodScheduler::setFragments(std::vector<RenderFragment> fragments)
{
    m_fragments = std::move(fragments);
    invalidate();
    pump();
}

void LodScheduler::setFragments(std::vector<RenderFragment> fragments, const Camera& camera)
{
    m_fragments = std::move(fragments);
    cameraSettled(camera);
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
    m_watcher = new QFutureWatcher<CutBatch>(this);
    connect(m_watcher, &QFutureWatcherBase::finished, this, &LodScheduler::finished);
    m_watcher->setFuture(QtConcurrent::run([fragments = m_fragments, camera = m_camera, settings = m_settings,
                                            budget = job.budget, motion = job.motion] {
        CutBatch batch = computeCuts(fragments, camera, settings, budget);
        batch.motion = motion;
        return batch;
    }));
}

void LodScheduler::finished()
{
    auto batch = std::make_shared<CutBatch>(m_watcher->future().takeResult());
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

oct::CutCamera LodScheduler::cutCameraFor(const Camera& camera, const Eigen::Matrix4d& pose)
{
    oct::CutCamera c;
    const Eigen::Matrix4d vp = camera.viewProjection() * pose;
    std::copy(vp.data(), vp.data() + 16, c.viewProjection.begin()); // both column-major
    const Eigen::Matrix3d r = pose.topLeftCorner<3, 3>();
    const Eigen::Vector3d eye = r.transpose() * (camera.eye() - pose.topRightCorner<3, 1>());
    c.eye = {eye.x(), eye.y(), eye.z()};
    c.orthographic = camera.isOrthographic();
    c.pixelsPerRadian = camera.pixelsPerRadian();
    c.pixelsPerMetre = camera.pixelsPerMetre();
    return c;
}

std::vector<std::uint64_t> LodScheduler::shareBudget(const std::vector<double>& demands,
                                                     const std::vector<std::uint64_t>& caps, std::uint64_t budget)
{
    const std::size_t n = demands.size();
    std::vector<std::uint64_t> out(n, 0);
    std::vector<char> active(n, 0);
    for (std::size_t i = 0; i < n; ++i) active[i] = demands[i] > 0 && std::isfinite(demands[i]) && caps[i] > 0;
    std::uint64_t remaining = budget;
    for (;;) {
        double total = 0;
        for (std::size_t i = 0; i < n; ++i) total += active[i] ? demands[i] : 0.0;
        if (total <= 0 || remaining == 0) break;
        bool capped = false;
        const double pool = double(remaining);
        for (std::size_t i = 0; i < n; ++i) {
            if (!active[i] || pool * demands[i] / total < double(caps[i])) continue;
            out[i] = caps[i]; // Σ caps taken here ≤ Σ shares ≤ remaining
            remaining -= caps[i];
            active[i] = 0;
            capped = true;
        }
        if (capped) continue;
        std::uint64_t given = 0;
        for (std::size_t i = 0; i < n; ++i)
            if (active[i]) given += out[i] = std::uint64_t(pool * demands[i] / total);
        // Rounding leaves fewer than n points: one each to those that got none, then to the largest.
        std::uint64_t left = remaining - std::min(given, remaining);
        for (std::size_t i = 0; i < n && left > 0; ++i)
            if (active[i] && out[i] == 0) { ++out[i]; --left; }
        for (std::size_t i = 0; i < n && left > 0; ++i)
            if (active[i] && out[i] < caps[i]) { ++out[i]; --left; }
        break;
    }
    return out;
}

LodScheduler::CutBatch LodScheduler::computeCuts(const std::vector<RenderFragment>& fragments, const Camera& camera,
                                                 const Settings& settings, std::uint64_t budget)
{
    QElapsedTimer timer;
    timer.start();
    struct Item {
        std::size_t slot = 0;                 ///< index in fragments (and batch.fragments)
        const RenderFragment* fragment = nullptr;
        oct::CutCamera camera;
        oct::CutOptions options;
        oct::CutResult cut;
    };
    std::vector<Item> items;
    std::vector<double> demands;
    std::vector<std::uint64_t> caps;
    CutBatch batch;
    batch.budget = budget;
    batch.fragments.resize(fragments.size());
    for (std::size_t slot = 0; slot < fragments.size(); ++slot) {
        const RenderFragment& f = fragments[slot];
        batch.fragments[slot].id = f.id;
        if (!f.visible || !f.octree) continue;
        const oct::PackedOctree& octree = *f.octree;
        Item item{slot, &f, cutCameraFor(camera, f.pose), {}, {}};
        if (settings.mode == Mode::GlobalLevel) {
            const int level = std::clamp(settings.globalLevel, 0, octree.depth());
            item.camera.cullToFrustum = false;
            item.options.pixelThreshold = 0;
            item.options.maxLevel = level;
            demands.push_back(double(octree.cellCount(level)));
            caps.push_back(octree.cellCount(level));
        } else {
            item.options.pixelThreshold = settings.pixelThreshold;
            demands.push_back(estimateDemand(octree, item.camera, settings.pixelThreshold));
            caps.push_back(octree.cellCount(octree.depth()));
        }
        items.push_back(item);
    }

    std::vector<std::uint64_t> shares = shareBudget(demands, caps, budget);
    auto run = [&](std::size_t i) {
        items[i].cut = {};
        if (shares[i] == 0) return;
        items[i].options.pointBudget = shares[i];
        items[i].cut = oct::computeViewCut(*items[i].fragment->octree, items[i].camera, items[i].options);
    };
    std::uint64_t used = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        run(i);
        used += items[i].cut.cells.size();
    }
    // One more round: what fragments satisfied below their share did not use goes to those that hit theirs.
    if (items.size() > 1 && budget - std::min(used, budget) > budget / 20) {
        std::vector<double> moreDemand(items.size(), 0);
        std::vector<std::uint64_t> room(items.size(), 0);
        for (std::size_t i = 0; i < items.size(); ++i)
            if (items[i].cut.budgetReached) {
                moreDemand[i] = demands[i];
                room[i] = caps[i] - std::min(caps[i], shares[i]);
            }
        const std::vector<std::uint64_t> extra = shareBudget(moreDemand, room, budget - used);
        for (std::size_t i = 0; i < items.size(); ++i)
            if (extra[i] > 0) {
                shares[i] += extra[i];
                run(i);
            }
    }
    bool anyReached = false;
    for (Item& item : items) {
        anyReached = anyReached || item.cut.budgetReached;
        batch.cells += item.cut.cells.size();
        batch.fragments[item.slot].splats = makeSplatBuffer(*item.fragment->octree, item.cut, item.fragment->id + 1);
        item.cut = {};
    }
    batch.budgetReached = anyReached;
    batch.seconds = double(timer.nsecsElapsed()) * 1e-9;
    return batch;
}

} // namespace stylos::widgets
