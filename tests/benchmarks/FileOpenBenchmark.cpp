// What opening a .poct costs before any cell is read: the XXH64 digest that verifies each section, and
// PackedOctree::open on a 5.6 M-cell (12 MB) file already in the page cache (open, map, verify, index).
// These were speed assertions in unit tests (Hash64Test, PackedOctreeTest) until they moved here: a test
// must not fail because a machine is busy.
#include "QuadTreeLevels.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/octree/PoctWriter.h"
#include "stylos/core/util/Hash64.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using namespace stylos::core;

/** XXH64 of 64 MiB already in memory: bytes per second is the figure. */
void BM_Xxh64(benchmark::State& state)
{
    std::vector<std::uint8_t> data(std::size_t(64) << 20);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 2654435761u >> 13);
    benchmark::DoNotOptimize(xxh64(data.data(), data.size())); // the pages touched once
    for (auto _ : state) benchmark::DoNotOptimize(xxh64(data.data(), data.size()));
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(data.size()));
}
BENCHMARK(BM_Xxh64)->Unit(benchmark::kMillisecond);

/** PackedOctree::open of a 4^11-leaf file written once to the temporary folder (then in the page cache). */
void BM_PackedOctreeOpen(benchmark::State& state)
{
    const auto path = std::filesystem::temp_directory_path() /
                      ("stylos-open-benchmark-" + std::to_string(::getpid()) + ".poct");
    const auto size = octree::writePoct(stylos::test::QuadTreeLevels(11), path);
    if (!size) {
        state.SkipWithError(size.error().message.c_str());
        return;
    }
    for (auto _ : state) {
        auto opened = octree::PackedOctree::open(path);
        if (!opened) {
            state.SkipWithError(opened.error().message.c_str());
            break;
        }
        benchmark::DoNotOptimize(opened->totalCells());
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(size.value()));
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
}
BENCHMARK(BM_PackedOctreeOpen)->Unit(benchmark::kMillisecond);

} // namespace
