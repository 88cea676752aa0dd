#include "stylos/core/shading/SkydomeShading.h"

#include "HorizonSweep.h"
#include "ParallelChunks.h"
#include "stylos/core/shading/DirectionRaster.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace stylos::core::shading {
namespace {

/** Runs sweepBand over every line of @p raster with @p threads workers; false when cancelled. */
template <typename Sink>
bool sweepDirection(const HeightField& field, const DirectionRaster& raster, unsigned threads,
                    std::vector<detail::BandScratch>& scratch, ProgressSink* progress, const Sink& sink)
{
    const float* heights = field.heights().data();
    const PixelState* states = field.states().data();
    const std::size_t bands = (std::size_t(raster.lineCount()) + detail::kBandLines - 1) / detail::kBandLines;
    return detail::parallelChunks(bands, 1, threads, progress, [&](std::size_t band, std::size_t, unsigned worker) {
        const int first = int(band) * detail::kBandLines;
        const int count = std::min(detail::kBandLines, raster.lineCount() - first);
        detail::sweepBand(raster, first, count, heights, states, field.width(), field.pixelSize(), scratch[worker],
                          sink);
    });
}

std::vector<detail::BandScratch> makeScratch(const HeightField& field, unsigned threads)
{
    return std::vector<detail::BandScratch>(threads, detail::BandScratch(std::max(field.width(), field.height())));
}

} // namespace

double skydomeAzimuth(int k, int directions) { return 2.0 * std::numbers::pi * k / directions; }

Result<ShadedImage> shadeSkydome(const HeightField& field, const SkydomeOptions& options, ProgressSink* progress)
{
    if (options.directions < 1 || options.directions > 4096)
        return Error{ErrorCode::InvalidArgument,
                     "skydome: " + std::to_string(options.directions) + " directions is not in [1, 4096]"};
    const unsigned threads = detail::resolveThreads(options.threads);
    auto scratch = makeScratch(field, threads);
    std::vector<float> occlusion(field.pixelCount(), 0.0f); // Σ_k sin θ_k
    float* sum = occlusion.data();
    const auto sink = [sum](std::size_t i, double rise, double run) {
        // sin θ for θ = max(0, atan(rise / run)), branch-free, in float (as the sum).
        const float r = float(std::max(rise, 0.0)), d = float(run);
        sum[i] += r / std::sqrt(r * r + d * d);
    };
    for (int k = 0; k < options.directions; ++k) {
        const DirectionRaster raster(field.width(), field.height(), skydomeAzimuth(k, options.directions));
        if (!sweepDirection(field, raster, threads, scratch, progress, sink))
            return Error{ErrorCode::Cancelled, "skydome: cancelled"};
        if (progress) progress->update(double(k + 1) / options.directions);
    }

    ShadedImage image{field.width(), field.height(), field.pixelSize(), std::move(occlusion), {}};
    image.coverage.assign(field.pixelCount(), 0);
    const auto states = field.states();
    const float directions = float(options.directions);
    for (std::size_t i = 0; i < image.values.size(); ++i) {
        const bool covered = states[i] != PixelState::Empty;
        image.coverage[i] = covered;
        image.values[i] = covered ? std::clamp(1.0f - image.values[i] / directions, 0.0f, 1.0f) : 0.0f;
    }
    return image;
}

Result<std::vector<float>> horizonAngles(const HeightField& field, double azimuth, unsigned threads,
                                         ProgressSink* progress)
{
    if (!std::isfinite(azimuth))
        return Error{ErrorCode::InvalidArgument, "skydome: the azimuth is not a finite number"};
    threads = detail::resolveThreads(threads);
    auto scratch = makeScratch(field, threads);
    std::vector<float> angles(field.pixelCount(), 0.0f);
    float* out = angles.data();
    const DirectionRaster raster(field.width(), field.height(), azimuth);
    const auto sink = [out](std::size_t i, double rise, double run) {
        out[i] = float(std::atan2(std::max(rise, 0.0), run));
    };
    if (!sweepDirection(field, raster, threads, scratch, progress, sink))
        return Error{ErrorCode::Cancelled, "skydome: cancelled"};
    if (progress) progress->update(1.0);
    return angles;
}

} // namespace stylos::core::shading
