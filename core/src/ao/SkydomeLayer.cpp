#include "stylos/core/ao/SkydomeLayer.h"

#include "stylos/core/util/Stopwatch.h"

#include "stylos/core/ao/AoCells.h"
#include "stylos/core/ao/AoExport.h"
#include "stylos/core/ao/SkydomeSmoothing.h"
#include "stylos/core/util/SubProgress.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

namespace stylos::core::ao {

namespace {

/**
 * The default smoothing radius, metres: @p edges of the level's cells, at most MaxDefaultSmoothingSpacings
 * median leaf spacings (a sample of 1001 leaves; a file without the stored spacing layer has it computed once).
 */
double defaultSmoothingRadius(const octree::PackedOctree& octree, const AoCells& cells, double edges)
{
    const double radius = edges * cells.edge;
    const std::uint64_t leaves = octree.cellCount(octree.depth());
    if (leaves == 0) return radius;
    std::vector<float> spacings;
    const std::uint64_t samples = std::min<std::uint64_t>(leaves, 1001);
    for (std::uint64_t k = 0; k < samples; ++k) spacings.push_back(octree.leafSpacing(k * leaves / samples));
    std::nth_element(spacings.begin(), spacings.begin() + std::ptrdiff_t(samples / 2), spacings.end());
    const double median = spacings[samples / 2];
    return median > 0.0 ? std::min(radius, MaxDefaultSmoothingSpacings * median) : radius;
}

} // namespace

Result<std::vector<float>> computeLeafSkydome(const octree::PackedOctree& octree, const SkydomeLayerOptions& options,
                                              ProgressSink* progress, SkydomeLayerReport* out)
{
    SkydomeLayerReport report;
    report.level = options.level.value_or(closedSurfaceLevel(octree));
    if (report.level < 0 || report.level > octree.depth())
        return Error::at(ErrorCode::InvalidArgument, octree.path().string(), {},
                         "the level " + std::to_string(report.level) + " is outside the levels 0.."
                             + std::to_string(octree.depth()) + " of the octree");

    auto start = Clock::now();
    AoCells cells;
    {
        SubProgress step(progress, 0.0, 0.1);
        auto read = cellsAtLevel(octree, report.level, &step);
        if (!read) return read.error();
        cells = std::move(read).value();
    }
    report.cells = cells.size();
    report.readSeconds = secondsSince(start);

    start = Clock::now();
    std::vector<float> perLeaf;
    {
        if (options.leafReceivers && options.ao.method == AoMethod::DepthMap) {
            AoReceivers receivers;
            {
                SubProgress step(progress, 0.1, 0.15);
                auto read = leafReceivers(octree, cells, &step);
                if (!read) return read.error();
                receivers = std::move(read).value();
            }
            {
                SubProgress step(progress, 0.15, 0.95);
                auto values = computeAmbientOcclusion(cells, receivers, options.ao, &step);
                if (!values) return values.error();
                perLeaf = std::move(values).value();
            }
            const double radius = options.smoothingRadius ? *options.smoothingRadius
                                                          : defaultSmoothingRadius(octree, cells, options.smoothing);
            if (!(radius >= 0.0) || radius > MaxSmoothingEdges * cells.edge)
                return Error::at(ErrorCode::InvalidArgument, octree.path().string(), {},
                                 "the smoothing radius " + std::to_string(radius) + " m is more than " +
                                     std::to_string(int(MaxSmoothingEdges)) + " edges of the level's cells (" +
                                     std::to_string(cells.edge) + " m): it would average whole parts of the object");
            if (radius > 0.0 && !perLeaf.empty()) {
                const auto smoothStart = Clock::now();
                report.smoothingRadius = radius;
                SkydomeSmoothing smoothing;
                smoothing.radius = radius / cells.edge; // the receivers' unit: the cells' edge
                smoothing.threads = options.ao.threads;
                SubProgress step(progress, 0.95, 1.0);
                if (auto smoothed = smoothSkydome(receivers, perLeaf, smoothing, &step); !smoothed) return smoothed.error();
                report.smoothSeconds = secondsSince(smoothStart);
            }
        } else {
            SubProgress step(progress, 0.1, 1.0);
            auto values = computeAmbientOcclusion(cells, options.ao, &step);
            if (!values) return values.error();
            perLeaf = valuesPerLeaf(cells, *values);
        }
    }
    report.leaves = perLeaf.size();
    report.meanAmbient =
        perLeaf.empty() ? 0.0 : std::accumulate(perLeaf.begin(), perLeaf.end(), 0.0) / double(perLeaf.size());
    report.aoSeconds = secondsSince(start);
    if (out) *out = report;
    return perLeaf;
}

Result<SkydomeLayerReport> computeSkydomeLayer(const octree::PackedOctree& octree, const std::filesystem::path& output,
                                               const SkydomeLayerOptions& options, ProgressSink* progress)
{
    SkydomeLayerReport report;
    std::vector<float> perLeaf;
    {
        SubProgress step(progress, 0.0, 0.9);
        auto values = computeLeafSkydome(octree, options, &step, &report);
        if (!values) return values.error();
        perLeaf = std::move(values).value();
    }

    // The last moment a cancel leaves the output as it was.
    if (progress) progress->update(0.9);
    if (progress && progress->isCancelRequested())
        return Error::at(ErrorCode::Cancelled, output.string(), {}, "cancelled");
    const auto start = Clock::now();
    {
        SubProgress step(progress, 0.9, 1.0);
        auto written = options.output == SkydomeOutput::Ply ? writeAmbientPly(octree, perLeaf, output, &step)
                                                            : writeAmbientPoct(octree, perLeaf, output, &step);
        if (!written) return written.error();
    }
    report.writeSeconds = secondsSince(start);
    if (progress) progress->update(1.0);
    return report;
}

} // namespace stylos::core::ao
