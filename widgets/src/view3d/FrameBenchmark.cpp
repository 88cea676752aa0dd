#include "stylos/widgets/view3d/FrameBenchmark.h"

#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace stylos::widgets {

namespace {
constexpr int PollMs = 20;
}

FrameBenchmark::FrameBenchmark(ViewportWidget& viewport, const Run& run, QObject* parent)
    : QObject(parent), m_viewport(&viewport), m_run(run)
{
}

bool FrameBenchmark::prepare(ViewportWidget&) { return true; }

void FrameBenchmark::start()
{
    m_ms.clear();
    m_points.clear();
    m_waitedMs = 0;
    m_error.clear();
    QTimer::singleShot(0, this, &FrameBenchmark::waitForView);
}

void FrameBenchmark::waitForView()
{
    if (!m_viewport) return finish();
    const bool drawn = m_viewport->firstFrameMs() >= 0;
    const bool settled = !m_run.waitUntilRefined || m_viewport->isSettled();
    if (drawn && settled) {
        m_viewport->renderNow(); // the refined view, drawn once
        m_firstFrameMs = m_viewport->firstFrameMs();
        m_refinedPoints = m_viewport->lastPointsDrawn();
        if (!prepare(*m_viewport)) return finish();
        m_cutsBefore = m_viewport->scheduler().cutsStarted();
        QTimer::singleShot(0, this, &FrameBenchmark::step);
        return;
    }
    if (m_waitedMs >= m_run.waitTimeoutMs) return finish();
    m_waitedMs += PollMs;
    QTimer::singleShot(PollMs, this, &FrameBenchmark::waitForView);
}

void FrameBenchmark::step()
{
    if (!m_viewport || int(m_ms.size()) >= m_run.frames) return finish();
    QElapsedTimer timer;
    timer.start();
    advance(*m_viewport, int(m_ms.size()));
    m_viewport->renderNow(); // drawn, swapped and finished (glFinish)
    m_ms.push_back(double(timer.nsecsElapsed()) * 1e-6);
    m_points.push_back(m_viewport->lastPointsDrawn());
    QTimer::singleShot(0, this, &FrameBenchmark::step);
}

QJsonObject FrameBenchmark::summarize(const std::vector<double>& ms, const std::vector<std::uint64_t>& points)
{
    QJsonObject o;
    o["frames"] = int(ms.size());
    if (ms.empty()) return o;
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t n = sorted.size();
    o["medianMs"] = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    o["p95Ms"] = sorted[std::size_t(std::ceil(0.95 * double(n))) - 1];
    o["meanMs"] = std::accumulate(sorted.begin(), sorted.end(), 0.0) / double(n);
    o["maxMs"] = sorted.back();
    if (!points.empty()) {
        o["meanPointsDrawn"] = double(std::accumulate(points.begin(), points.end(), std::uint64_t(0))) / double(points.size());
        o["minPointsDrawn"] = double(*std::min_element(points.begin(), points.end()));
        o["maxPointsDrawn"] = double(*std::max_element(points.begin(), points.end()));
    }
    return o;
}

void FrameBenchmark::finish()
{
    QJsonObject o = summarize(m_ms, m_points);
    if (m_viewport) {
        o["width"] = m_viewport->width();
        o["height"] = m_viewport->height();
        o["pointBudget"] = double(m_viewport->scheduler().pointBudget());
        o["targetFrameMs"] = m_viewport->scheduler().targetFrameMs();
        if (!m_ms.empty()) o["cutsStarted"] = double(m_viewport->scheduler().cutsStarted() - m_cutsBefore);
    }
    o["firstFrameMs"] = m_firstFrameMs;
    o["refinedPoints"] = double(m_refinedPoints);
    describe(o);
    if (!m_error.isEmpty()) o["error"] = m_error;
    else if (m_ms.empty()) o["error"] = QStringLiteral("the view showed no points within %1 ms").arg(m_run.waitTimeoutMs);
    Q_EMIT finished(o);
}

} // namespace stylos::widgets
