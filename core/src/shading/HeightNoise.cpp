#include "stylos/core/shading/HeightNoise.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

namespace stylos::core::shading {

namespace {

/** Runs @p body(first, last) over [0, count) in about equal chunks on @p threads threads. */
template <typename Body>
void parallelRanges(int count, unsigned threads, Body body)
{
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = std::min<unsigned>(threads, unsigned(std::max(1, count / 16)));
    if (threads <= 1) {
        body(0, count);
        return;
    }
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back([&, t] { body(int(std::int64_t(count) * t / threads), int(std::int64_t(count) * (t + 1) / threads)); });
    body(0, int(std::int64_t(count) / threads));
    for (std::thread& thread : pool) thread.join();
}

std::vector<float> gaussianTaps(double sigmaPixels)
{
    const int radius = int(std::ceil(3.0 * sigmaPixels));
    std::vector<float> taps(std::size_t(2 * radius + 1));
    for (int k = -radius; k <= radius; ++k)
        taps[std::size_t(k + radius)] = float(std::exp(-0.5 * (k * k) / (sigmaPixels * sigmaPixels)));
    return taps;
}

} // namespace

double estimateHeightNoise(const HeightField& field)
{
    const int w = field.width(), h = field.height();
    std::vector<float> residuals;
    // At most about 2 M samples, on a regular stride of rows (the median needs no more).
    const int rowStep = std::max(1, int((std::int64_t(w) * h) / 2'000'000));
    for (int r = 1; r + 1 < h; r += rowStep)
        for (int c = 1; c + 1 < w; ++c) {
            if (field.stateAt(c, r) != PixelState::Measured) continue;
            if (field.stateAt(c - 1, r) != PixelState::Measured || field.stateAt(c + 1, r) != PixelState::Measured ||
                field.stateAt(c, r - 1) != PixelState::Measured || field.stateAt(c, r + 1) != PixelState::Measured)
                continue;
            const float around = 0.25f * (field.heightAt(c - 1, r) + field.heightAt(c + 1, r) +
                                          field.heightAt(c, r - 1) + field.heightAt(c, r + 1));
            residuals.push_back(std::abs(field.heightAt(c, r) - around));
        }
    if (residuals.size() < 64) return 0.0;
    const auto middle = residuals.begin() + std::ptrdiff_t(residuals.size() / 2);
    std::nth_element(residuals.begin(), middle, residuals.end());
    return 1.4826 * double(*middle) / std::sqrt(1.25);
}

double noiseSmoothingSigma(double noise, double pixelSize)
{
    if (!(noise > 0.0) || !(pixelSize > 0.0)) return 0.0;
    const double pixels = noise / (2.0 * std::sqrt(std::numbers::pi) * kSlopeNoise * pixelSize);
    if (pixels < 0.5) return 0.0;
    return std::min(pixels, kMaxSmoothingPixels) * pixelSize;
}

Result<HeightField> smoothHeights(const HeightField& field, double sigma, unsigned threads)
{
    const double pixels = sigma / field.pixelSize();
    if (!std::isfinite(sigma) || sigma < 0.0 || pixels > kMaxSmoothingPixels + 1e-9)
        return Error::at(ErrorCode::InvalidArgument, "", "",
                         "the smoothing must be between 0 and " + std::to_string(kMaxSmoothingPixels) +
                             " pixels (" + std::to_string(kMaxSmoothingPixels * field.pixelSize() * 1e3) + " mm), got " +
                             std::to_string(sigma * 1e3) + " mm");
    HeightField out = field;
    if (sigma == 0.0 || field.pixelCount() == 0) return out;

    const std::vector<float> taps = gaussianTaps(pixels);
    const int radius = int(taps.size() / 2);
    const int w = field.width(), h = field.height();
    const auto states = field.states();
    const auto heights = field.heights();
    // Pass 1, along rows: weighted sums of height·valid and of valid.
    std::vector<float> sumH(field.pixelCount()), sumW(field.pixelCount());
    parallelRanges(h, threads, [&](int first, int last) {
        for (int r = first; r < last; ++r) {
            const std::size_t row = std::size_t(r) * std::size_t(w);
            for (int c = 0; c < w; ++c) {
                float sh = 0.0f, sw = 0.0f;
                const int k0 = std::max(-radius, -c), k1 = std::min(radius, w - 1 - c);
                for (int k = k0; k <= k1; ++k) {
                    const std::size_t i = row + std::size_t(c + k);
                    if (states[i] == PixelState::Empty) continue;
                    const float t = taps[std::size_t(k + radius)];
                    sh += t * heights[i];
                    sw += t;
                }
                sumH[row + std::size_t(c)] = sh;
                sumW[row + std::size_t(c)] = sw;
            }
        }
    });
    // Pass 2, along columns, then the ratio on the non-empty pixels.
    auto outHeights = out.heights();
    parallelRanges(h, threads, [&](int first, int last) {
        std::vector<float> accH(static_cast<std::size_t>(w)), accW(static_cast<std::size_t>(w));
        for (int r = first; r < last; ++r) {
            std::fill(accH.begin(), accH.end(), 0.0f);
            std::fill(accW.begin(), accW.end(), 0.0f);
            const int k0 = std::max(-radius, -r), k1 = std::min(radius, h - 1 - r);
            for (int k = k0; k <= k1; ++k) { // whole rows at a time: sequential reads
                const float t = taps[std::size_t(k + radius)];
                const float* rowH = sumH.data() + std::size_t(r + k) * std::size_t(w);
                const float* rowW = sumW.data() + std::size_t(r + k) * std::size_t(w);
                for (int c = 0; c < w; ++c) {
                    accH[std::size_t(c)] += t * rowH[c];
                    accW[std::size_t(c)] += t * rowW[c];
                }
            }
            const std::size_t row = std::size_t(r) * std::size_t(w);
            for (int c = 0; c < w; ++c)
                if (states[row + std::size_t(c)] != PixelState::Empty)
                    outHeights[row + std::size_t(c)] = accH[std::size_t(c)] / accW[std::size_t(c)]; // > 0: itself
        }
    });
    return out;
}

} // namespace stylos::core::shading
