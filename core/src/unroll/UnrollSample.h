#pragma once
// Internal to the unroller: a deterministic pseudo-random sample of point indices.
#include <cmath>
#include <cstdint>

namespace stylos::core::unroll::detail {

/**
 * @brief Takes index i when splitmix64(i) < rate · 2^64: about rate · n of n indices, the same ones on
 *        every run and every thread count, with no aliasing against the scan order (a stride would
 *        pick one column of a scan grid). rate ≥ 1 takes every index. Immutable; thread-safe.
 */
class UnrollSample {
public:
    /** A sample of about @p wanted of @p total indices (all of them when total ≤ wanted). */
    UnrollSample(double wanted, std::uint64_t total)
        : m_rate(total == 0 || double(total) <= wanted ? 1.0 : wanted / double(total)),
          m_threshold(m_rate >= 1.0 ? ~std::uint64_t(0) : std::uint64_t(std::ldexp(m_rate, 64)))
    {
    }

    double rate() const { return m_rate; }
    bool taken(std::uint64_t i) const { return m_rate >= 1.0 || mix(i) < m_threshold; }

    static std::uint64_t mix(std::uint64_t x)
    {
        x += 0x9e3779b97f4a7c15ull;
        x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
        x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
        return x ^ (x >> 31);
    }

private:
    double m_rate;
    std::uint64_t m_threshold;
};

} // namespace stylos::core::unroll::detail
