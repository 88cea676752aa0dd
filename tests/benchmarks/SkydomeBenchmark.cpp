// Skydome speed on a 4096 × 4096 fractal terrain (0.5 mm pixels, 2 m side): the exact hull sweep in
// ns per pixel·direction (issue target: ≤ 5 ns on 2 cores) against the RVT-like radius-limited ray
// march (16 directions, 10 px), and how far apart their images are; the portable, AVX2 and AVX-512
// kernels side by side (BM_SkydomeHullSweep's third argument).
// stylos_benchmarks --benchmark_filter=Skydome
#include "stylos/core/shading/SkyViewFactor.h"
#include "stylos/core/shading/SkydomeShading.h"
#include "stylos/core/synth/FractalNoise.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

using namespace stylos::core;
using namespace stylos::core::shading;

namespace {

constexpr int kSide = 4096;

/** fBm relief: 1 cm at 0.5 m wavelength down to ~1 mm (10 octaves), plus fine tool-mark-like ripples. */
const HeightField& terrain()
{
    static const HeightField field = [] {
        auto f = HeightField::create(kSide, kSide, 0.0005).value();
        const synth::FractalNoise noise(11, 0.5, 0.01, 10);
        auto rows = [&](int begin, int end) {
            for (int r = begin; r < end; ++r)
                for (int c = 0; c < kSide; ++c) {
                    const double x = c * 0.0005, y = r * 0.0005;
                    f.setMeasured(c, r, float(noise.value(x, y) + 0.0002 * std::sin(x * 900.0 + 0.3 * y * 900.0)));
                }
        };
        std::thread helper(rows, 0, kSide / 2);
        rows(kSide / 2, kSide);
        helper.join();
        return f;
    }();
    return field;
}

/** Sets the per-pixel·direction time, in ns, from a measured duration. */
void reportRate(benchmark::State& state, double seconds, int directions)
{
    const double items = double(kSide) * kSide * directions * double(state.iterations());
    state.counters["ns_per_pixel_dir"] = seconds * 1e9 / items;
    state.counters["directions"] = directions;
}

template <typename Run>
void timed(benchmark::State& state, int directions, Run&& run)
{
    double seconds = 0.0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        auto image = run();
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!image.ok()) state.SkipWithError(image.error().message.c_str());
        benchmark::DoNotOptimize(image);
    }
    reportRate(state, seconds, directions);
}

/**
 * Args: directions, threads (0 = hardware threads), kernel (SkydomeKernel: 0 auto, 1 portable, 2 AVX2,
 * 3 AVX-512; a kernel this CPU lacks is skipped). The label names the kernel that ran.
 */
void BM_SkydomeHullSweep(benchmark::State& state)
{
    const auto& field = terrain();
    const SkydomeOptions options{int(state.range(0)), unsigned(state.range(1)), SkydomeKernel(state.range(2))};
    const auto kernel = resolveSkydomeKernel(options.kernel);
    if (!kernel.ok()) {
        state.SkipWithError(kernel.error().message.c_str());
        return;
    }
    state.SetLabel(std::string(skydomeKernelName(kernel.value())));
    timed(state, options.directions, [&] { return shadeSkydome(field, options); });
}
// Auto first (the fastest of this CPU), then the three kernels side by side at 32 directions, on 2
// threads and on 1.
BENCHMARK(BM_SkydomeHullSweep)
    ->Args({32, 0, 0})->Args({40, 0, 0})->Args({16, 0, 0})->Args({32, 1, 0})
    ->Args({32, 0, 1})->Args({32, 0, 2})->Args({32, 0, 3})->Args({32, 1, 1})->Args({32, 1, 2})->Args({32, 1, 3})
    ->ArgNames({"directions", "threads", "kernel"})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

/** Args: directions, radius (px), threads. */
void BM_SkydomeRvtRayMarch(benchmark::State& state)
{
    const auto& field = terrain();
    const SkyViewOptions options{int(state.range(0)), int(state.range(1)), 1, unsigned(state.range(2))};
    timed(state, options.directions, [&] { return shadeSkyViewFactor(field, options); });
}
BENCHMARK(BM_SkydomeRvtRayMarch)
    ->Args({16, 10, 0})->Args({16, 10, 1})->Args({32, 100, 0})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

/** Difference between the exact skydome (Args: directions) and RVT's SVF (16 directions, 10 px). */
void BM_SkydomeVersusRvt(benchmark::State& state)
{
    const auto& field = terrain();
    const int directions = int(state.range(0));
    double mad = 0.0, correlation = 0.0, largest = 0.0, meanDome = 0.0, meanRvt = 0.0;
    for (auto _ : state) {
        const auto dome = shadeSkydome(field, {directions, 0});
        const auto rvt = shadeSkyViewFactor(field, {16, 10, 1, 0});
        if (!dome.ok() || !rvt.ok()) {
            state.SkipWithError("shading failed");
            return;
        }
        const std::size_t n = dome->values.size();
        double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, sad = 0, big = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double a = dome->values[i], b = rvt->values[i];
            sa += a;
            sb += b;
            saa += a * a;
            sbb += b * b;
            sab += a * b;
            sad += std::fabs(a - b);
            big = std::max(big, std::fabs(a - b));
        }
        const double N = double(n);
        mad = sad / N;
        largest = big;
        meanDome = sa / N;
        meanRvt = sb / N;
        correlation = (sab / N - meanDome * meanRvt)
                      / std::sqrt((saa / N - meanDome * meanDome) * (sbb / N - meanRvt * meanRvt));
    }
    state.counters["mean_abs_diff"] = mad;
    state.counters["max_abs_diff"] = largest;
    state.counters["correlation"] = correlation;
    state.counters["mean_skydome"] = meanDome;
    state.counters["mean_rvt"] = meanRvt;
}
BENCHMARK(BM_SkydomeVersusRvt)->Arg(16)->Arg(40)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

} // namespace
