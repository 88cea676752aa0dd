#pragma once
/** @file
 * @brief The bridge between a core algorithm's ProgressSink and a QPromise: progress goes to the
 *        promise (and from there to a QFutureWatcher on the GUI thread); Cancel on the future turns
 *        isCancelRequested() true. Thread-safe like QPromise: called from the worker thread.
 */
#include "stylos/core/util/Progress.h"

#include <QPromise>

#include <algorithm>
#include <atomic>

namespace stylos::widgets {

/** @brief Progress is reported in per-mille: the promise's range is set to [0, Scale]. */
inline constexpr int ProgressScale = 1000;

template <typename T>
class PromiseProgress final : public core::ProgressSink {
public:
    /** Maps this sink's [0, 1] onto [@p from, @p to] of the whole task (for multi-step tasks). */
    explicit PromiseProgress(QPromise<T>& promise, double from = 0.0, double to = 1.0)
        : m_promise(promise), m_from(from), m_to(to)
    {
    }

    void update(double fraction) override
    {
        const double f = m_from + (m_to - m_from) * std::clamp(fraction, 0.0, 1.0);
        const int value = static_cast<int>(f * ProgressScale);
        // Only forward changes: an algorithm may call this every few thousand points.
        if (m_last.exchange(value, std::memory_order_relaxed) != value) m_promise.setProgressValue(value);
    }

    bool isCancelRequested() const override { return m_promise.isCanceled(); }

private:
    QPromise<T>& m_promise;
    double m_from;
    double m_to;
    std::atomic<int> m_last{-1};
};

} // namespace stylos::widgets
