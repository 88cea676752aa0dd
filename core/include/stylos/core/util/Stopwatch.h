#pragma once
/** @file
 * @brief Wall time for the reports of long steps (the "seconds" of the JSON outputs): the steady clock,
 *        and the seconds elapsed since a time point. Thread-safety: pure functions.
 */
#include <chrono>

namespace stylos::core {

using Clock = std::chrono::steady_clock;

/** @brief Seconds from @p start to now. */
inline double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace stylos::core
