#pragma once
/** @file
 * @brief Progress and cancel for long algorithms. Algorithms call update() every few thousand items
 *        and stop with ErrorCode::Cancelled when isCancelRequested() turns true.
 *        Implementations must be thread-safe: workers may call them from any thread.
 */
#include <atomic>

namespace stylos::core {

class ProgressSink {
public:
    virtual ~ProgressSink() = default;
    /** Fraction done in [0, 1]. */
    virtual void update(double fraction) = 0;
    virtual bool isCancelRequested() const = 0;
};

/** @brief A sink that reports nothing and can be cancelled from another thread (tests, CLI). */
class SilentProgress final : public ProgressSink {
public:
    void update(double fraction) override { m_last.store(fraction, std::memory_order_relaxed); }
    bool isCancelRequested() const override { return m_cancel.load(std::memory_order_relaxed); }
    void cancel() { m_cancel.store(true); }
    double last() const { return m_last.load(std::memory_order_relaxed); }

private:
    std::atomic<bool> m_cancel{false};
    std::atomic<double> m_last{0.0};
};

} // namespace stylos::core
