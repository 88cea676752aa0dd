#pragma once
/** @file
 * @brief Automation: orbits the camera of a ViewportWidget for N frames and reports the frame times,
 *        for `stylos --orbit-benchmark N FILE` and for measurements. Each frame turns the camera about
 *        the scene's vertical axis through the target, draws a frame synchronously (ViewportWidget::renderNow:
 *        drawing and the swap of the view's native window) and waits for the GPU (glFinish); the time of the whole is measured with
 *        QElapsedTimer. Between frames control returns to the event loop (a zero timer), so that the
 *        level-of-detail cuts computed in the background are delivered as they would be interactively.
 *
 * Before the first frame it waits until the view has drawn points and (by default) has been refined,
 * the state after opening a file and letting it settle.
 * Result (finished()): a JSON object {"frames", "width", "height", "medianMs", "p95Ms", "meanMs",
 * "maxMs", "meanPointsDrawn", "minPointsDrawn", "maxPointsDrawn", "pointBudget", "targetFrameMs",
 * "firstFrameMs", "refinedPoints", "degreesPerFrame"}; frame times in ms, p95 by the nearest rank.
 * GUI thread only. Failure modes: none; a viewport without fragments never starts (finished() is
 * emitted with "error" after the wait timeout).
 */
#include <QJsonObject>
#include <QObject>
#include <QPointer>

#include <cstdint>
#include <vector>

namespace stylos::widgets {

class ViewportWidget;

class OrbitBenchmark : public QObject {
    Q_OBJECT

public:
    struct Options {
        int frames = 360;
        double degreesPerFrame = 1.0;
        bool waitUntilRefined = true;
        int waitTimeoutMs = 120000;   ///< give up waiting for the first frame / refinement after this
    };

    OrbitBenchmark(ViewportWidget& viewport, const Options& options, QObject* parent = nullptr);

    /** @brief Starts (asynchronously); finished() carries the result. */
    void start();

    /** @brief The summary of per-frame times (ms) and points drawn (the keys of the result). */
    static QJsonObject summarize(const std::vector<double>& ms, const std::vector<std::uint64_t>& points);

Q_SIGNALS:
    void finished(const QJsonObject& result);

private:
    void waitForView();
    void step();
    void finish();

    QPointer<ViewportWidget> m_viewport;
    Options m_options;
    std::vector<double> m_ms;
    std::vector<std::uint64_t> m_points;
    int m_waitedMs = 0;
    double m_firstFrameMs = -1;
    std::uint64_t m_refinedPoints = 0;
};

} // namespace stylos::widgets
