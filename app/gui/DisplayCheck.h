#pragma once
/** @file
 * @brief Before the workbench creates its window: is there a display to open it on?
 *
 * Qt aborts (exit 134, "could not connect to display") when no platform plugin can start. Stylos says
 * instead what to do: run it on a desktop, over `ssh -X`, or under a virtual display (`xvfb-run -a`), and
 * that `stylos-cli` needs none. --help and --version still answer without a display.
 */

namespace stylos::app {

/** @brief Whether the environment names a display or a platform: DISPLAY, WAYLAND_DISPLAY,
 *         QT_QPA_PLATFORM, or a `-platform` argument among @p argv. */
bool hasDisplay(int argc, const char* const* argv);

/**
 * @brief Without a display: answers --help and --version (which exit 0) and usage errors (a non-zero exit) as the
 *        workbench would (@p version for --version), else prints what to do on stderr and returns the exit status 1.
 *        Call it only when hasDisplay() is false; it creates (and destroys) a QCoreApplication.
 */
int runWithoutDisplay(int argc, char* argv[], const char* version);

} // namespace stylos::app
