#pragma once
/** @file
 * @brief The synthetic generators' random numbers: std::mt19937_64 (whose output the standard fixes)
 *        with our own conversions to uniform and normal variates, so the same seed gives the same
 *        numbers with every standard library (std::normal_distribution's output is implementation-
 *        defined). Not thread-safe: one Random per thread.
 */
#include <Eigen/Geometry>

#include <cstdint>
#include <random>

namespace stylos::core::synth {

class Random {
public:
    explicit Random(std::uint64_t seed) : m_engine(seed) {}

    /** A seed derived from @p seed and a @p stream number (splitmix64), for independent streams. */
    static std::uint64_t derive(std::uint64_t seed, std::uint64_t stream);

    /** 64 raw bits, e.g. to seed another generator. */
    std::uint64_t bits() { return m_engine(); }
    /** Uniform in [0, 1), 53 bits. */
    double uniform() { return static_cast<double>(m_engine() >> 11) * 0x1.0p-53; }
    /** Uniform in [lo, hi). */
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /** Standard normal (Box–Muller; the second variate of each pair is kept for the next call). */
    double normal();
    /** Uniformly distributed unit vector. */
    Eigen::Vector3d unitVector();
    /** Uniformly distributed rotation (normalised quaternion of four normal variates). */
    Eigen::Matrix3d rotation();

private:
    std::mt19937_64 m_engine;
    double m_spare = 0.0;
    bool m_hasSpare = false;
};

} // namespace stylos::core::synth
