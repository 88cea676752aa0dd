#pragma once
/** @file
 * @brief Automation: what the view's frame benchmarks share (OrbitBenchmark: the camera turns; PoseBenchmark:
 *        a fragment's pose changes). Each frame changes what the view shows (advance()), draws a frame
 *        synchronously (ViewportWidget::renderNow: drawing and the swap of the view's native window) and waits
 *        for the GPU (glFinish); the time of the whole is measured with QElapsedTimer. Between frames control
 *        returns to the event loop (a zero timer), so that the level-of-detail cuts computed in the
 *        background are delivered as they would be interactively.
 *
 * Before the first frame it waits until the view has drawn points and (by default) has been refined, the
 * state after opening a file and letting it settle. Result (finished()): a JSON object {"frames", "width",
 * "height", "medianMs", "p95Ms", "meanMs", "maxMs", "meanPointsDrawn", "minPointsDrawn", "maxPointsDrawn",
 * "pointBudget", "targetFrameMs", "firstFrameMs", "refinedPoints", "cutsStarted"} and the keys of the kind of
 * benchmark; "cutsStarted" counts the level-of-detail cuts the view started from the first timed frame to the end;
 * frame times in ms, p95 by the nearest rank. GUI thread only. Failure modes: none; a viewport without
 * fragments never starts (finished() is emitted with "error" after the wait timeout).
 */
#include <QJsonObject>
#include <QObject>
#include <QPointer>

#include <cstdint>
#include <vector>

namespace stylos::widgets {

class ViewportWidget;

class FrameBenchmark : public QObject {
    Q_OBJECT

public:
    /** @brief How many frames, and the wait before the first. */
    struct Run {
        int frames = 360;
        bool waitUntilRefined = true;
        int waitTimeoutMs = 120000;   ///< give up waiting for the first frame / refinement after this
    };

    /** @brief Starts (asynchronously); finished() carries the result. */
    void start();

    /** @brief The summary of per-frame times (ms) and points drawn (the keys of the result). */
    static QJsonObject summarize(const std::vector<double>& ms, const std::vector<std::uint64_t>& points);

Q_SIGNALS:
    void finished(const QJsonObject& result);

protected:
    FrameBenchmark(ViewportWidget& viewport, const Run& run, QObject* parent);

    /** @brief Once, when the view is ready, before the first timed frame: false stops with "error". */
    virtual bool prepare(ViewportWidget& viewport);
    /** @brief Changes what frame @p frame (0, 1, …) shows; timed with the frame. */
    virtual void advance(ViewportWidget& viewport, int frame) = 0;
    /** @brief Adds the keys of this kind of benchmark to @p result. */
    virtual void describe(QJsonObject& result) const = 0;

    QString m_error; ///< set by prepare() when it refuses

private:
    void waitForView();
    void step();
    void finish();

    QPointer<ViewportWidget> m_viewport;
    Run m_run;
    std::vector<double> m_ms;
    std::vector<std::uint64_t> m_points;
    int m_waitedMs = 0;
    double m_firstFrameMs = -1;
    std::uint64_t m_refinedPoints = 0;
    std::uint64_t m_cutsBefore = 0;  ///< LodScheduler::cutsStarted() before the first timed frame
};

} // namespace stylos::widgets
