// The core part of painting a développée of 16384 × 4096 pixels holding 16 M leaves (one leaf per 4 pixels, as
// a 30 M-point drum at 0.25 mm): one brush dab of radius R pixels — the capsule's pixels, their leaves, the new
// labels, the touched pixels back from the leaves and their shown label (what the overlay redraws). The undo
// step and the repaint (Qt) are not in it. Also the magic wand over half of it (33.5 M pixels) and over 100 M pixels.
// Run: ./build/bin/stylos_benchmarks --benchmark_filter='BM_Paint'
#include "stylos/core/annotation/PaintRegion.h"
#include "stylos/core/annotation/PixelLeafIndex.h"

#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace stylos::core::annotation;

constexpr int W = 16384;
constexpr int H = 4096;

const PixelLeafIndex& bigIndex()
{
    static const std::unique_ptr<PixelLeafIndex> index = [] {
        std::vector<std::int64_t> pixels(std::size_t(W) * H / 4);
        for (std::size_t l = 0; l < pixels.size(); ++l) pixels[l] = std::int64_t(4 * l);
        return std::make_unique<PixelLeafIndex>(PixelLeafIndex::build(pixels, W, H));
    }();
    return *index;
}

void BM_PaintDab(benchmark::State& state)
{
    const PixelLeafIndex& index = bigIndex();
    std::vector<std::uint8_t> labels(index.leafCount(), 0);
    const double radius = double(state.range(0));
    double x = 1000.0;
    std::size_t touched = 0;
    for (auto _ : state) {
        const auto pixels = brushPixels({x, 2000.0}, {x + radius / 4.0, 2000.0}, radius, W, H);
        const auto leaves = index.leavesOf(pixels);
        for (std::uint32_t leaf : leaves) labels[leaf] = std::uint8_t(1 + (labels[leaf] & 1));
        const auto shown = index.pixelsOf(leaves);
        std::vector<std::uint8_t> ids(shown.size());
        for (std::size_t i = 0; i < shown.size(); ++i) ids[i] = index.majorityLabel(shown[i], labels);
        benchmark::DoNotOptimize(ids.data());
        touched = pixels.size();
        x += radius / 4.0;
        if (x > W - 2 * radius) x = 1000.0;
    }
    state.counters["pixels"] = double(touched);
}
BENCHMARK(BM_PaintDab)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_PaintWand(benchmark::State& state)
{
    // Rows of W pixels; a wall of other values down column `wall`: the wand from pixel 0 takes its left side.
    const int rows = int(state.range(0));
    const int wall = int(state.range(1));
    std::vector<float> values(std::size_t(W) * std::size_t(rows), 0.0f);
    std::vector<std::uint8_t> valid(values.size(), 1);
    for (int r = 0; r < rows; ++r) values[std::size_t(r) * W + std::size_t(wall)] = 1.0f;
    std::size_t taken = 0;
    for (auto _ : state) {
        taken = floodFill(values, valid, W, rows, 0, 0.5f).size();
        benchmark::DoNotOptimize(taken);
    }
    state.counters["pixels"] = double(taken);
    state.counters["ns_per_pixel"] = benchmark::Counter(double(taken) * double(state.iterations()),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
// Half of the 16 k × 4 k développée (33.5 M pixels), then 100 M pixels (16 k × 6144, all but the last column).
BENCHMARK(BM_PaintWand)->Args({H, W / 2})->Args({6144, W - 1})->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace
