#include "OptimalBuilder.h"

#include "PointPass.h"
#include "StreamingBuilder.h"
#include "WorkerPool.h"

#include <atomic>

namespace stylos::core::octree {

namespace {

/** One marking pass: sets the child bits of the cells at @p level. */
Status markLevel(BuildContext& context, const BuildOptions& options, ConstructionOctree& tree, int level,
                 WorkerPool& pool)
{
    auto reader = context.open();
    if (!reader.ok()) return reader.error();
    const RootBox box = tree.description().box;
    const int depth = options.depth;
    PointPass pass(std::move(*reader), [box, depth](const io::PointBatch& batch, std::vector<PreparedPoint>& out) {
        const std::size_t n = batch.size();
        out.resize(n);
        for (std::size_t i = 0; i < n; ++i) out[i].coords = box.quantise(&batch.positions[3 * i], depth);
    });
    std::vector<ConstructionOctree::Path> paths(pool.threads(), tree.rootPath());
    std::atomic<bool> missing{false};
    for (;;) {
        auto points = pass.next();
        if (!points.ok()) return points.error();
        if (points->empty()) break;
        const std::span<const PreparedPoint> all = *points;
        const std::size_t parts = pool.threads();
        pool.run([&](unsigned t) {
            const std::size_t begin = all.size() * t / parts, end = all.size() * (t + 1) / parts;
            if (!tree.markAll(all.subspan(begin, end - begin), level, paths[t]))
                missing.store(true, std::memory_order_relaxed);
        });
        if (missing.load()) return context.inputChanged("a point fell outside the cells of the earlier passes");
        context.progress(pass.fraction());
        if (context.cancelRequested()) return context.cancelled();
    }
    return context.endPass(pass.pointsRead(), pass.pointsSkipped());
}

/**
 * The leaf pass: every point averaged into its leaf, in input order. The reader thread prepares the
 * points (quantised, unit normal, first-point code); the pool finds their leaves (read-only, in parallel);
 * this thread averages them in order.
 */
Status averageLeaves(BuildContext& context, const BuildOptions& options, ConstructionOctree& tree, WorkerPool& pool)
{
    auto reader = context.open();
    if (!reader.ok()) return reader.error();
    const RootBox box = tree.description().box;
    const int depth = options.depth;
    const NormalEncoder encoder(options.normalCode);
    PointPass pass(std::move(*reader), [&, box, depth](const io::PointBatch& batch, std::vector<PreparedPoint>& out) {
        prepareBatch(box, depth, encoder, batch, out);
    });
    std::vector<ConstructionOctree::Path> paths(pool.threads(), tree.rootPath());
    std::vector<std::uint32_t> leaves;
    for (;;) {
        auto points = pass.next();
        if (!points.ok()) return points.error();
        if (points->empty()) break;
        const std::span<const PreparedPoint> all = *points;
        leaves.resize(all.size());
        const std::size_t parts = pool.threads();
        const ConstructionOctree& finder = tree;
        pool.run([&](unsigned t) {
            const std::size_t begin = all.size() * t / parts, end = all.size() * (t + 1) / parts;
            finder.findLeaves(all.subspan(begin, end - begin), std::span(leaves).subspan(begin, end - begin), paths[t]);
        });
        for (std::size_t i = 0; i < all.size(); ++i) {
            if (leaves[i] == CellArena::Exhausted)
                return context.inputChanged("a point fell outside the cells of the marking passes");
            tree.average(leaves[i], all[i]);
        }
        context.progress(pass.fraction());
        if (context.cancelRequested()) return context.cancelled();
    }
    return context.endPass(pass.pointsRead(), pass.pointsSkipped());
}

} // namespace

Result<std::unique_ptr<ConstructionOctree>> buildOptimal(BuildContext& context, const BuildOptions& options)
{
    const auto box = context.rootBox();
    if (!box.ok()) return box.error();
    auto created = context.newTree(box.value());
    if (!created.ok()) return created.error();
    std::unique_ptr<ConstructionOctree> tree = std::move(created.value());
    WorkerPool pool(options.threads);
    for (int level = 0; level < options.depth; ++level) {
        const Status marked = markLevel(context, options, *tree, level, pool);
        if (!marked.ok()) return marked.error();
        if (!tree->allocateLevel(level))
            return context.outOfBudget(tree->bytesAfterAllocating(level), "at level " + std::to_string(level + 1));
    }
    const Status averaged = averageLeaves(context, options, *tree, pool);
    if (!averaged.ok()) return averaged.error();
    tree->setThreads(options.threads);
    return tree;
}

} // namespace stylos::core::octree
