#pragma once
// Internal to the skydome: a group of 16 neighbouring rasterised lines, prepared for the horizon
// kernel and walked in one or both directions.
#include "HorizonSweep.h"
#include "stylos/core/shading/DirectionRaster.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace stylos::core::shading::detail {

/**
 * The constants of one direction's walks: the position key of every major index (HorizonSweep.h;
 * steps counted against the raster's direction, the order of a forward walk) and the metres per step
 * and per minor-axis move. Read-only once built: shared by the workers.
 */
struct WalkGeometry {
    std::vector<std::int32_t> keys; ///< per major index
    float along = 1.0f;             ///< |d_major| · pixel size, metres
    float across = 0.0f;            ///< |d_minor| · pixel size, metres
    WalkGeometry(const DirectionRaster& raster, double pixelSize);
};

/**
 * Where a band reads its heights (metres, NaN where Empty): pixel (major a, minor b) of a raster at
 * element a · stride + b, so that the 16 pixels of a step are contiguous (HorizonSources.h).
 */
struct BandSource {
    const float* heights = nullptr;
    std::size_t stride = 0;
};

/**
 * Scratch of one worker: 16 consecutive lines of a raster (one kernel group) as the kernel walks them:
 * per step the element of lane 0 and the lanes inside the grid, the heights read by the first walk,
 * the values, and the hull stacks. Not thread-safe: one per worker.
 */
class HorizonBand {
public:
    static constexpr int kLines = kGroupLanes;

    /** Room for bands of up to @p longestLine steps. */
    explicit HorizonBand(int longestLine);

    /** Prepares lines [firstLine, firstLine + count) of @p raster (count in [1, kLines]) read from @p source. */
    void prepare(const DirectionRaster& raster, const WalkGeometry& geometry, int firstLine, int count,
                 const BandSource& source);

    /**
     * Runs @p kernel over the band: a forward walk is the raster's azimuth and reads the source, a
     * reverse one the opposite azimuth (same lines) and reads what the forward walk read. @p sum (in
     * the source's layout) receives the values for the WalkOutput::Sum* outputs.
     */
    void walk(GroupKernel kernel, const WalkGeometry& geometry, bool reverse, WalkOutput output, HorizonValue value,
              float* sum);

    /** Calls f(element index in the source's layout, value) for every pixel (after a Values walk). */
    template <typename F>
    void forEachValue(F&& f) const
    {
        for (int s = 0; s < m_steps; ++s)
            for (int j = 0; j < kLines; ++j)
                if ((m_inside[std::size_t(s)] >> j) & 1u)
                    f(std::size_t(m_offsets[std::size_t(s)] + j), m_values[std::size_t(s) * kLines + std::size_t(j)]);
    }

private:
    std::vector<float> m_heights, m_values; // [step][lane]
    std::vector<std::int32_t> m_keys;       // [step]
    std::vector<std::int64_t> m_offsets;    // [step]
    std::vector<std::uint16_t> m_inside;    // [step]
    HullStacks m_stacks;
    BandSource m_source;
    int m_steps = 0;
};

} // namespace stylos::core::shading::detail
