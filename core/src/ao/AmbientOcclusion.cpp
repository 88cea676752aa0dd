#include "stylos/core/ao/AmbientOcclusion.h"

#include "../shading/ParallelChunks.h"
#include "AoKernel.h"
#include "stylos/core/ao/Directions.h"

#include <algorithm>
#include <atomic>
#include <string>

namespace stylos::core::ao {

const char* aoMethodName(AoMethod method)
{
    return method == AoMethod::Slices ? "slices" : "depthmap";
}

std::optional<AoMethod> aoMethodFromName(const std::string& name)
{
    if (name == "slices") return AoMethod::Slices;
    if (name == "depthmap") return AoMethod::DepthMap;
    return std::nullopt;
}

namespace detail {

PreparedCells prepareCells(const AoCells& cells)
{
    PreparedCells p;
    const std::size_t n = cells.size();
    for (auto* v : {&p.x, &p.y, &p.z, &p.nx, &p.ny, &p.nz}) v->resize(n);
    p.opacity = cells.opacity;
    p.opacity.resize(n, 1.0f);
    for (std::size_t i = 0; i < n; ++i) {
        const auto& c = cells.coords[i];
        p.x[i] = float(c[0]) + 0.5f;
        p.y[i] = float(c[1]) + 0.5f;
        p.z[i] = float(c[2]) + 0.5f;
        p.nx[i] = cells.normals[i][0];
        p.ny[i] = cells.normals[i][1];
        p.nz[i] = cells.normals[i][2];
        for (int a = 0; a < 3; ++a) p.extent[a] = std::max(p.extent[a], c[a] + 1);
    }
    return p;
}

PreparedCells prepareReceivers(const AoReceivers& receivers)
{
    PreparedCells p;
    const std::size_t n = receivers.size();
    for (auto* v : {&p.x, &p.y, &p.z, &p.nx, &p.ny, &p.nz}) v->resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        p.x[i] = receivers.positions[i][0];
        p.y[i] = receivers.positions[i][1];
        p.z[i] = receivers.positions[i][2];
        p.nx[i] = receivers.normals[i][0];
        p.ny[i] = receivers.normals[i][1];
        p.nz[i] = receivers.normals[i][2];
    }
    return p;
}

} // namespace detail

