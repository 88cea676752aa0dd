#pragma once
/** @file
 * @brief Decides when the 3D view's level-of-detail cut is computed, and computes it in the background. What
 *        a cut is — which cells of which fragments under the shared point budget, in Budget or GlobalLevel
 *        mode — is the core's (core::view::computeSceneCut); this class schedules it.
 *
 * Timing. While the camera moves, the view draws a prefix of the current cut (SplatBuffer is shuffled)
 * of drawLimit() points: the limit adapts from the frame times reported (reportFrame) so that a frame
 * takes about targetFrameMs(); every motionInterval() a new cut at that limit is computed for the new
 * view. When the camera has been still for idleDelay(), the cut is refined progressively — budgets of
 * drawLimit() × 4^k, then the full budget — each stage computed in the background and delivered by
 * cutReady(); refined() says the last stage is in.
 *
 * Poses. A change of a fragment's pose alone (setFragmentPose) starts no cut: the view keeps drawing the
 * cells it has, with the new model matrix, as moving frames (isMoving() is true) while poses keep changing.
 * Once no pose (nor the camera) has changed for idleDelay(), the cut is computed for the new poses — its
 * cells, culling and detail depend on where the fragment now is — and refined in stages as after a camera
 * move. So dragging a fragment never re-cuts on a mouse move; the cut of a moved fragment lags by the idle
 * delay (250 ms by default) after the drag stops.
 *
 * Threads: the public interface is for the GUI thread. Cuts run on QThreadPool::globalInstance()
 * (QtConcurrent), one at a time, reading the shared octrees only; results come back on the GUI
 * thread (cutReady), where the receiver uploads them. Nothing blocks the GUI thread except the
 * destructor, which waits for the running cut (one cut: a fraction of a second).
 * Failure modes: none (a fragment without an octree, hidden or out of view gets an empty cut).
 */
#include "stylos/core/view/Camera.h"
#include "stylos/core/view/SceneCut.h"
#include "stylos/core/view/ViewFragment.h"

#include <QFutureWatcher>
#include <QObject>
#include <QTimer>

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

namespace stylos::widgets {

class LodScheduler : public QObject {
    Q_OBJECT

public:
    using Mode = core::view::CutMode;
    using Settings = core::view::CutSettings;
    using Camera = core::view::Camera;
    using Fragments = std::vector<core::view::ViewFragment>;

    explicit LodScheduler(QObject* parent = nullptr);
    ~LodScheduler() override;

    /** @brief Replaces the fragments; recomputes from a coarse first stage. */
    void setFragments(Fragments fragments);
    /** @brief Replaces the fragments and the camera (still) at once: one computation, not two. */
    void setFragments(Fragments fragments, const Camera& camera);
    const Fragments& fragments() const { return m_fragments; }
    /**
     * @brief Fragment @p id's pose alone changed (octree frame → scene frame), and @p camera with it (its
     *        scene bounds follow the poses): no cut now; moving until idleDelay() passes without another
     *        change, then the cut for the new poses (see the file comment). False (nothing changes) when no
     *        fragment has that id.
     */
    bool setFragmentPose(std::uint64_t id, const Eigen::Matrix4d& pose, const Camera& camera);

    /** @brief The camera moved (or changed in any way): the view is "moving" until idleDelay() passes. */
    void cameraChanged(const Camera& camera);
    /** @brief Starts refining at once for @p camera, without waiting for idleDelay() (still view). */
    void cameraSettled(const Camera& camera);
    /** @brief The camera or a pose changed less than idleDelay() ago (moving frames are drawn). */
    bool isMoving() const { return m_moving; }
    /** @brief The last refinement stage for the current view and settings has been delivered. */
    bool isRefined() const { return m_refined; }
    bool isComputing() const { return m_watcher != nullptr; }
    /** @brief Cuts started since construction (each stage and each motion cut counts one). */
    std::uint64_t cutsStarted() const { return m_cutsStarted; }

    void setSettings(const Settings& settings);
    const Settings& settings() const { return m_settings; }
    /** @brief Total point budget (≥ 1, default 1 M). */
    void setPointBudget(std::uint64_t points);
    std::uint64_t pointBudget() const { return m_budget; }
    /** @brief Frame time to keep under while moving, ms (default 50; the controller aims at 85 % of it). */
    void setTargetFrameMs(double ms) { m_targetMs = ms > 1 ? ms : 1; }
    double targetFrameMs() const { return m_targetMs; }
    void setIdleDelay(int ms) { m_idleTimer.setInterval(ms); }
    int idleDelay() const { return m_idleTimer.interval(); }
    void setMotionInterval(int ms) { m_motionTimer.setInterval(ms); }
    int motionInterval() const { return m_motionTimer.interval(); }
    /** @brief Smallest drawLimit() the controller goes down to (default 5 000). */
    void setMinimumDrawLimit(std::uint64_t points) { m_minDraw = points > 0 ? points : 1; }

    /**
     * @brief Points to draw in the next frame: drawLimit() while moving, 0 (everything) when still.
     */
    std::uint64_t frameLimit() const { return m_moving ? m_drawLimit : 0; }
    /** @brief The adaptive number of points a moving frame can draw within the target (100 000 until
     *         frames have been reported). */
    std::uint64_t drawLimit() const { return m_drawLimit; }
    /** @brief A frame took @p ms and drew @p points: adapts drawLimit(). Frames of 0 points are ignored. */
    void reportFrame(double ms, std::uint64_t points);

Q_SIGNALS:
    /** @brief New cuts for the fragments (GUI thread); upload them and repaint. */
    void cutReady(std::shared_ptr<const stylos::core::view::SceneCut> batch);
    /** @brief The view has been refined as far as the budget and threshold allow. */
    void refined();
    /** @brief The camera and the poses have been still for idleDelay() after moving. */
    void motionStopped();

private:
    struct Job {
        std::uint64_t version = 0;
        std::uint64_t budget = 0;
        bool motion = false;
        int stage = 0;
    };

    void invalidate();
    void pump();
    void start(const Job& job);
    void finished();
    std::uint64_t stageBudget(int stage) const;

    Fragments m_fragments;
    Camera m_camera;
    Settings m_settings;
    std::uint64_t m_budget = 1'000'000;
    double m_targetMs = 50;
    std::uint64_t m_minDraw = 5'000;
    std::uint64_t m_drawLimit = 100'000;
    bool m_haveCamera = false;
    bool m_moving = false;
    bool m_refined = false;
    bool m_motionDue = false;
    std::uint64_t m_version = 1;        ///< bumps on any change of fragments, camera or settings
    std::uint64_t m_stageVersion = 0;   ///< version the stages below belong to
    int m_nextStage = 0;                ///< next refinement stage for m_stageVersion
    std::uint64_t m_stageBase = 1;      ///< budget of stage 0 for m_stageVersion (then × 4 per stage)
    std::uint64_t m_lastJobVersion = 0;
    std::uint64_t m_cutsStarted = 0;
    Job m_running;
    QFutureWatcher<core::view::SceneCut>* m_watcher = nullptr;
    QTimer m_idleTimer;
    QTimer m_motionTimer;
};

} // namespace stylos::widgets

Q_DECLARE_METATYPE(std::shared_ptr<const stylos::core::view::SceneCut>)
