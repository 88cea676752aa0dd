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
 * azimuth, on the same lines), both walks' values going to @p sum (laid out as the raster's source);
 * without @p sum, a single forward walk whose values go to sink(band). False when cancelled.
 */
template <typename Sink>
bool sweepDirection(const detail::HorizonSources& sources, double pixelSize, const DirectionRaster& raster, bool both,
                    float* sum, detail::HorizonValue value, detail::GroupKernel kernel, unsigned threads, Bands& bands,
                    ProgressSink* progress, const Sink& sink)
{
    const detail::WalkGeometry geometry(raster, pixelSize);
    const detail::BandSource source = sources.source(raster);
    constexpr int lines = detail::HorizonBand::kLines;
    const std::size_t count = (std::size_t(raster.lineCount()) + lines - 1) / lines;
    // Chunks of 4 bands: fewer hand-outs; bands stay independent (each pixel is on one line).
    return detail::parallelChunks(count, 4, threads, progress, [&](std::size_t begin, std::size_t end, unsigned worker) {
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
    });
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
    const auto kernel = detail::groupKernel(options.simd);
    // With D even, direction k and its opposite k + D/2 walk the same lines (one load, two walks).
    const int D = options.directions;
    const int walked = D % 2 == 0 ? D / 2 : D;
    std::vector<DirectionRaster> rasters;
    bool columnMajor = false;
    for (int k = 0; k < walked; ++k) {
        rasters.emplace_back(field.width(), field.height(), skydomeAzimuth(k, D));
        columnMajor = columnMajor || rasters.back().columnMajor();
    }
    const detail::HorizonSources sources(field, columnMajor, threads);
    auto bands = makeBands(field, threads);
    // Σ_k sin θ_k, row-major for the row-major rasters, transposed for the column-major ones.
    std::vector<float> occlusion(field.pixelCount(), 0.0f), transposed(columnMajor ? field.pixelCount() : 0, 0.0f);
    for (int k = 0; k < walked; ++k) {
        float* sum = rasters[std::size_t(k)].columnMajor() ? transposed.data() : occlusion.data();
        if (!sweepDirection(sources, field.pixelSize(), rasters[std::size_t(k)], walked < D, sum,
                            detail::HorizonValue::Sine, kernel, threads, bands, progress, [](const auto&) {}))
            return Error{ErrorCode::Cancelled, "skydome: cancelled"};
        if (progress) progress->update(double(k + 1) / walked);
    }
    if (columnMajor) detail::addTransposed(occlusion.data(), transposed.data(), field.width(), field.height(), threads);

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
    const DirectionRaster raster(field.width(), field.height(), azimuth);
    const detail::HorizonSources sources(field, raster.columnMajor(), threads);
    auto bands = makeBands(field, threads);
    std::vector<float> angles(field.pixelCount(), 0.0f);
    float* out = angles.data();
    const std::size_t width = std::size_t(field.width()), height = std::size_t(field.height());
    const bool columnMajor = raster.columnMajor();
    const auto sink = [&](const detail::HorizonBand& band) {
        band.forEachValue([&](std::size_t e, float slope) {
            const std::size_t i = columnMajor ? (e % height) * width + e / height : e; // e is transposed
            out[i] = float(std::atan(double(slope)));
        });
    };
    if (!sweepDirection(sources, field.pixelSize(), raster, false, nullptr, detail::HorizonValue::Slope,
                        detail::groupKernel(true), threads, bands, progress, sink))
        return Error{ErrorCode::Cancelled, "skydome: cancelled"};
    if (progress) progress->update(1.0);
    return angles;
}

} // namespace stylos::core::shading