namespace {

Result<std::vector<float>> runSkydome(const AoCells& cells, const AoReceivers* receivers, const AoOptions& options,
                                      ProgressSink* progress)
{
    if (options.directions < 1 || options.directions > 65536)
        return Error::at(ErrorCode::InvalidArgument, "skydome", "",
                         "the number of directions must be 1..65536, not " + std::to_string(options.directions));
    if (!(options.bias >= 0.0) || !(options.receiverBias >= 0.0))
        return Error::at(ErrorCode::InvalidArgument, "skydome", "", "the bias must be ≥ 0");

    if (receivers && options.method != AoMethod::DepthMap)
        return Error::at(ErrorCode::InvalidArgument, "skydome", "",
                         "receivers off the cells (leaves) need the depthmap method");
    const detail::DepthMapPasses* passes = nullptr;
    if (options.method == AoMethod::DepthMap) {
        auto chosen = detail::chosenDepthMapPasses();
        if (!chosen) return chosen.error();
        passes = *chosen;
    }
    const detail::PreparedCells prepared = detail::prepareCells(cells);
    detail::PreparedCells preparedReceivers = receivers ? detail::prepareReceivers(*receivers) : detail::PreparedCells{};
    const std::size_t measured = receivers ? preparedReceivers.size() : prepared.size();
    const std::vector<Direction> directions = fibonacciDirections(options.directions, options.upperHemisphere);
    const unsigned maxThreads = std::max(1u, shading::detail::resolveThreads(options.threads));

    // Two-sided (AoOptions::twoSided): a probe of every stride-th direction (kProbe at most, spread over
    // the sphere) is measured on both sides of every receiver, which then keeps the side that sees more
    // (its normal turned when that is the back) and is measured one-sided on it over the other
    // directions, its probe sums for that side included. The value is the one-sided value on the chosen
    // side over all directions, for a probe's worth of extra work (measured: a full two-sided pass over
    // all directions costs 40-50 % more, the probe about 5 %).
    constexpr std::size_t kProbe = 32;
    const bool twoSided = receivers != nullptr && twoSidedApplies(options);
    std::vector<std::size_t> probe, rest;
    const std::size_t stride = std::max<std::size_t>(1, directions.size() / kProbe);
    for (std::size_t k = 0; k < directions.size(); ++k)
        (twoSided && k % stride == 0 && probe.size() < kProbe ? probe : rest).push_back(k);

    // One kernel (scratch) and one pair of sums per worker. Worker w takes the phase's directions w, w + T,
    // w + 2T... and the workers' sums are added in worker order: the same thread count gives the same
    // bits; another count groups the float sums differently (a difference in the last bits; none with
    // uniform weights and binary visibility, whose sums are small integers).
    std::atomic<std::size_t> done{0};
    const auto runPhase = [&](const std::vector<std::size_t>& ids, const AoOptions& phaseOptions,
                              std::vector<detail::Accumulator>& sums, bool sidesApart) {
        const unsigned threads = std::max(1u, std::min<unsigned>(maxThreads, unsigned(std::max<std::size_t>(1, ids.size()))));
        sums.clear();
        sums.reserve(threads);
        for (unsigned t = 0; t < threads; ++t) sums.emplace_back(measured, sidesApart);
        return shading::detail::parallelChunks(
            threads, 1, threads, progress, [&](std::size_t worker, std::size_t, unsigned) {
                auto kernel = phaseOptions.method == AoMethod::Slices
                                  ? detail::makeSliceKernel(prepared, phaseOptions)
                                  : detail::makeDepthMapKernel(prepared, phaseOptions, *passes,
                                                               receivers ? &preparedReceivers : nullptr);
                for (std::size_t j = worker; j < ids.size(); j += threads) {
                    if (progress && progress->isCancelRequested()) return;
                    const auto& d = directions[ids[j]];
                    kernel->run({float(d[0]), float(d[1]), float(d[2])}, sums[worker]);
                    const std::size_t n = done.fetch_add(1) + 1;
                    if (progress) progress->update(double(n) / double(directions.size()));
                }
            });
    };
    const auto cancelled = [&] {
        return Error::at(ErrorCode::Cancelled, "skydome", "", "skydome cancelled");
    };

    // The probe: each receiver's side, and its sums on that side.
    std::vector<float> startSeen, startTotal; // small integers with uniform weights: exact in float
    if (!probe.empty()) {
        AoOptions probeOptions = options;
        probeOptions.twoSided = true;
        std::vector<detail::Accumulator> probeSums;
        if (!runPhase(probe, probeOptions, probeSums, true) || (progress && progress->isCancelRequested()))
            return cancelled();
        startSeen.assign(measured, 0.0f);
        startTotal.assign(measured, 0.0f);
        for (std::size_t i = 0; i < measured; ++i) {
            double seen = 0.0, total = 0.0, seenBack = 0.0, totalBack = 0.0;
            for (const auto& sum : probeSums) {
                seen += sum.seen[i];
                total += sum.total[i];
                seenBack += sum.seenBack[i];
                totalBack += sum.totalBack[i];
            }
            const double front = total > 0.0 ? seen / total : 0.0;
            const double back = totalBack > 0.0 ? seenBack / totalBack : 0.0;
            if (back > front) { // the back is the outside: turn the normal
                preparedReceivers.nx[i] = -preparedReceivers.nx[i];
                preparedReceivers.ny[i] = -preparedReceivers.ny[i];
                preparedReceivers.nz[i] = -preparedReceivers.nz[i];
                seen = seenBack;
                total = totalBack;
            }
            startSeen[i] = float(seen);
            startTotal[i] = float(total);
        }
    }
    AoOptions restOptions = options;
    restOptions.twoSided = false;
    std::vector<detail::Accumulator> sums;
    if (!runPhase(rest, restOptions, sums, false) || (progress && progress->isCancelRequested())) return cancelled();

    std::vector<float> values(measured, 0.0f);
    for (std::size_t i = 0; i < values.size(); ++i) {
        double seen = startSeen.empty() ? 0.0 : startSeen[i], total = startTotal.empty() ? 0.0 : startTotal[i];
        for (const auto& sum : sums) {
            seen += sum.seen[i];
            total += sum.total[i];
        }
        values[i] = total > 0.0 ? float(std::clamp(seen / total, 0.0, 1.0)) : 0.0f;
    }
    return values;
}

} // namespace

Result<std::vector<float>> computeAmbientOcclusion(const AoCells& cells, const AoOptions& options,
                                                   ProgressSink* progress)
{
    return runSkydome(cells, nullptr, options, progress);
}

Result<std::vector<float>> computeAmbientOcclusion(const AoCells& occluders, const AoReceivers& receivers,
                                                   const AoOptions& options, ProgressSink* progress)
{
    return runSkydome(occluders, &receivers, options, progress);
}

} // namespace stylos::core::ao
