#include "ConsoleProgress.h"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <unistd.h>

namespace stylos::cli {

namespace {
std::atomic<bool> g_interrupted{false};
extern "C" void onInterrupt(int) { g_interrupted.store(true); }
} // namespace

void installInterruptHandler() { std::signal(SIGINT, onInterrupt); }

ConsoleProgress::ConsoleProgress(std::string label) : m_label(std::move(label)), m_tty(::isatty(2) != 0) {}

ConsoleProgress::~ConsoleProgress()
{
    if (m_tty && m_lastPercent >= 0) std::fputs("\n", stderr);
}

void ConsoleProgress::update(double fraction)
{
    const int percent = static_cast<int>(fraction * 100.0);
    if (!m_tty || m_lastPercent.exchange(percent) == percent) return;
    std::lock_guard lock(m_print);
    std::fprintf(stderr, "\r%s %3d%%", m_label.c_str(), percent);
    std::fflush(stderr);
}

bool ConsoleProgress::isCancelRequested() const { return g_interrupted.load(); }

} // namespace stylos::cli
