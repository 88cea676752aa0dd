#pragma once
// What the benchmarks record beside their figures: a monotonic clock and the machine's load average.
#include <chrono>
#include <fstream>
#include <string>

namespace stylos::bench {

/** Seconds on the steady clock (differences only). */
inline double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

/** The 1, 5 and 15 minute load averages as /proc/loadavg gives them ("" where there is none). */
inline std::string loadAverage()
{
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

} // namespace stylos::bench
