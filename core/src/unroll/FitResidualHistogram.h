#pragma once
// Internal to the surface fit: a histogram of absolute residuals on a logarithmic scale, for the
// robust trimming threshold.
#include <bit>
#include <cstdint>
#include <vector>

namespace stylos::core::unroll::detail {

/**
 * @brief Counts of |residual| / scale in bins of 1/128 octave (0.54 % wide) from 2⁻⁴⁰ to 2⁸, plus an
 *        underflow bin [0, 2⁻⁴⁰) and an overflow bin (≥ 2⁸, and NaN). Integer counts: histograms
 *        merged in any order are equal, so thresholds do not depend on the thread count.
 *        Quantiles interpolate linearly within a bin. Not thread-safe (one per worker, then merge).
 */
class FitResidualHistogram {
  public:
    static constexpr int kBins = 48 * 128 + 2;

    /** Residuals are counted in units of @p scale (> 0, metres). */
    explicit FitResidualHistogram(double scale);

    void add(double absResidual)
    {
        const float v = static_cast<float>(absResidual * m_inverseScale);
        const std::uint32_t bits = std::bit_cast<std::uint32_t>(v); // v ≥ 0: the bits grow with v
        std::uint32_t bin = bits < kLowBits ? 0u : ((bits - kLowBits) >> kShift) + 1u;
        if (bin > kBins - 1) bin = kBins - 1;
        ++m_counts[bin];
    }
    void merge(const FitResidualHistogram& other);
    void clear();
    std::uint64_t total() const;

    /**
     * @brief The trimming threshold: the fixed point of τ = max(κ · 1.4826 · median{|r| : |r| ≤ τ}, floor)
     *        reached from @p start (metres) — the scale of the residuals kept, made robust to any
     *        share of outliers outside the band (bed faces, a broken cavity). For Gaussian residuals
     *        of σ with κ = 3 it converges near 3σ (the truncation shrinks the median slightly).
     * @return the threshold in metres; @p start when no residual is below it.
     */
    double trimThreshold(double start, double kappa, double floor) const;

    /** Number of residuals ≤ @p x metres, interpolated within its bin. */
    double countBelow(double x) const;
    /** The residual (metres) below which @p count residuals lie (the inverse of countBelow). */
    double valueAtCount(double count) const;

  private:
    static constexpr std::uint32_t kLowBits = 0x2B800000u; ///< bits of 2⁻⁴⁰ as a float
    static constexpr int kShift = 23 - 7;                  ///< 2⁷ bins per octave
    double binLow(int bin) const;                          ///< lower edge, in units of scale
    double binHigh(int bin) const;
    void cumulate() const;

    double m_scale;
    double m_inverseScale;
    std::vector<std::uint64_t> m_counts;
    mutable std::vector<double> m_cumulative; ///< m_cumulative[b] = counts of the bins before b
    mutable bool m_dirty = true;
};

} // namespace stylos::core::unroll::detail
