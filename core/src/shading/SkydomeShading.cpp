#include "stylos/core/shading/SkydomeShading.h"

#include "HorizonBand.h"
#include "HorizonSources.h"
#include "ParallelChunks.h"
#include "stylos/core/shading/DirectionRaster.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

namespace stylos::core::shading {
namespace {

using Bands = std::vector<std::unique_ptr<detail::HorizonBand>>;

/**
 * Walks every band of @p raster: forward (its azimuth) and, when @p both, in reverse (the opposite
 * azimuth, on the same lines), both walks' values going to @p sum (laid out as @p source); without
 * @p sum, a single forward walk whose values go to sink(band). False when cancelled.
 */
template <typename Sink>
bool sweepDirection(const detail::BandSource& source, double pixelSize, const DirectionRaster& raster, bool both,
                    float* sum, detail::HorizonValue value, detail::GroupKernel kernel, unsigned threads, Bands& bands,
                    ProgressSink* progress, const Sink& sink)
{
    const detail::WalkGeometry geometry(raster, pixelSize);
    constexpr int lines = detail::HorizonBand::kLines;
    const std::size_t count = (std::size_t(raster.lineCount()) + lines - 1) / lines;
    // Chunks of 4 bands (64 lines) per hand-out; bands stay independent (each pixel is on one line).
    const auto work = [&](std::size_t begin, std::size_t end, unsigned worker) {
        detail::HorizonBand& band = *bands[worker];
        for (std::size_t b = begin; b < end; ++b) {
            const int first = int(b) * lines;
            band.prepare(raster, geometry, first, std::min(lines, raster.lineCount() - first), source);
            if (sum == nullptr) {
                band.walk(kernel, geometry, false, detail::WalkOutput::Values, value, nullptr);
                sink(band);
            } else if (both) {
                band.walk(kernel, geometry, false, detail::WalkOutput::Values, value, nullptr);
                band.walk(kernel, geometry, true, detail::WalkOutput::SumWithValues, value, sum);
            } else {
                band.walk(kernel, geometry, false, detail::WalkOutput::Sum, value, sum);
            }
        }
    };
    return detail::parallelChunks(count, 4, threads, progress, work);
}

Bands makeBands(const HeightField& field, unsigned threads)
{
    Bands bands;
    for (unsigned t = 0; t < threads; ++t)
        bands.push_back(std::make_unique<detail::HorizonBand>(std::max(field.width(), field.height())));
    return bands;
}

} // namespace

double skydomeAzimuth(int k, int directions) { return 2.0 * std::numbers::pi * k / directions; }

Result<ShadedImage> shadeSkydome(const HeightField& field, const SkydomeOptions& options, ProgressSink* progress)
{
    if (options.directions < 1 || options.directions > 4096)
        return Error{ErrorCode::InvalidArgument,
                     "skydome: " + std::to_string(options.directions) + " directions is not in [1, 4096]"};
    const unsigned threads = detail::resolveThreads(options.threads);
    const auto resolved = resolveSkydomeKernel(options.kernel);
    if (!resolved.ok()) return resolved.error();
    const auto kernel = detail::groupKernel(resolved.value());
    // With D even, direction k and its opposite k + D/2 walk the same lines (one read, two walks).
    const int D = options.directions;
    const int walked = D % 2 == 0 ? D / 2 : D;
    std::vector<DirectionRaster> columns, rows; // column-major rasters, then row-major ones
    for (int k = 0; k < walked; ++k) {
        DirectionRaster raster(field.width(), field.height(), skydomeAzimuth(k, D));
        (raster.columnMajor() ? columns : rows).push_back(std::move(raster));
    }
    auto bands = makeBands(field, threads);
    int done = 0;
    const auto sweepAll = [&](const std::vector<DirectionRaster>& rasters, const detail::BandSource& source,
                              float* sum) {
        for (const DirectionRaster& raster : rasters) {
            if (!sweepDirection(source, field.pixelSize(), raster, walked < D, sum, detail::HorizonValue::Sine, kernel,
                                threads, bands, progress, [](const auto&) {}))
                return false;
            if (progress) progress->update(double(++done) / walked);
        }
        return true;
    };
    // Σ_k sin θ_k: the column-major rasters first, on a transposed copy into a transposed sum; then the
    // row-major ones. Two 4-byte buffers per pixel, each used twice: (copy, sum) = (first, second),
    // then the transposed sum is turned back into first, and second takes the row-major copy.
    std::vector<float> first, second;
    detail::assignZeros(first, field.pixelCount());
    detail::assignZeros(second, field.pixelCount());
    if (!columns.empty()) {
        const auto source = detail::copyField(first.data(), field, true, threads);
        if (!sweepAll(columns, source, second.data())) return Error{ErrorCode::Cancelled, "skydome: cancelled"};
        detail::transposeBack(first.data(), second.data(), field.width(), field.height(), threads);
    }
    const auto source = detail::copyField(second.data(), field, false, threads);
    if (!sweepAll(rows, source, first.data())) return Error{ErrorCode::Cancelled, "skydome: cancelled"};
    std::vector<float> occlusion = std::move(first);
    second = {};

    ShadedImage image{field.width(), field.height(), field.pixelSize(), std::move(occlusion), {}};
    image.coverage.assign(field.pixelCount(), 0);
    const PixelState* states = field.states().data();
    const float directions = float(options.directions);
    detail::parallelChunks(image.values.size(), std::size_t(1) << 16, threads, nullptr,
                           [&](std::size_t begin, std::size_t end, unsigned) {
                               for (std::size_t i = begin; i < end; ++i) {
                                   const bool covered = states[i] != PixelState::Empty;
                                   const float sky = 1.0f - image.values[i] / directions;
                                   image.coverage[i] = covered;
                                   image.values[i] = covered ? std::clamp(sky, 0.0f, 1.0f) : 0.0f;
                               }
                           });
    return image;
}

Result<std::vector<float>> horizonAngles(const HeightField& field, double azimuth, unsigned threads,
                                         ProgressSink* progress, SkydomeKernel kernelAsked)
{
    if (!std::isfinite(azimuth))
        return Error{ErrorCode::InvalidArgument, "skydome: the azimuth is not a finite number"};
    const auto kernel = resolveSkydomeKernel(kernelAsked);
    if (!kernel.ok()) return kernel.error();
    threads = detail::resolveThreads(threads);
    const DirectionRaster raster(field.width(), field.height(), azimuth);
    const bool columnMajor = raster.columnMajor();
    std::vector<float> copy;
    detail::assignZeros(copy, field.pixelCount());
    const auto source = detail::copyField(copy.data(), field, columnMajor, threads);
    auto bands = makeBands(field, threads);
    std::vector<float> angles(field.pixelCount(), 0.0f);
    float* out = angles.data();
    const std::size_t width = std::size_t(field.width()), height = std::size_t(field.height());
    const auto sink = [&](const detail::HorizonBand& band) {
        band.forEachValue([&](std::size_t e, float slope) {
            const std::size_t i = columnMajor ? (e % height) * width + e / height : e; // e is transposed
            out[i] = float(std::atan(double(slope)));
        });
    };
    if (!sweepDirection(source, field.pixelSize(), raster, false, nullptr, detail::HorizonValue::Slope,
                        detail::groupKernel(kernel.value()), threads, bands, progress, sink))
        return Error{ErrorCode::Cancelled, "skydome: cancelled"};
    if (progress) progress->update(1.0);
    return angles;
}

} // namespace stylos::core::shading
