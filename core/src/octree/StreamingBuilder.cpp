#include "StreamingBuilder.h"

#include "PointPass.h"

namespace stylos::core::octree {

void prepareBatch(const RootBox& box, int depth, const NormalEncoder& encode, const io::PointBatch& batch,
                  std::vector<PreparedPoint>& out)
{
    const std::size_t n = batch.size();
    out.resize(n);
    const bool colour = !batch.colors.empty();
    thread_local std::vector<std::array<float, 3>> normals;
    thread_local std::vector<std::uint16_t> codes;
    normals.resize(n);
    codes.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        PreparedPoint& p = out[i];
        p.coords = box.quantise(&batch.positions[3 * i], depth);
        p.normal = unitNormal(batch.normals[3 * i], batch.normals[3 * i + 1], batch.normals[3 * i + 2]);
        if (colour) p.colour = {batch.colors[3 * i], batch.colors[3 * i + 1], batch.colors[3 * i + 2]};
        normals[i] = p.normal;
    }
    encode.encode(normals, codes);
    for (std::size_t i = 0; i < n; ++i) out[i].firstCode = codes[i];
}

Result<std::unique_ptr<ConstructionOctree>> buildStreaming(BuildContext& context, const BuildOptions& options)
{
    const auto box = context.rootBox();
    if (!box.ok()) return box.error();
    auto created = context.newTree(box.value());
    if (!created.ok()) return created.error();
    std::unique_ptr<ConstructionOctree> tree = std::move(created.value());
    auto reader = context.open();
    if (!reader.ok()) return reader.error();

    const RootBox b = box.value();
    const int depth = options.depth;
    const NormalCodeKind kind = options.normalCode;
    const NormalEncoder encoder(kind);
    PointPass pass(std::move(*reader), [b, depth, &encoder](const io::PointBatch& batch, std::vector<PreparedPoint>& out) {
        prepareBatch(b, depth, encoder, batch, out);
    });
    ConstructionOctree::Path path = tree->rootPath();
    std::uint64_t inserted = 0;
    for (;;) {
        auto points = pass.next();
        if (!points.ok()) return points.error();
        if (points->empty()) break;
        for (const PreparedPoint& p : *points) {
            if (!tree->populate(p, path)) {
                const std::string when =
                    "after " + std::to_string(inserted) +
                    (context.expectedPoints() ? " of " + std::to_string(*context.expectedPoints()) : std::string()) +
                    " points, and more for the rest,";
                return context.outOfBudget(tree->arena().bytesWithChunks(tree->arena().chunks() + 1), when);
            }
            ++inserted;
        }
        context.progress(pass.fraction());
        if (context.cancelRequested()) return context.cancelled();
    }
    const Status counted = context.endPass(pass.pointsRead(), pass.pointsSkipped());
    if (!counted.ok()) return counted.error();
    tree->setThreads(options.threads);
    return tree;
}

} // namespace stylos::core::octree
