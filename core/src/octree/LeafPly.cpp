#include "stylos/core/octree/LeafPly.h"

namespace stylos::core::octree {

Result<std::uint64_t> writeLeafPly(const PackedOctree& octree, const std::vector<LeafPlyColumn>& columns,
                                   const std::string& comment, const std::filesystem::path& output,
                                   ProgressSink* progress)
{
    io::PointSchema schema;
    io::PlyWriterOptions options;
    options.positionType = io::PlyScalarType::Float64;
    for (const LeafPlyColumn& column : columns) {
        schema.scalarNames.push_back(column.name);
        options.scalarTypes.push_back(column.type);
    }
    options.comments = {comment};
    auto writer = io::PlyWriter::create(output, schema, options);
    if (!writer) return writer.error();

    constexpr std::size_t kBatch = 64 * 1024;
    const std::uint64_t leaves = octree.cellCount(octree.depth());
    io::PointBatch batch;
    batch.reset(schema, kBatch);
    Status status;
    auto flush = [&] {
        status = writer->write(batch);
        batch.reset(schema, kBatch);
        if (status && progress) {
            progress->update(leaves ? double(writer->pointsWritten()) / double(leaves) : 1.0);
            if (progress->isCancelRequested())
                status = Error::at(ErrorCode::Cancelled, output.string(), "", "cancelled while writing");
        }
        return bool(status);
    };
    octree.forEachCell(octree.depth(), [&](const CellView& cell) {
        batch.positions.insert(batch.positions.end(), cell.centre.begin(), cell.centre.end());
        for (std::size_t k = 0; k < columns.size(); ++k) batch.scalars[k].push_back(columns[k].value(cell.index));
        return batch.size() < kBatch || flush();
    });
    if (status && !batch.empty()) flush();
    if (!status) return status.error(); // the writer's destructor removes its temporary file
    if (auto s = writer->finish(); !s) return s.error();
    return writer->pointsWritten();
}

} // namespace stylos::core::octree
