#include "stylos/core/shading/SkyViewFactor.h"

#include "ParallelChunks.h"
#include "stylos/core/shading/SkydomeShading.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace stylos::core::shading {
namespace {

constexpr std::size_t kRowsPerChunk = 16;

/** One sample of a ray: a pixel offset and 1 / its metric length. */
struct RaySample {
    int dc, dr;
    float inverseDistance;
};

/** RVT's horizon_shift_vector for one azimuth: distinct rounded offsets at radii r_min + j/3. */
std::vector<RaySample> raySamples(double azimuth, int minRadius, int radius, double pixelSize)
{
    std::vector<RaySample> samples;
    const double dc = std::sin(azimuth), dr = -std::cos(azimuth);
    for (int j = 0; j <= (radius - minRadius) * 3; ++j) {
        const double r = minRadius + j / 3.0;
        const int c = int(std::nearbyint(r * dc)), w = int(std::nearbyint(r * dr)); // half to even
        if ((c == 0 && w == 0)
            || std::any_of(samples.begin(), samples.end(), [&](const RaySample& s) { return s.dc == c && s.dr == w; }))
            continue;
        samples.push_back({c, w, float(1.0 / (std::sqrt(double(c * c + w * w)) * pixelSize))});
    }
    return samples;
}

} // namespace

Result<ShadedImage> shadeSkyViewFactor(const HeightField& field, const SkyViewOptions& options, ProgressSink* progress)
{
    if (options.directions < 1 || options.directions > 4096)
        return Error{ErrorCode::InvalidArgument,
                     "sky-view factor: " + std::to_string(options.directions) + " directions is not in [1, 4096]"};
    if (options.minRadius < 1 || options.radius < options.minRadius || options.radius > 4096)
        return Error{ErrorCode::InvalidArgument, "sky-view factor: radii " + std::to_string(options.minRadius)
                                                     + " .. " + std::to_string(options.radius)
                                                     + " px are not 1 <= min <= max <= 4096"};
    const int width = field.width(), height = field.height();
    std::vector<std::vector<RaySample>> rays;
    for (int k = 0; k < options.directions; ++k)
        rays.push_back(raySamples(skydomeAzimuth(k, options.directions), options.minRadius, options.radius,
                                  field.pixelSize()));

    // Heights with NaN on Empty pixels: a NaN slope never wins the maximum below.
    std::vector<float> heights(field.heights().begin(), field.heights().end());
    const auto states = field.states();
    for (std::size_t i = 0; i < heights.size(); ++i)
        if (states[i] == PixelState::Empty) heights[i] = std::numeric_limits<float>::quiet_NaN();

    ShadedImage image{width, height, field.pixelSize(), std::vector<float>(field.pixelCount(), 0.0f), {}};
    const unsigned threads = detail::resolveThreads(options.threads);
    std::vector<std::vector<float>> scratch(threads, std::vector<float>(std::size_t(2 * width)));
    const float* h = heights.data();
    const bool done = detail::parallelChunks(
        std::size_t(height), kRowsPerChunk, threads, progress, [&](std::size_t begin, std::size_t end, unsigned worker) {
            float* best = scratch[worker].data();      // largest slope per column, this direction
            float* occlusion = best + width;           // Σ_k sin θ_k per column
            for (std::size_t r = begin; r < end; ++r) {
                const float* row = h + r * std::size_t(width);
                std::fill(occlusion, occlusion + width, 0.0f);
                for (const auto& ray : rays) {
                    std::fill(best, best + width, 0.0f); // θ is clamped at 0: start from slope 0
                    for (const RaySample& s : ray) {
                        const std::ptrdiff_t rr = std::ptrdiff_t(r) + s.dr;
                        if (rr < 0 || rr >= height) continue;
                        const float* other = h + rr * std::ptrdiff_t(width);
                        const int first = std::max(0, -s.dc), last = std::min(width, width - s.dc);
                        const float inverse = s.inverseDistance;
                        for (int c = first; c < last; ++c) {
                            const float slope = (other[c + s.dc] - row[c]) * inverse;
                            best[c] = slope > best[c] ? slope : best[c];
                        }
                    }
                    for (int c = 0; c < width; ++c)
                        occlusion[c] += best[c] / std::sqrt(1.0f + best[c] * best[c]);
                }
                float* out = image.values.data() + r * std::size_t(width);
                const float directions = float(options.directions);
                for (int c = 0; c < width; ++c) out[c] = std::clamp(1.0f - occlusion[c] / directions, 0.0f, 1.0f);
            }
        });
    if (!done) return Error{ErrorCode::Cancelled, "sky-view factor: cancelled"};

    image.coverage.assign(field.pixelCount(), 0);
    for (std::size_t i = 0; i < heights.size(); ++i) {
        image.coverage[i] = states[i] != PixelState::Empty;
        if (!image.coverage[i]) image.values[i] = 0.0f;
    }
    if (progress) progress->update(1.0);
    return image;
}

} // namespace stylos::core::shading
