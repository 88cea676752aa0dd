// Building a `.poct` file: the construction (OctreeBuilder.cpp), then the writer; for point files
// without normals, their estimation first, into a temporary folder next to the output.
#include "stylos/core/octree/OctreeBuild.h"

#include "BuildContext.h"
#include "UnpulledBuild.h"

#include "stylos/core/normals/NormalFileEstimation.h"
#include "stylos/core/octree/ConstructionOctree.h"
#include "stylos/core/octree/LeafSpacing.h"
#include "stylos/core/octree/PoctWriter.h"
#include "stylos/core/util/ScratchFolder.h"
#include "stylos/core/util/SubProgress.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <future>
#include <random>
#include <system_error>

namespace stylos::core::octree {

namespace {

namespace fs = std::filesystem;

/**
 * The levels of a construction octree not pulled yet: the first visitLevels() pulls it and hands the cells
 * on as they are pulled (ConstructionOctree::pullAndVisitLevels); anything else pulls it first.
 */
class PullingLevels final : public OctreeLevels {
public:
    PullingLevels(ConstructionOctree& tree, unsigned threads) : m_tree(tree), m_threads(threads) {}
    const OctreeDescription& description() const override { return m_tree.description(); }
    void visitLevel(int level, const std::function<void(const CellBlock&)>& sink) const override
    {
        pullOnce(nullptr);
        m_tree.visitLevel(level, sink);
    }
    void visitLevels(const std::function<void(int level, const CellBlock&)>& sink) const override
    {
        if (!pullOnce(&sink)) m_tree.visitLevels(sink);
    }
    std::vector<std::vector<std::uint64_t>> descendantCounts(int ancestorLevel,
                                                             std::span<const int> levels) const override
    {
        return m_tree.descendantCounts(ancestorLevel, levels);
    }

private:
    /** Pulls the tree unless done before (handing its cells to @p sink); true if it pulled now. */
    bool pullOnce(const std::function<void(int level, const CellBlock&)>* sink) const
    {
        if (m_pulled) return false;
        m_pulled = true;
        m_tree.pullAndVisitLevels(m_threads, sink);
        return true;
    }
    ConstructionOctree& m_tree;
    unsigned m_threads;
    mutable bool m_pulled = false;
};

} // namespace

Result<BuildReport> buildOctree(const PointSourceFactory& open, const fs::path& output, const BuildOptions& options,
                                ProgressSink* progress)
{
    const auto start = std::chrono::steady_clock::now();
    SubProgress building(progress, 0.0, 0.95);
    BuildReport report;
    auto tree = buildUnpulledConstructionOctree(open, options, &building, &report);
    if (!tree.ok()) return tree.error();
    if (progress && progress->isCancelRequested())
        return Error::at(ErrorCode::Cancelled, output.string(), "", "octree build cancelled");
    SubProgress writing(progress, 0.95, 1.0);
    // The spacing layer (4 bytes a leaf) is held beside the construction structure while the file is written:
    // it counts against the same limit.
    const std::uint64_t leaves = report.cellsPerLevel.empty() ? 0 : report.cellsPerLevel.back();
    if (options.memoryLimit > 0 && report.constructionBytes + 4 * leaves > options.memoryLimit)
        return Error::at(ErrorCode::OutOfBudget, output.string(), "",
                         "the octree needs " + formatBytes(report.constructionBytes + 4 * leaves) +
                             " with its leaves' spacing layer (" + std::to_string(leaves) +
                             " leaves × 4 bytes) but the memory limit (--memory-limit) is " +
                             formatBytes(options.memoryLimit, false));
    // The tree is pulled as it is written (no walk of its own for the writer); meanwhile another thread counts
    // what the spacing layer needs of its shape, which the pull does not change; the layer is finished once
    // the normals are pulled, after the cells.
    ConstructionOctree& built = **tree;
    std::future<LeafSpacingShape> shape = std::async(std::launch::async, [&built] { return leafSpacingShape(built); });
    const PullingLevels pulling(built, options.threads);
    const PendingLayer spacing{LeafSpacingLayerName, AttributeType::Float32, 1,
                               [&] { return leafSpacingLayer(built, shape.get()); }};
    auto written = writePoct(pulling, output, {}, std::span<const PendingLayer>(&spacing, 1), &writing);
    if (shape.valid()) shape.wait();  // it reads the tree: it ends before the tree goes
    if (!written.ok()) return written.error();
    report.fileBytes = *written;
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (progress) progress->update(1.0);
    return report;
}

Result<BuildReport> buildOctreeFile(const fs::path& input, const fs::path& output, const BuildOptions& options,
                                    ProgressSink* progress, const io::ReadOptions& read)
{
    const auto start = std::chrono::steady_clock::now();
    bool hasNormals = false;
    {
        auto probe = io::openPointReader(input, read);
        if (!probe.ok()) return probe.error();
        hasNormals = (*probe)->header().schema.hasNormals;
    }
    if (hasNormals) {
        return buildOctree([input, read] { return io::openPointReader(input, read); }, output, options, progress);
    }
    const Status valid = checkBuildOptions(options);  // before the (long) estimation
    if (!valid.ok()) return valid.error();

    ScratchFolder folder; // the estimated normals, removed with it
    if (const Status created = folder.create(output, "build"); !created) return created.error();
    const fs::path withNormals = folder.path() / "normals.ply";
    normals::NormalFileOptions estimate;
    estimate.normals.threads = options.threads;
    estimate.temporaryDirectory = folder.path();
    estimate.read = read;
    if (options.memoryLimit > 0)
        estimate.memoryBudget = std::max<std::size_t>(64u << 10, std::min<std::uint64_t>(estimate.memoryBudget,
                                                                                          options.memoryLimit));
    SubProgress estimating(progress, 0.0, 0.4);
    auto estimated = normals::estimateNormalsForFile(input, withNormals, estimate, &estimating);
    if (!estimated.ok()) return estimated.error();

    SubProgress building(progress, 0.4, 1.0);
    auto report = buildOctree([withNormals] { return io::openPointReader(withNormals); }, output, options, &building);
    if (!report.ok()) {
        // The build read the temporary file of estimated normals: its errors name the input the user gave.
        Error error = report.error();
        const std::string temporary = withNormals.string();
        if (error.message.rfind(temporary, 0) == 0) error.message = input.string() + error.message.substr(temporary.size());
        return error;
    }
    report->normalsEstimated = true;
    report->normalScans = estimated->scans;
    report->normalScanColumn = estimated->scanColumn;
    report->skippedPoints = estimated->skippedPoints;
    report->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

} // namespace stylos::core::octree
