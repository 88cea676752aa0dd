#pragma once
/** @file
 * @brief Decides which cells of which fragments the 3D view draws, and computes them in the background.
 *
 * Two modes. **Budget** (the default): per fragment the view-dependent cut (core::octree::computeViewCut:
 * refine while a cell projects larger than the pixel threshold), the total point budget (default 1 M)
 * shared among the visible fragments in proportion to the cells each needs at the threshold (capped by
 * its leaf count; what one cannot use goes to the others). **GlobalLevel**: the paper's level slider,
 * every cell of one level of every fragment (the budget still caps it).
 *
 * Timing. While the camera moves, the view draws a prefix of the current cut (SplatBuffer is shuffled)
 * of drawLimit() points: the limit adapts from the frame times reported (reportFrame) so that a frame
 * takes about targetFrameMs(); every motionInterval() a new cut at that limit is computed for the new
 * view. When the camera has been still for idleDelay(), the cut is refined progressively — budgets of
 * drawLimit() × 4^k, then the full budget — each stage computed in the background and delivered by
 * cutReady(); refined() says the last stage is in.
 *
 * Threads: the public interface is for the GUI thread. Cuts run on QThreadPool::globalInstance()
 * (QtConcurrent), one at a time, reading the shared octrees only; results come back on the GUI
 * thread (cutReady), where the receiver uploads them. Nothing blocks the GUI thread except the
 * destructor, which waits for the running cut (one cut: a fraction of a second).
 * Failure modes: none (a fragment without an octree, hidden or out of view gets an empty cut).
 */
#include "stylos/widgets/Camera.h"
#include "stylos/widgets/RenderFragment.h"
#include "stylos/widgets/SplatBuffer.h"

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QObject>
#include <QTimer>

#include <cstdint>
#include <memory>
#include <vector>

namespace stylos::widgets {

class LodScheduler : public QObject {
    Q_OBJECT

public:
    enum class Mode { Budget, GlobalLevel };

    /** @brief What a cut depends on besides the fragments and the camera. */
    struct Settings {
        Mode mode = Mode::Budget;
        double pixelThreshold = 1.0;   ///< refine while a cell projects larger than this, pixels
        int globalLevel = 8;           ///< GlobalLevel mode: the level drawn (clamped to each depth)
    };

    /** @brief One fragment's cut. */
    struct FragmentCut {
        std::uint64_t id = 0;
        SplatBuffer splats;
    };

    /** @brief The cuts of one computation. */
    struct CutBatch {
        std::vector<FragmentCut> fragments;
        std::uint64_t budget = 0;      ///< the budget it was computed for
        std::uint64_t cells = 0;       ///< cells in all cuts
        bool motion = false;           ///< a cut made while the camera moved
        bool budgetReached = false;    ///< some cut stopped at its share of the budget
        bool final = false;            ///< the last refinement stage for this view (set by the scheduler)
        double seconds = 0;            ///< time the computation took
    };

    explicit LodScheduler(QObject* parent = nullptr);
    ~LodScheduler() override;

    /** @brief Replaces the fragments; recomputes from a coarse first stage. */
    void setFragments(std::vector<RenderFragment> fragments);
    /** @brief Replaces the fragments and the camera (still) at once: one computation, not two. */
    void setFragments(std::vector<RenderFragment> fragments, const Camera& camera);
    const std::vector<RenderFragment>& fragments() const { return m_fragments; }

    /** @brief The camera moved (or changed in any way): the view is "moving" until idleDelay() passes. */
    void cameraChanged(const Camera& camera);
    /** @brief Starts refining at once for @p camera, without waiting for idleDelay() (still view). */
    void cameraSettled(const Camera& camera);
    bool isMoving() const { return m_moving; }
    /** @brief The last refinement stage for the current view and settings has been delivered. */
    bool isRefined() const { return m_refined; }
    bool isComputing() const { return m_watcher != nullptr; }

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

    /**
     * @brief The cuts for @p camera (synchronous; the background jobs call it). @p budget is shared as the
     *        file comment says. Pure function of its arguments; reentrant.
     */
    static CutBatch computeCuts(const std::vector<RenderFragment>& fragments, const Camera& camera,
                                const Settings& settings, std::uint64_t budget);
    /**
     * @brief Water-filling share of @p budget: in proportion to @p demands, none above its cap, what a
     *        capped one cannot use shared among the others; zero demand or cap gets 0. Σ ≤ budget.
     */
    static std::vector<std::uint64_t> shareBudget(const std::vector<double>& demands,
                                                  const std::vector<std::uint64_t>& caps, std::uint64_t budget);
    /** @brief core's cut camera for @p camera, in the frame of an octree placed by @p pose (octree → scene). */
    static core::octree::CutCamera cutCameraFor(const Camera& camera, const Eigen::Matrix4d& pose);

Q_SIGNALS:
    /** @brief New cuts for the fragments (GUI thread); upload them and repaint. */
    void cutReady(std::shared_ptr<const stylos::widgets::LodScheduler::CutBatch> batch);
    /** @brief The view has been refined as far as the budget and threshold allow. */
    void refined();
    /** @brief The camera has been still for idleDelay() after moving. */
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

    std::vector<RenderFragment> m_fragments;
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
    Job m_running;
    QFutureWatcher<CutBatch>* m_watcher = nullptr;
    QTimer m_idleTimer;
    QTimer m_motionTimer;
};

} // namespace stylos::widgets

Q_DECLARE_METATYPE(std::shared_ptr<const stylos::widgets::LodScheduler::CutBatch>)
