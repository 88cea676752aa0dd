// The construction half of building an octree: checks, then the chosen builder (no file is written here).
#include "BuildContext.h"
#include "OptimalBuilder.h"
#include "StreamingBuilder.h"
#include "UnpulledBuild.h"

#include "stylos/core/octree/ConstructionOctree.h"

#include <chrono>
#include <cmath>

namespace stylos::core::octree {

Status checkBuildOptions(const BuildOptions& options)
{
    if (options.depth < MinOctreeDepth || options.depth > MaxOctreeDepth)
        return Error::at(ErrorCode::InvalidArgument, "octree", "",
                         "depth " + std::to_string(options.depth) + " is outside the supported range " +
                             std::to_string(MinOctreeDepth) + ".." + std::to_string(MaxOctreeDepth));
    if (options.threads == 0)
        return Error::at(ErrorCode::InvalidArgument, "octree", "", "threads must be at least 1");
    if (options.box && !(options.box->size > 0 && std::isfinite(options.box->size)))
        return Error::at(ErrorCode::InvalidArgument, "octree", "", "the root box must have a positive size");
    return {};
}

const char* buildMethodName(BuildMethod method)
{
    return method == BuildMethod::Streaming ? "streaming" : "optimal";
}

Result<std::unique_ptr<ConstructionOctree>> buildConstructionOctree(const PointSourceFactory& open,
                                                                    const BuildOptions& options,
                                                                    ProgressSink* progress, BuildReport* report)
{
    auto tree = buildUnpulledConstructionOctree(open, options, progress, report);
    if (!tree.ok()) return tree.error();
    const auto start = std::chrono::steady_clock::now();
    (*tree)->pull(options.threads);
    if (report) report->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return tree;
}

Result<std::unique_ptr<ConstructionOctree>> buildUnpulledConstructionOctree(const PointSourceFactory& open,
                                                                            const BuildOptions& options,
                                                                            ProgressSink* progress, BuildReport* report)
{
    const auto start = std::chrono::steady_clock::now();
    const Status valid = checkBuildOptions(options);
    if (!valid.ok()) return valid.error();
    if (!open) return Error::at(ErrorCode::InvalidArgument, "octree", "", "no point source");

    const bool optimal = options.method == BuildMethod::Optimal;
    BuildContext context(open, options, progress, optimal ? options.depth + 1 : 1);
    auto tree = optimal ? buildOptimal(context, options) : buildStreaming(context, options);
    if (!tree.ok()) return tree.error();
    context.progressAfterPasses();
    if (report) {
        const OctreeDescription& d = (*tree)->description();
        report->points = d.points;
        report->skippedPoints = context.skippedPoints();
        report->cellsPerLevel = d.cellsPerLevel;
        report->cells = 0;
        for (std::uint64_t c : d.cellsPerLevel) report->cells += c;
        report->leaves = d.cellsPerLevel.back();
        report->depth = d.depth;
        report->method = options.method;
        report->constructionBytes = (*tree)->bytes();
        report->fileBytes = 0;
        report->passes = std::uint64_t(context.passes());
        report->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return tree;
}

} // namespace stylos::core::octree
