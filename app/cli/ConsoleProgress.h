#pragma once
// Progress on stderr (only when stderr is a terminal) and cancel on Ctrl-C, for stylos-cli.
#include "stylos/core/util/Progress.h"

#include <atomic>
#include <mutex>
#include <string>

namespace stylos::cli {

/** Thread-safe, as ProgressSink requires: workers of a parallel stage may all report. */
class ConsoleProgress final : public core::ProgressSink {
public:
    explicit ConsoleProgress(std::string label);
    ~ConsoleProgress() override;
    void update(double fraction) override;
    bool isCancelRequested() const override;

private:
    std::string m_label;
    std::atomic<int> m_lastPercent{-1};
    std::mutex m_print;
    bool m_tty = false;
};

/** Installs a SIGINT handler that turns Ctrl-C into a cancel request for every ConsoleProgress. */
void installInterruptHandler();

} // namespace stylos::cli
