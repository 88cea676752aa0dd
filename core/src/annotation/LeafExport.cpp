// One PLY point per leaf with the annotation and ambient layers as properties.
#include "stylos/core/annotation/LeafExport.h"

#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/octree/LeafPly.h"

#include <cstring>
#include <set>

namespace stylos::core::annotation {

namespace {

/** One layer's values per leaf, as doubles for PointBatch's scalar columns. */
struct Column {
    std::vector<std::uint8_t> labels;
    std::vector<float> floats;
    double at(std::uint64_t leaf) const { return labels.empty() ? double(floats[leaf]) : double(labels[leaf]); }
};

Result<Column> readColumn(const octree::PackedOctree& octree, const std::string& name)
{
    const std::string file = octree.path().string();
    if (const auto layer = layerFromName(name)) {
        auto labels = readLeafLabels(octree, *layer);
        if (!labels) return labels.error();
        return Column{std::move(labels).value(), {}};
    }
    const auto view = octree.attribute(name);
    if (!view) return Error::at(ErrorCode::InvalidArgument, file, {}, "has no \"" + name + "\" layer (stylos-cli ao adds it)");
    const std::uint64_t leaves = leafCount(octree);
    if (view->type != octree::AttributeType::Float32 || view->components != 1 || view->bytes.size() != leaves * 4)
        return Error::at(ErrorCode::Malformed, file, "layer \"" + name + "\"", "not one float per leaf");
    Column column;
    column.floats.resize(leaves);
    if (leaves) std::memcpy(column.floats.data(), view->bytes.data(), view->bytes.size());
    return column;
}

} // namespace

bool isExportableLayer(const std::string& name) { return name == "material" || name == "toolmark" || name == "ambient"; }

Result<std::uint64_t> exportLeafPly(const octree::PackedOctree& octree, const std::vector<std::string>& layers,
                                    const std::filesystem::path& output, ProgressSink* progress)
{
    std::vector<Column> columns;
    std::vector<std::string> names;
    std::set<std::string> seen;
    for (const std::string& name : layers) {
        if (!isExportableLayer(name))
            return Error::at(ErrorCode::InvalidArgument, output.string(), {}, "unknown layer \"" + name + "\" (material, toolmark, ambient)");
        if (!seen.insert(name).second)
            return Error::at(ErrorCode::InvalidArgument, output.string(), {}, "layer \"" + name + "\" given twice");
        auto column = readColumn(octree, name);
        if (!column) return column.error();
        columns.push_back(std::move(column).value());
        names.push_back(name);
    }
    std::vector<octree::LeafPlyColumn> plyColumns;
    for (std::size_t k = 0; k < columns.size(); ++k)
        plyColumns.push_back({names[k], names[k] == "ambient" ? io::PlyScalarType::Float32 : io::PlyScalarType::UInt8,
                              [&column = columns[k]](std::uint64_t leaf) { return column.at(leaf); }});
    return octree::writeLeafPly(octree, plyColumns,
                                "stylos leaves: one vertex per leaf centre of an octree of depth " +
                                    std::to_string(octree.depth()),
                                output, progress);
}

} // namespace stylos::core::annotation
