// Normal code speed: encode and decode (computed and by table) of both kinds, on 4096 random unit
// vectors / their codes. Rates are items (normals) per second.
// stylos_benchmarks --benchmark_filter=NormalCode
#include "stylos/core/octree/NormalCode.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace stylos::core::octree;

namespace {

constexpr std::size_t batch = 4096;

const std::vector<std::array<float, 3>>& randomNormals()
{
    static const std::vector<std::array<float, 3>> normals = [] {
        std::vector<std::array<float, 3>> result(batch);
        std::mt19937_64 random(1);
        std::normal_distribution<float> gauss;
        for (auto& n : result) {
            n = {gauss(random), gauss(random), gauss(random)};
            const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (float& c : n) c /= length;
        }
        return result;
    }();
    return normals;
}

std::vector<std::uint16_t> codesOf(NormalCodeKind kind)
{
    std::vector<std::uint16_t> codes;
    for (const auto& n : randomNormals()) codes.push_back(encodeNormal(kind, n[0], n[1], n[2]));
    return codes;
}

template <NormalCodeKind Kind>
void BM_NormalCodeEncode(benchmark::State& state)
{
    const auto& normals = randomNormals();
    for (auto _ : state)
        for (const auto& n : normals) benchmark::DoNotOptimize(encodeNormal(Kind, n[0], n[1], n[2]));
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(batch));
}

void BM_NormalCodeEncodeOctahedral16Rounded(benchmark::State& state)
{
    const auto& normals = randomNormals();
    for (auto _ : state)
        for (const auto& n : normals) benchmark::DoNotOptimize(encodeOctahedral16Rounded(n[0], n[1], n[2]));
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(batch));
}

template <NormalCodeKind Kind>
void BM_NormalCodeDecode(benchmark::State& state)
{
    const auto codes = codesOf(Kind);
    for (auto _ : state)
        for (std::uint16_t code : codes) benchmark::DoNotOptimize(decodeNormal(Kind, code));
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(batch));
}

template <NormalCodeKind Kind>
void BM_NormalCodeDecodeTable(benchmark::State& state)
{
    const auto codes = codesOf(Kind);
    const auto* table = normalDecodeTable(Kind);
    const unsigned mask = Kind == NormalCodeKind::Paper15 ? 0x7FFFu : 0xFFFFu;
    for (auto _ : state) {
        float sum = 0;
        for (std::uint16_t code : codes) sum += table[code & mask][2];
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(batch));
}

} // namespace

BENCHMARK(BM_NormalCodeEncode<NormalCodeKind::Paper15>);
BENCHMARK(BM_NormalCodeEncode<NormalCodeKind::Octahedral16>);
BENCHMARK(BM_NormalCodeEncodeOctahedral16Rounded);
BENCHMARK(BM_NormalCodeDecode<NormalCodeKind::Paper15>);
BENCHMARK(BM_NormalCodeDecode<NormalCodeKind::Octahedral16>);
BENCHMARK(BM_NormalCodeDecodeTable<NormalCodeKind::Paper15>);
BENCHMARK(BM_NormalCodeDecodeTable<NormalCodeKind::Octahedral16>);
